// Conformal GA R(4,1) in the null basis e_o, e1, e2, e3, e_∞ (docs/models-cga.md §1): storage,
// products, metric dual and the golden-file blade keys.
//
// Elements are graded multivectors (pgamesh/algebra/graded.hpp) whose blade masks name outer
// products of the null basis: bit 0 = e_o, bits 1–3 = e1, e2, e3, bit 4 = e_∞, so mask 0b10011 is
// e_o ∧ e1 ∧ e_∞ (key "eo^e1^einf") — the same masks and blades as the general engine's `cga3`.
// The metric-free operations of `graded` (∧, ∨, reverse, involution, grade projection, sums) apply
// unchanged. The metric products are this file's: their compile-time term lists are built by
// expanding both blades in the orthogonal basis (e_∞ = e₊ + e₋, e_o = ½(e₋ − e₊), Hitzer eq. 3 with
// e_o·e_∞ = −1), multiplying there with graded::Algebra<4, 1>'s signs and mapping back, so every
// coefficient is an exact dyadic constant. Storing the null basis (rather than e₊, e₋) keeps a
// point's weight exact far from the origin: in e₊, e₋ a point at 10⁶ has coefficients ½x² ∓ ½
// whose difference, the weight, loses 4 digits.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/algebra/graded.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::cga {

using graded::BladeMask;
using graded::GradeMask;

// The algebra tag of the null basis (see above). It has no diagonal signature: graded's own
// metric products would be wrong here, so product_factor refuses at compile time every product
// but scalar × scalar, and the metric products below must be used instead (ADL picks them).
struct NullBasis {
  static constexpr int n = 5;
  static constexpr BladeMask full_mask = 31;
  static constexpr GradeMask all_grades = 63, even_grades = 0x15, odd_grades = 0x2a;
  static constexpr double product_factor(BladeMask a, BladeMask b) {
    if (a == 0 && b == 0) return 1.0;
    throw "cga::NullBasis: use cga::geometric, not graded's diagonal products";
  }
};

template <GradeMask G>
using Multivector = graded::Multivector<NullBasis, G>;
template <int K>
using Blade = graded::KVector<NullBasis, K>;
using Vector = Blade<1>;      // points, dual spheres and dual planes
using Bivector = Blade<2>;    // point pairs, flat points; dual circles and dual lines
using Trivector = Blade<3>;   // circles and lines; dual point pairs
using Quadvector = Blade<4>;  // spheres and planes
using Pseudoscalar = Blade<5>;
using Versor = graded::Even<NullBasis>;  // motors: rotor, translator, dilator and products
using Rotor = Multivector<0b101>;        // scalar + bivector: each elementary motor
using Full = graded::Full<NullBasis>;

// Blade masks of the null basis.
inline constexpr BladeMask eo_mask = 1, e1_mask = 2, e2_mask = 4, e3_mask = 8, einf_mask = 16;
inline constexpr BladeMask euclidean_mask = 14;

// The basis vectors and the pseudoscalar I = e_o ∧ e1 ∧ e2 ∧ e3 ∧ e_∞ (I² = −1).
constexpr Vector eo(double c = 1.0) {
  return graded::basis<NullBasis, eo_mask>(c);
}
constexpr Vector e1(double c = 1.0) {
  return graded::basis<NullBasis, e1_mask>(c);
}
constexpr Vector e2(double c = 1.0) {
  return graded::basis<NullBasis, e2_mask>(c);
}
constexpr Vector e3(double c = 1.0) {
  return graded::basis<NullBasis, e3_mask>(c);
}
constexpr Vector einf(double c = 1.0) {
  return graded::basis<NullBasis, einf_mask>(c);
}
constexpr Pseudoscalar pseudoscalar(double c = 1.0) {
  return graded::basis<NullBasis, 31>(c);
}

namespace detail {

// Up to two (blade, coefficient) terms: the image of one basis blade under the change of basis.
struct BladeImage {
  int count = 0;
  std::array<BladeMask, 2> mask{};
  std::array<double, 2> coeff{};
};

// Orthogonal masks: bits 0–2 = e1, e2, e3, bit 3 = e₊ (square +1), bit 4 = e₋ (square −1), the
// generator order of graded::Algebra<4, 1>. E is the Euclidean part, s = (−1)^grade(E) the sign
// of moving e_o across it.
constexpr BladeImage to_orthogonal(BladeMask null) {
  const BladeMask e = (null >> 1) & 7u;
  const double s = clifford::odd_parity(e) ? -1.0 : 1.0;
  const bool o = (null & eo_mask) != 0, inf = (null & einf_mask) != 0;
  if (!o && !inf) return {1, {e, 0}, {1.0, 0.0}};
  if (o && !inf) return {2, {e | 16u, e | 8u}, {0.5 * s, -0.5 * s}};  // e_o∧E = s E∧½(e₋ − e₊)
  if (!o && inf) return {2, {e | 8u, e | 16u}, {1.0, 1.0}};  // E∧e_∞ = E∧(e₊ + e₋)
  return {1, {e | 24u, 0}, {-s, 0.0}};  // e_o∧E∧e_∞ = s E∧e_o∧e_∞ = −s E∧e₊∧e₋
}

constexpr BladeImage to_null(BladeMask orth) {
  const BladeMask e = orth & 7u, b = e << 1;
  const double s = clifford::odd_parity(e) ? -1.0 : 1.0;
  switch (orth >> 3) {
    case 0:
      return {1, {b, 0}, {1.0, 0.0}};
    case 1:  // E∧e₊ = E∧(½e_∞ − e_o)
      return {2, {b | einf_mask, b | eo_mask}, {0.5, -s}};
    case 2:  // E∧e₋ = E∧(e_o + ½e_∞)
      return {2, {b | eo_mask, b | einf_mask}, {s, 0.5}};
    default:  // E∧e₊∧e₋ = −E∧e_o∧e_∞
      return {1, {b | eo_mask | einf_mask, 0}, {-s, 0.0}};
  }
}

// The geometric product of null-basis blades a and b: at most 8 (blade, coefficient) terms.
struct PairProduct {
  int count = 0;
  std::array<BladeMask, 8> mask{};
  std::array<double, 8> coeff{};
};

constexpr PairProduct blade_product(BladeMask a, BladeMask b) {
  using R41 = graded::Algebra<4, 1>;
  PairProduct out;
  const BladeImage ia = to_orthogonal(a), ib = to_orthogonal(b);
  for (int i = 0; i < ia.count; ++i)
    for (int j = 0; j < ib.count; ++j) {
      const double f = R41::product_factor(ia.mask[i], ib.mask[j]);
      if (f == 0) continue;
      const BladeImage back = to_null(ia.mask[i] ^ ib.mask[j]);
      for (int k = 0; k < back.count; ++k) {
        const double c = ia.coeff[i] * ib.coeff[j] * f * back.coeff[k];
        int slot = 0;
        while (slot < out.count && out.mask[slot] != back.mask[k]) ++slot;
        if (slot == out.count) {
          out.mask[slot] = back.mask[k];
          out.coeff[slot] = 0;
          ++out.count;
        }
        out.coeff[slot] += c;
      }
    }
  return out;
}

// All 32 × 32 blade products, computed once (indexed a · 32 + b): the term lists below only look
// them up, which keeps each list's constant evaluation within compilers' step limits.
inline constexpr auto blade_products = [] {
  std::array<PairProduct, 1024> t{};
  for (BladeMask a = 0; a < 32; ++a)
    for (BladeMask b = 0; b < 32; ++b) t[a * 32 + b] = blade_product(a, b);
  return t;
}();

// The metric products, each the grade selection of the geometric product that defines it (the
// same definitions as the general engine, clifford/products.hpp).
enum class Product { geometric, left_contraction, right_contraction, inner, scalar };

constexpr bool keeps(Product k, int r, int s, int g) {
  switch (k) {
    case Product::geometric:
      return true;
    case Product::left_contraction:
      return s >= r && g == s - r;
    case Product::right_contraction:
      return r >= s && g == r - s;
    case Product::inner:
      return g == (r > s ? r - s : s - r);
    case Product::scalar:
      return g == 0;
  }
  return false;
}

struct Term {
  std::uint16_t i, j, k;
  double coeff;
  bool first;  // the first term of out[k]: assigns instead of adding
};

template <Product K, GradeMask GA, GradeMask GB, GradeMask Keep>
struct Table {
  static constexpr const auto& xs = graded::blade_list<5, GA>;
  static constexpr const auto& ys = graded::blade_list<5, GB>;

  template <class F>
  static constexpr void each(F&& f) {
    for (std::size_t i = 0; i < xs.size(); ++i)
      for (std::size_t j = 0; j < ys.size(); ++j) {
        const PairProduct& p = blade_products[xs[i] * 32 + ys[j]];
        const int r = clifford::grade_of(xs[i]), s = clifford::grade_of(ys[j]);
        for (int t = 0; t < p.count; ++t) {
          const int g = clifford::grade_of(p.mask[t]);
          if (p.coeff[t] != 0 && keeps(K, r, s, g) && (Keep >> g & 1u) != 0)
            f(i, j, p.mask[t], p.coeff[t]);
        }
      }
  }

  static constexpr GradeMask result = [] {
    GradeMask g = 0;
    each([&](std::size_t, std::size_t, BladeMask m, double) {
      g |= GradeMask{1} << clifford::grade_of(m);
    });
    return g;
  }();

  static constexpr std::size_t count = [] {
    std::size_t n = 0;
    each([&](std::size_t, std::size_t, BladeMask, double) { ++n; });
    return n;
  }();

  // Terms grouped by output blade (counting sort), the first of each group marked.
  static constexpr auto terms = [] {
    std::array<Term, count> out{};
    constexpr std::size_t outputs = graded::blade_list<5, result>.size();
    std::array<std::size_t, outputs + 1> start{};
    each([&](std::size_t, std::size_t, BladeMask m, double) {
      ++start[static_cast<std::size_t>(graded::blade_position<5, result>[m]) + 1];
    });
    for (std::size_t k = 0; k < outputs; ++k) start[k + 1] += start[k];
    auto next = start;
    each([&](std::size_t i, std::size_t j, BladeMask m, double c) {
      const auto k = static_cast<std::size_t>(graded::blade_position<5, result>[m]);
      out[next[k]++] = Term{static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(j),
                            static_cast<std::uint16_t>(k), c, next[k] == start[k]};
    });
    return out;
  }();
};

// Adds terms Offset … Offset + |I| − 1 of table T in one fold expression, every index and
// coefficient a constant: out[k] = (first ? −0 : out[k]) + c · x[i] y[j] (−0 + v = v exactly).
template <class T, std::size_t Offset, class Out, class X, class Y, std::size_t... I>
constexpr void add_terms(Out& out, const X& x, const Y& y, std::index_sequence<I...>) {
  ((out.c[T::terms[Offset + I].k] =
        (T::terms[Offset + I].first ? -0.0 : out.c[T::terms[Offset + I].k]) +
        T::terms[Offset + I].coeff * (x.c[T::terms[Offset + I].i] * y.c[T::terms[Offset + I].j])),
   ...);
}

// Folds of at most this many terms (clang limits a fold's nesting to 256), chained.
inline constexpr std::size_t fold_chunk = 128;

template <class T, std::size_t Offset = 0, class Out, class X, class Y>
constexpr void add_all_terms(Out& out, const X& x, const Y& y) {
  constexpr std::size_t n = std::min(fold_chunk, T::count - Offset);
  add_terms<T, Offset>(out, x, y, std::make_index_sequence<n>{});
  if constexpr (Offset + n < T::count) add_all_terms<T, Offset + n>(out, x, y);
}

}  // namespace detail

// Product K of x and y, restricted to the grades in Keep (all by default).
template <detail::Product K, GradeMask Keep = ~GradeMask{0}, GradeMask GA, GradeMask GB>
constexpr auto product(const Multivector<GA>& x, const Multivector<GB>& y) {
  using T = detail::Table<K, GA, GB, Keep>;
  Multivector<T::result> out;
  if constexpr (T::count <= graded::unroll_limit) {
    detail::add_all_terms<T>(out, x, y);
  } else {
    for (const detail::Term& t : T::terms) out.c[t.k] += t.coeff * (x.c[t.i] * y.c[t.j]);
  }
  return out;
}

// Geometric product A B.
template <GradeMask GA, GradeMask GB>
constexpr auto geometric(const Multivector<GA>& a, const Multivector<GB>& b) {
  return product<detail::Product::geometric>(a, b);
}
// Left contraction A ⌋ B = Σ ⟨A_r B_s⟩_(s−r).
template <GradeMask GA, GradeMask GB>
constexpr auto left_contraction(const Multivector<GA>& a, const Multivector<GB>& b) {
  return product<detail::Product::left_contraction>(a, b);
}
// Right contraction A ⌊ B = Σ ⟨A_r B_s⟩_(r−s).
template <GradeMask GA, GradeMask GB>
constexpr auto right_contraction(const Multivector<GA>& a, const Multivector<GB>& b) {
  return product<detail::Product::right_contraction>(a, b);
}
// Symmetric inner product Σ ⟨A_r B_s⟩_|r−s| (ganja.js `|`); for vectors X·Y = −½|x − y|².
template <GradeMask GA, GradeMask GB>
constexpr auto inner(const Multivector<GA>& a, const Multivector<GB>& b) {
  return product<detail::Product::inner>(a, b);
}
// Scalar product ⟨A B⟩₀ (Hitzer's "∗").
template <GradeMask GA, GradeMask GB>
constexpr double scalar_product(const Multivector<GA>& a, const Multivector<GB>& b) {
  return graded::scalar_part(product<detail::Product::scalar>(a, b));
}

template <GradeMask GA, GradeMask GB>
constexpr auto operator*(const Multivector<GA>& a, const Multivector<GB>& b) {
  return geometric(a, b);
}
template <GradeMask GA, GradeMask GB>
constexpr auto operator|(const Multivector<GA>& a, const Multivector<GB>& b) {
  return inner(a, b);
}

// ⟨A Ã⟩₀: the squared norm of a blade or versor (negative for imaginary rounds' duals etc.).
template <GradeMask G>
constexpr double norm_squared(const Multivector<G>& a) {
  return scalar_product(a, graded::reverse(a));
}

// Metric dual X I⁻¹ and undual X I (I⁻¹ = −I), so undual(dual(X)) = X. This is the dual that
// maps an object's direct (OPNS) form to its dual (IPNS) form, not graded's Hodge complement.
template <GradeMask G>
constexpr auto dual(const Multivector<G>& x) {
  return geometric(x, pseudoscalar(-1.0));
}
template <GradeMask G>
constexpr auto undual(const Multivector<G>& x) {
  return geometric(x, pseudoscalar(1.0));
}

// Sandwich V X Ṽ on X's grades (the second product computes only those).
template <GradeMask GV, GradeMask GX>
constexpr Multivector<GX> sandwich(const Multivector<GV>& v, const Multivector<GX>& x) {
  return graded::project<GX>(
      product<detail::Product::geometric, GX>(geometric(v, x), graded::reverse(v)));
}

// The same element on the grades G2 (projection or widening).
template <GradeMask G2, GradeMask G>
constexpr Multivector<G2> widen(const Multivector<G>& x) {
  return graded::project<G2>(x);
}

// ---- blade keys ---------------------------------------------------------------------------------

// The golden files' key of a null-basis blade: "1", "eo", "e1^e2", "eo^e1^einf", …
std::string blade_key(BladeMask mask);

// Parses a key (factors in the basis order e_o, e1, e2, e3, e_∞, joined by '^'; "1" for the
// scalar); throws ModelError when it is not one.
BladeMask parse_blade_key(const std::string& key);

// Masks in the golden files' listing order: by grade, then lexicographic in the factors
// (eo^e1, eo^e2, eo^e3, eo^einf, e1^e2, …).
const std::array<BladeMask, 32>& listing_order();

// Coefficients of any element on the 32 blades, indexed by mask.
template <GradeMask G>
constexpr std::array<double, 32> coefficients(const Multivector<G>& x) {
  std::array<double, 32> out{};
  for (std::size_t i = 0; i < x.size; ++i) out[x.blades[i]] = x.c[i];
  return out;
}

// The non-zero blades of x as (key, coefficient) in listing order; coefficients with
// |c| ≤ rel · max|c| are left out (rel = 0: only exact zeros).
std::vector<std::pair<std::string, double>> named_blades(const std::array<double, 32>& coeffs,
                                                         double rel = 0.0);
template <GradeMask G>
std::vector<std::pair<std::string, double>> blades(const Multivector<G>& x, double rel = 0.0) {
  return named_blades(coefficients(x), rel);
}

// An element of the grades G from (key, coefficient) pairs; throws ModelError on an unknown key
// or a key whose grade is not in G.
Full from_named_full(const std::vector<std::pair<std::string, double>>& named);
template <GradeMask G>
Multivector<G> from_blades(const std::vector<std::pair<std::string, double>>& named) {
  const Full f = from_named_full(named);
  for (std::size_t i = 0; i < f.size; ++i)
    if (f.c[i] != 0 && Multivector<G>::index_of(f.blades[i]) < 0)
      throw ModelError("cga::from_blades: blade " + blade_key(f.blades[i]) +
                       " has a grade the target does not store");
  return graded::project<G>(f);
}

// "2 eo + 1.5 e1^einf": non-zero coefficients with their keys, "0" for zero.
std::string to_string(const std::array<double, 32>& coeffs);
template <GradeMask G>
std::string to_string(const Multivector<G>& x) {
  return to_string(coefficients(x));
}
template <GradeMask G>
std::ostream& operator<<(std::ostream& os, const Multivector<G>& x) {
  return os << to_string(x);
}

}  // namespace pgamesh::cga
