// Compile-time diagonal signatures R(p,q,r) for graded multivectors, and the blade lists of each
// grade set. Generators are ordered and named exactly as clifford::Algebra::signature(p, q, r)
// orders them (null first, then positive, then negative), with the same blade masks (bit i =
// generator i) and the same reorder signs (clifford/blade.hpp), so a graded multivector and the
// general engine's agree blade by blade.
#pragma once

#include <array>
#include <cstddef>

#include "pgamesh/algebra/clifford/blade.hpp"

namespace pgamesh::graded {

using clifford::BladeMask;

// A set of grades: bit k set <=> grade k is present.
using GradeMask = unsigned;

// The term list of a product is built at compile time and has O(|A|·|B|) entries (65536 for two
// full multivectors of 8 generators), so the algebra is limited to 8 generators; larger
// algebras belong to the general engine (clifford::Algebra, up to 24 generators).
inline constexpr int max_generators = 8;

// The diagonal signature R(P,Q,R): R generators squaring to 0, then P to +1, then Q to −1.
template <int P, int Q, int R = 0>
struct Algebra {
  static_assert(P >= 0 && Q >= 0 && R >= 0, "graded::Algebra: signature counts must be >= 0");
  static_assert(P + Q + R >= 1, "graded::Algebra: needs at least one generator");
  static_assert(P + Q + R <= max_generators,
                "graded::Algebra is limited to 8 generators (compile-time term lists are "
                "O(|A|*|B|)); use clifford::Algebra for larger algebras");

  static constexpr int p = P, q = Q, r = R, n = P + Q + R;
  static constexpr BladeMask full_mask = (BladeMask{1} << n) - 1;
  static constexpr GradeMask all_grades = (GradeMask{1} << (n + 1)) - 1;
  static constexpr GradeMask even_grades = all_grades & 0x55555555u;
  static constexpr GradeMask odd_grades = all_grades & 0xaaaaaaaau;

  // Generators squaring to 0 and to −1 (the order of clifford::Algebra::signature).
  static constexpr BladeMask null_mask = (BladeMask{1} << R) - 1;
  static constexpr BladeMask negative_mask = full_mask & ~((BladeMask{1} << (R + P)) - 1);

  // Square of generator i.
  static constexpr double square(int i) { return i < R ? 0.0 : (i < R + P ? 1.0 : -1.0); }

  // Coefficient of e_(a^b) in e_a e_b: the reorder sign times the product of the squares of the
  // common factors (what clifford::Algebra::product_factor gives for this signature), which is 0
  // with a common null factor and otherwise (−1)^(common negative factors).
  static constexpr double product_factor(BladeMask a, BladeMask b) {
    if ((a & b & null_mask) != 0) return 0.0;
    const double weight = clifford::odd_parity(a & b & negative_mask) ? -1.0 : 1.0;
    return weight * clifford::reorder_sign(a, b);
  }
};

// Number of basis blades of N generators whose grade is in G.
template <int N>
constexpr std::size_t blade_count(GradeMask g) {
  std::size_t count = 0;
  for (BladeMask m = 0; m < (BladeMask{1} << N); ++m)
    if (g >> clifford::grade_of(m) & 1u) ++count;
  return count;
}

// The blades of the grades in G, ascending by mask: the storage order of Multivector<A, G>.
template <int N, GradeMask G>
inline constexpr auto blade_list = [] {
  std::array<BladeMask, blade_count<N>(G)> out{};
  std::size_t i = 0;
  for (BladeMask m = 0; m < (BladeMask{1} << N); ++m)
    if (G >> clifford::grade_of(m) & 1u) out[i++] = m;
  return out;
}();

// Position of each blade mask in blade_list<N, G> (−1 when its grade is not in G).
template <int N, GradeMask G>
inline constexpr auto blade_position = [] {
  std::array<int, std::size_t{1} << N> out{};
  for (auto& x : out) x = -1;
  int i = 0;
  for (BladeMask m : blade_list<N, G>) out[m] = i++;
  return out;
}();

// The grade set {n − k : k ∈ g}: the grades of the duals.
template <int N>
constexpr GradeMask complement_grades(GradeMask g) {
  GradeMask out = 0;
  for (int k = 0; k <= N; ++k)
    if (g >> k & 1u) out |= GradeMask{1} << (N - k);
  return out;
}

}  // namespace pgamesh::graded
