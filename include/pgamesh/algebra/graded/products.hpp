// Products of graded multivectors. For each product kind and pair of grade sets, the list of
// terms (i, j → k, sign) is built at compile time from the blade signs of clifford/blade.hpp,
// with the pairs that vanish dropped (degenerate generators, blades outside the product's filter
// or outside the requested grades); the result's grade set is the set of grades those terms
// reach. Lists of up to `unroll_limit` terms are evaluated fully unrolled, longer ones by a loop
// over the constant list (compile time stays sane for 8 generators).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "pgamesh/algebra/graded/multivector.hpp"

namespace pgamesh::graded {

// The bilinear products, with the general engine's definitions (clifford/products.hpp).
enum class Product {
  geometric,         // A B
  outer,             // A ∧ B
  left_contraction,  // Σ ⟨A_r B_s⟩_(s−r), zero for r > s
  inner,             // Σ ⟨A_r B_s⟩_|r−s| (the symmetric "fat dot", ganja's |)
  scalar,            // ⟨A B⟩_0
  regressive,        // (A* ∧ B*)^(−*), paper eq. 2.2
};

// Term lists longer than this are evaluated by a loop instead of unrolled code. AddressSanitizer
// builds instrument every access of an unrolled list, which made compiling the tests take many
// minutes; they unroll only short lists (the same terms in the same order: the same sums).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr std::size_t unroll_limit = 64;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr std::size_t unroll_limit = 64;
#else
inline constexpr std::size_t unroll_limit = 2048;
#endif
#else
inline constexpr std::size_t unroll_limit = 2048;
#endif

// Coefficient of the product of basis blades a and b (0 when the pair does not contribute) and
// the blade it lands on.
template <class A, Product K>
constexpr double pair_factor(BladeMask a, BladeMask b) {
  switch (K) {
    case Product::geometric:
      return A::product_factor(a, b);
    case Product::outer:
      return (a & b) == 0 ? clifford::reorder_sign(a, b) : 0.0;
    case Product::left_contraction:
      return (a & ~b) == 0 ? A::product_factor(a, b) : 0.0;
    case Product::inner:
      return ((a & ~b) == 0 || (b & ~a) == 0) ? A::product_factor(a, b) : 0.0;
    case Product::scalar:
      return a == b ? A::product_factor(a, b) : 0.0;
    case Product::regressive: {
      // e_a* ∧ e_b* is non-zero when the complements are disjoint, i.e. a ∪ b = all; then
      // undual(dual_sign(a) dual_sign(b) e_(~a) ∧ e_(~b)) lands on e_(a∩b).
      const BladeMask all = A::full_mask, ca = all & ~a, cb = all & ~b;
      if ((ca & cb) != 0) return 0.0;
      return clifford::dual_sign(a, A::n) * clifford::dual_sign(b, A::n) *
             clifford::reorder_sign(ca, cb) * clifford::undual_sign(ca | cb, A::n);
    }
  }
  return 0.0;
}

template <Product K>
constexpr BladeMask pair_blade(BladeMask a, BladeMask b) {
  return K == Product::regressive ? (a & b) : (a ^ b);
}

// One term of a product: out[k] (=|+=|-=) x[i] · y[j].
struct Term {
  std::uint16_t i, j, k;
  bool negative;
  bool first;  // the first term of out[k]: assigns instead of adding
};

// The compile-time term list of product K of grade sets GA, GB, keeping result grades in Keep.
template <class A, Product K, GradeMask GA, GradeMask GB, GradeMask Keep>
struct ProductTable {
  static constexpr const auto& xs = blade_list<A::n, GA>;
  static constexpr const auto& ys = blade_list<A::n, GB>;

  // Each blade pair's sign (0 when the pair does not contribute or lands outside Keep) and the
  // blade it lands on, evaluated once: the compiler's constant evaluator is slow (about half a
  // microsecond per operation), and the passes below read this instead of recomputing the signs.
  struct Pair {
    std::int8_t sign;
    BladeMask blade;
  };
  static constexpr auto pairs = [] {
    std::array<Pair, xs.size() * ys.size()> out{};
    std::size_t n = 0;
    for (BladeMask a : xs)
      for (BladeMask b : ys) {
        const double f = pair_factor<A, K>(a, b);
        const BladeMask blade = pair_blade<K>(a, b);
        const bool keep = f != 0 && (Keep >> clifford::grade_of(blade) & 1u) != 0;
        out[n++] = Pair{static_cast<std::int8_t>(!keep ? 0 : (f < 0 ? -1 : 1)), blade};
      }
    return out;
  }();

  // Grades reached by the non-vanishing terms.
  static constexpr GradeMask result = [] {
    GradeMask g = 0;
    for (const Pair& p : pairs)
      if (p.sign != 0) g |= GradeMask{1} << clifford::grade_of(p.blade);
    return g;
  }();

  static constexpr std::size_t count = [] {
    std::size_t n = 0;
    for (const Pair& p : pairs)
      if (p.sign != 0) ++n;
    return n;
  }();

  // Terms grouped by output blade (a counting sort on k), the first of each group marked; within a
  // group in the order of (i, j), which fixes the order of the sums.
  static constexpr auto terms = [] {
    std::array<Term, count> out{};
    constexpr std::size_t outputs = blade_list<A::n, result>.size();
    std::array<std::size_t, outputs + 1> start{};
    for (const Pair& p : pairs)
      if (p.sign != 0) ++start[static_cast<std::size_t>(blade_position<A::n, result>[p.blade]) + 1];
    for (std::size_t k = 0; k < outputs; ++k) start[k + 1] += start[k];
    std::array<std::size_t, outputs + 1> next = start;
    for (std::size_t i = 0; i < xs.size(); ++i)
      for (std::size_t j = 0; j < ys.size(); ++j) {
        const Pair& p = pairs[i * ys.size() + j];
        if (p.sign == 0) continue;
        const auto k = static_cast<std::size_t>(blade_position<A::n, result>[p.blade]);
        const bool first = next[k] == start[k];
        out[next[k]++] = Term{static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(j),
                              static_cast<std::uint16_t>(k), p.sign < 0, first};
      }
    return out;
  }();
};

// Adds the terms I… of Table to out in one fold expression (no per-term function), every index
// and sign a constant: out[k] = (first ? −0 : out[k]) ± x[i] y[j], where −0 + v = v exactly, so
// the optimiser reduces each term to one multiply and at most one add or subtract.
template <class Table, class Out, class X, class Y, std::size_t... I>
constexpr void add_terms(Out& out, const X& x, const Y& y, std::index_sequence<I...>) {
  ((out.c[Table::terms[I].k] = (Table::terms[I].first ? -0.0 : out.c[Table::terms[I].k]) +
                               (Table::terms[I].negative ? -1.0 : 1.0) *
                                   (x.c[Table::terms[I].i] * y.c[Table::terms[I].j])),
   ...);
}

// Product K of x and y restricted to the grades in Keep (all by default).
template <Product K, GradeMask Keep = ~GradeMask{0}, class A, GradeMask GA, GradeMask GB>
constexpr auto product(const Multivector<A, GA>& x, const Multivector<A, GB>& y) {
  using Table = ProductTable<A, K, GA, GB, Keep>;
  Multivector<A, Table::result> out;
  if constexpr (Table::count <= unroll_limit) {
    add_terms<Table>(out, x, y, std::make_index_sequence<Table::count>{});
  } else {
    for (const Term& e : Table::terms) {
      const double v = x.c[e.i] * y.c[e.j];
      out.c[e.k] += e.negative ? -v : v;
    }
  }
  return out;
}

// Geometric product A B.
template <class A, GradeMask GA, GradeMask GB>
constexpr auto geometric(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return product<Product::geometric>(a, b);
}

// Outer (wedge) product A ∧ B — the meet in PGA.
template <class A, GradeMask GA, GradeMask GB>
constexpr auto outer(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return product<Product::outer>(a, b);
}

// Left contraction A ⌋ B = Σ ⟨A_r B_s⟩_(s−r) (zero for r > s).
template <class A, GradeMask GA, GradeMask GB>
constexpr auto left_contraction(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return product<Product::left_contraction>(a, b);
}

// Symmetric inner product Σ ⟨A_r B_s⟩_|r−s| (clifford::inner, ganja.js `|`, docs/conventions.md
// §4).
template <class A, GradeMask GA, GradeMask GB>
constexpr auto inner(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return product<Product::inner>(a, b);
}

// Scalar product ⟨A B⟩_0.
template <class A, GradeMask GA, GradeMask GB>
constexpr double scalar_product(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return scalar_part(product<Product::scalar>(a, b));
}

// Regressive product (join) A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2), in one pass.
template <class A, GradeMask GA, GradeMask GB>
constexpr auto regressive(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return product<Product::regressive>(a, b);
}

// The join of PGA: the regressive product.
template <class A, GradeMask GA, GradeMask GB>
constexpr auto join(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return regressive(a, b);
}

template <class A, GradeMask GA, GradeMask GB>
constexpr auto operator*(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return geometric(a, b);
}
template <class A, GradeMask GA, GradeMask GB>
constexpr auto operator^(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return outer(a, b);
}
template <class A, GradeMask GA, GradeMask GB>
constexpr auto operator|(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return inner(a, b);
}
template <class A, GradeMask GA, GradeMask GB>
constexpr auto operator&(const Multivector<A, GA>& a, const Multivector<A, GB>& b) {
  return regressive(a, b);
}

// ⟨A Ã⟩_0 — the squared norm of a blade or versor (can be negative in mixed signatures).
template <class A, GradeMask G>
constexpr double norm_squared(const Multivector<A, G>& a) {
  return scalar_product(a, reverse(a));
}

// sqrt |⟨A Ã⟩_0|.
template <class A, GradeMask G>
double norm(const Multivector<A, G>& a) {
  return std::sqrt(std::abs(norm_squared(a)));
}

// Sandwich V X Ṽ projected to X's grades (motors and rotors act this way, docs/conventions.md §7).
// The second product keeps only the terms that land on X's grades, so the grades a versor cannot
// produce from X are never computed.
template <class A, GradeMask GV, GradeMask GX>
constexpr Multivector<A, GX> sandwich(const Multivector<A, GV>& v, const Multivector<A, GX>& x) {
  return project<GX>(product<Product::geometric, GX>(geometric(v, x), reverse(v)));
}

// Inverse of a versor: Ṽ / (V Ṽ). Throws std::domain_error when V Ṽ is not a non-zero scalar
// (coefficients beyond 1e-12 of its largest), as clifford::inverse does.
template <class A, GradeMask G>
Multivector<A, G> inverse(const Multivector<A, G>& v) {
  const Multivector<A, G> r = reverse(v);
  const auto vr = geometric(v, r);
  const double s = scalar_part(vr);
  double scale = 1e-300;
  for (double c : vr.c) scale = std::max(scale, std::abs(c));
  bool scalar = s != 0;
  for (std::size_t i = 0; i < vr.size; ++i)
    if (vr.blades[i] != 0 && std::abs(vr.c[i]) > 1e-12 * scale) scalar = false;
  if (!scalar) throw std::domain_error("graded::inverse: V ~V is not a non-zero scalar");
  return r / s;
}

}  // namespace pgamesh::graded
