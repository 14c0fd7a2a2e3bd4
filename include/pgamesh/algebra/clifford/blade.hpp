// Basis blades as bitmasks: bit i set <=> generator i is a factor, factors in ascending order.
// These are the only places where the sign of a product of basis blades is computed; the general
// engine (clifford::Algebra) and the compile-time PGA R(d,0,1) (pgad) both call them.
#pragma once

#include <cstdint>
#include <type_traits>

namespace pgamesh::clifford {

using BladeMask = std::uint32_t;

// Grade of a basis blade = number of its factors. Counted with shifts and masks: without
// -mpopcnt, std::popcount is a library call, too slow for the inner loops of the products. The
// compile-time product tables (graded, pgad) call it and odd_parity some 10^5 times per table, and
// the compiler's constant evaluator pays for every operation: there the builtin, one step, is used.
constexpr int grade_of(BladeMask m) {
  if (std::is_constant_evaluated()) return __builtin_popcount(m);
  m = m - ((m >> 1) & 0x55555555u);
  m = (m & 0x33333333u) + ((m >> 2) & 0x33333333u);
  m = (m + (m >> 4)) & 0x0f0f0f0fu;
  return static_cast<int>((m * 0x01010101u) >> 24);
}

// Bit j of the result is the parity of the factors of `a` above generator j (a suffix XOR), so
// the parity of the swaps in reorder_sign is one masked parity whatever the grades.
constexpr BladeMask parity_above(BladeMask a) {
  BladeMask p = a >> 1;
  p ^= p >> 1;
  p ^= p >> 2;
  p ^= p >> 4;
  p ^= p >> 8;
  p ^= p >> 16;
  return p;
}

// Parity of the number of set bits, by folding (see grade_of on std::popcount).
constexpr bool odd_parity(BladeMask x) {
  if (std::is_constant_evaluated()) return __builtin_parity(x) != 0;
  x ^= x >> 16;
  x ^= x >> 8;
  x ^= x >> 4;
  x ^= x >> 2;
  x ^= x >> 1;
  return (x & 1u) != 0;
}

// Sign of e_a e_b = ±e_a e_b reordered into ascending factors (before metric contraction):
// (−1)^(number of pairs i in a, j in b with i > j), the transpositions that sort the factors.
constexpr double reorder_sign(BladeMask a, BladeMask b) {
  return odd_parity(parity_above(a) & b) ? -1.0 : 1.0;
}

// Sign of the reverse of a grade-k blade: (−1)^(k(k−1)/2).
constexpr double reverse_sign(int k) {
  return ((k * (k - 1) / 2) & 1) ? -1.0 : 1.0;
}

// Sign of the grade involution of a grade-k blade: (−1)^k.
constexpr double involution_sign(int k) {
  return (k & 1) ? -1.0 : 1.0;
}

// Sign of the Clifford conjugate (reverse of the involution) of a grade-k blade: (−1)^(k(k+1)/2).
constexpr double conjugate_sign(int k) {
  return ((k * (k + 1) / 2) & 1) ? -1.0 : 1.0;
}

// Hodge (complement) dual of a basis blade in an n-generator algebra, docs/conventions.md §3:
// e_J e_J* = I with I = e_0 e_1 … e_(n−1) (all factors ascending), computed without the metric:
// e_J* = s e_(~J) with s chosen so that e_J ∧ (s e_(~J)) = I, i.e. s = reorder_sign(J, ~J).
constexpr double dual_sign(BladeMask j, int n) {
  const BladeMask all = (n >= 32) ? ~BladeMask{0} : ((BladeMask{1} << n) - 1);
  return reorder_sign(j, all & ~j);
}

// Undual: A^(−*) with A^(−*) ∧ A = I (docs/conventions.md §3), so e_J^(−*) = s e_(~J),
// s = reorder_sign(~J, J).
constexpr double undual_sign(BladeMask j, int n) {
  const BladeMask all = (n >= 32) ? ~BladeMask{0} : ((BladeMask{1} << n) - 1);
  return reorder_sign(all & ~j, j);
}

}  // namespace pgamesh::clifford
