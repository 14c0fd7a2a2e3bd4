// PGA R(d,0,1) for a compile-time dimension d (1 ≤ d ≤ 7): dense multivectors of 2^(d+1)
// coefficients indexed by blade bitmask (bit 0 = e0, bit i = e_i), products from tables built at
// compile time. Conventions follow ERRATA §0.1 in any d: e0² = 0, e_i² = 1; the Hodge dual
// e_J e_J* = I = e0 e1 … ed; the join A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2); the point
// x ↦ (e0 + Σ x_i e_i)*, so o ∨ v1 ∨ … ∨ vd = det[v1 … vd] and S ∨ o = (−1)^d o ∨ S.
// For d = 3 the coefficients agree with pga3 (named blades there: e032 = −e023, …).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "pgamesh/algebra/clifford/blade.hpp"
#include "pgamesh/algebra/clifford/closed_forms.hpp"

namespace pgamesh::pgad {

using clifford::BladeMask;

// Euclidean coordinates in d dimensions.
template <int D>
using Vec = std::array<double, D>;

template <int D>
struct Multivector {
  static_assert(D >= 1 && D <= 7, "pgad supports 1 ≤ d ≤ 7");
  static constexpr int generators = D + 1;
  static constexpr std::size_t size = std::size_t{1} << (D + 1);
  static constexpr BladeMask pseudoscalar = static_cast<BladeMask>(size - 1);
  std::array<double, size> c{};

  constexpr double& operator[](BladeMask m) { return c[m]; }
  constexpr double operator[](BladeMask m) const { return c[m]; }
};

namespace detail {
// Sign tables for R(d,0,1), built at compile time:
//  gp[a][b]   — geometric-product factor of e_a e_b: 0 when e0 repeats, else the reorder sign;
//  join[i][j] — the sign of the term of e_(~i) ∨ e_(~j) = ((e_(~i))* ∧ (e_(~j))*)^(−*) (paper
//               eq. 2.2), i.e. gp · dual sign of both factors · undual sign of e_(i|j), for
//               disjoint i, j (complements within I = e0 e1 … ed).
template <int D>
struct ProductTable {
  static constexpr std::size_t size = Multivector<D>::size;
  std::array<std::array<signed char, size>, size> gp{};
  std::array<std::array<signed char, size>, size> join{};
};
template <int D>
constexpr ProductTable<D> make_product_table() {
  ProductTable<D> t{};
  constexpr BladeMask all = Multivector<D>::pseudoscalar;
  for (BladeMask a = 0; a < ProductTable<D>::size; ++a)
    for (BladeMask b = 0; b < ProductTable<D>::size; ++b) {
      t.gp[a][b] = (a & b & 1u) ? 0 : static_cast<signed char>(clifford::reorder_sign(a, b));
      if ((a & b) == 0)
        t.join[a][b] = static_cast<signed char>(t.gp[a][b] * clifford::dual_sign(all & ~a, D + 1) *
                                                clifford::dual_sign(all & ~b, D + 1) *
                                                clifford::undual_sign(a | b, D + 1));
    }
  return t;
}
template <int D>
inline constexpr ProductTable<D> product_table = make_product_table<D>();

// Σ over pairs (i, j) of non-zero coefficients with keep(i, j) of gp[i][j] a_i b_j e_(i^j), in
// ascending (i, j) order. The non-zero blades of b are listed once, so sparse operands (points,
// motors) cost only their non-zero pairs.
template <int D, class Keep>
constexpr Multivector<D> product(const Multivector<D>& a, const Multivector<D>& b, Keep keep) {
  constexpr std::size_t size = Multivector<D>::size;
  std::array<BladeMask, size> nz{};
  std::size_t count = 0;
  for (BladeMask j = 0; j < size; ++j)
    if (b.c[j] != 0) nz[count++] = j;
  Multivector<D> r{};
  const auto& t = product_table<D>.gp;
  for (BladeMask i = 0; i < size; ++i) {
    const double ai = a.c[i];
    if (ai == 0) continue;
    for (std::size_t k = 0; k < count; ++k) {
      const BladeMask j = nz[k];
      if (keep(i, j)) r.c[i ^ j] += t[i][j] * ai * b.c[j];
    }
  }
  return r;
}

template <int D, class Sign>
constexpr Multivector<D> complement(const Multivector<D>& a, Sign sign) {
  Multivector<D> r{};
  for (BladeMask m = 0; m < Multivector<D>::size; ++m)
    r.c[Multivector<D>::pseudoscalar & ~m] = sign(m) * a.c[m];
  return r;
}

template <int D, class SignOfGrade>
constexpr Multivector<D> scale_grades(const Multivector<D>& a, SignOfGrade sign) {
  Multivector<D> r = a;
  for (BladeMask m = 0; m < Multivector<D>::size; ++m) r.c[m] *= sign(clifford::grade_of(m));
  return r;
}
}  // namespace detail

// ---- linear structure ---------------------------------------------------------------------------

template <int D>
constexpr Multivector<D> operator+(Multivector<D> a, const Multivector<D>& b) {
  for (std::size_t i = 0; i < a.size; ++i) a.c[i] += b.c[i];
  return a;
}
template <int D>
constexpr Multivector<D> operator-(Multivector<D> a, const Multivector<D>& b) {
  for (std::size_t i = 0; i < a.size; ++i) a.c[i] -= b.c[i];
  return a;
}
template <int D>
constexpr Multivector<D> operator*(double s, Multivector<D> a) {
  for (double& x : a.c) x *= s;
  return a;
}
template <int D>
constexpr Multivector<D> operator*(Multivector<D> a, double s) {
  return s * a;
}
template <int D>
constexpr Multivector<D>& operator+=(Multivector<D>& a, const Multivector<D>& b) {
  for (std::size_t i = 0; i < a.size; ++i) a.c[i] += b.c[i];
  return a;
}

// c times the basis blade `mask`.
template <int D>
constexpr Multivector<D> blade(BladeMask mask, double c = 1.0) {
  Multivector<D> r{};
  r.c[mask] = c;
  return r;
}

// The scalar s.
template <int D>
constexpr Multivector<D> scalar(double s) {
  return blade<D>(0, s);
}

// Grade projection ⟨A⟩_k.
template <int D>
constexpr Multivector<D> grade(const Multivector<D>& a, int k) {
  Multivector<D> r{};
  for (BladeMask m = 0; m < a.size; ++m)
    if (clifford::grade_of(m) == k) r.c[m] = a.c[m];
  return r;
}

// ---- products -----------------------------------------------------------------------------------

// Geometric product A B.
template <int D>
constexpr Multivector<D> geometric(const Multivector<D>& a, const Multivector<D>& b) {
  return detail::product(a, b, [](BladeMask, BladeMask) { return true; });
}
// Outer product A ∧ B (the meet). Only the pairs with disjoint factors are visited: j runs over
// the subsets of ~i in ascending order (the same terms in the same order as the general product).
template <int D>
constexpr Multivector<D> outer(const Multivector<D>& a, const Multivector<D>& b) {
  constexpr BladeMask all = Multivector<D>::pseudoscalar;
  const auto& t = detail::product_table<D>.gp;
  Multivector<D> r{};
  for (BladeMask i = 0; i <= all; ++i) {
    const double ai = a.c[i];
    if (ai == 0) continue;
    const BladeMask free = all & ~i;
    BladeMask j = 0;
    do {
      r.c[i | j] += t[i][j] * ai * b.c[j];
      j = (j - free) & free;  // next subset of `free` in ascending order
    } while (j != 0);
  }
  return r;
}
// Left contraction A ⌋ B.
template <int D>
constexpr Multivector<D> left_contraction(const Multivector<D>& a, const Multivector<D>& b) {
  return detail::product(a, b, [](BladeMask i, BladeMask j) { return (i & ~j) == 0; });
}
// Symmetric inner product Σ ⟨A_r B_s⟩_|r−s| (ERRATA §0.1 `|`).
template <int D>
constexpr Multivector<D> inner(const Multivector<D>& a, const Multivector<D>& b) {
  return detail::product(a, b,
                         [](BladeMask i, BladeMask j) { return (i & ~j) == 0 || (j & ~i) == 0; });
}

// Hodge dual, e_J e_J* = I (ERRATA §0.1).
template <int D>
constexpr Multivector<D> dual(const Multivector<D>& a) {
  return detail::complement(a, [](BladeMask m) { return clifford::dual_sign(m, D + 1); });
}
// Undual A^(−*), the inverse of dual.
template <int D>
constexpr Multivector<D> undual(const Multivector<D>& a) {
  return detail::complement(a, [](BladeMask m) { return clifford::undual_sign(m, D + 1); });
}
// Join (regressive product) A ∨ B = (A* ∧ B*)^(−*), paper eq. 2.2.
// Computed in one pass without forming the duals: e_p ∨ e_q ≠ 0 only when p | q = I, and then it
// is ± e_(p&q) with the sign from detail::product_table::join. The loop visits i = ~p and
// j ⊆ p in the order undual(outer(dual(a), dual(b))) would, so the sums round the same way.
template <int D>
constexpr Multivector<D> join(const Multivector<D>& a, const Multivector<D>& b) {
  constexpr BladeMask all = Multivector<D>::pseudoscalar;
  const auto& t = detail::product_table<D>.join;
  Multivector<D> r{};
  for (BladeMask i = 0; i <= all; ++i) {
    const BladeMask p = all & ~i;
    const double ap = a.c[p];
    if (ap == 0) continue;
    BladeMask j = 0;
    do {
      const BladeMask q = all & ~j;
      r.c[p & q] += t[i][j] * ap * b.c[q];
      j = (j - p) & p;  // next subset of p in ascending order
    } while (j != 0);
  }
  return r;
}
// v0 ∨ v1 ∨ … (left to right).
template <int D, class... Rest>
constexpr Multivector<D> join(const Multivector<D>& a, const Multivector<D>& b,
                              const Rest&... rest) {
  return join(join(a, b), rest...);
}

// Reverse Ã.
template <int D>
constexpr Multivector<D> reverse(const Multivector<D>& a) {
  return detail::scale_grades(a, clifford::reverse_sign);
}
// Grade involution Â.
template <int D>
constexpr Multivector<D> involution(const Multivector<D>& a) {
  return detail::scale_grades(a, clifford::involution_sign);
}

template <int D>
constexpr Multivector<D> operator*(const Multivector<D>& a, const Multivector<D>& b) {
  return geometric(a, b);
}
template <int D>
constexpr Multivector<D> operator^(const Multivector<D>& a, const Multivector<D>& b) {
  return outer(a, b);
}
template <int D>
constexpr Multivector<D> operator&(const Multivector<D>& a, const Multivector<D>& b) {
  return join(a, b);
}
template <int D>
constexpr Multivector<D> operator|(const Multivector<D>& a, const Multivector<D>& b) {
  return inner(a, b);
}
template <int D>
constexpr Multivector<D> operator~(const Multivector<D>& a) {
  return reverse(a);
}
template <int D>
constexpr Multivector<D> operator!(const Multivector<D>& a) {
  return dual(a);
}

// ---- points, directions, planes -----------------------------------------------------------------

// The point x = (e0 + Σ x_i e_i)* (ERRATA §0.1; for d = 3: e123 + x e032 + y e013 + z e021).
template <int D>
constexpr Multivector<D> point(const Vec<D>& x) {
  Multivector<D> v = blade<D>(1);
  for (int i = 0; i < D; ++i) v.c[BladeMask{2} << i] = x[static_cast<std::size_t>(i)];
  return dual(v);
}
// The direction (ideal point) (Σ x_i e_i)*.
template <int D>
constexpr Multivector<D> direction(const Vec<D>& x) {
  Multivector<D> v{};
  for (int i = 0; i < D; ++i) v.c[BladeMask{2} << i] = x[static_cast<std::size_t>(i)];
  return dual(v);
}
// The origin o = e0* = e1 … ed.
template <int D>
constexpr Multivector<D> origin() {
  return point<D>(Vec<D>{});
}
// The hyperplane n·x + d = 0 as Σ n_i e_i + d e0.
template <int D>
constexpr Multivector<D> hyperplane(const Vec<D>& n, double d) {
  Multivector<D> p = blade<D>(1, d);
  for (int i = 0; i < D; ++i) p.c[BladeMask{2} << i] = n[static_cast<std::size_t>(i)];
  return p;
}

// Weight of a point (its e0* coefficient; 0 for a direction).
template <int D>
constexpr double weight(const Multivector<D>& p) {
  return undual(p).c[1];
}
// Euclidean position of a weighted point: (e_i* coefficients) / weight.
template <int D>
constexpr Vec<D> position(const Multivector<D>& p) {
  const Multivector<D> v = undual(p);
  Vec<D> x{};
  for (int i = 0; i < D; ++i) x[static_cast<std::size_t>(i)] = v.c[BladeMask{2} << i] / v.c[1];
  return x;
}

// ---- norms and the Euclidean split (ERRATA §0.1, paper eq. 3.1) --------------------------------

// Euclidean part A_E (blades without e0) and ideal part e0 A_I (blades with e0).
template <int D>
struct EuclideanSplit {
  Multivector<D> euclidean, ideal;
};
template <int D>
constexpr EuclideanSplit<D> euclidean_split(const Multivector<D>& a) {
  EuclideanSplit<D> s{};
  for (BladeMask m = 0; m < a.size; ++m) ((m & 1u) ? s.ideal : s.euclidean).c[m] = a.c[m];
  return s;
}

// ‖A‖ = sqrt(Σ squares of the coefficients without e0).
template <int D>
double norm(const Multivector<D>& a) {
  double s = 0;
  for (BladeMask m = 0; m < a.size; m += 2) s += a.c[m] * a.c[m];
  return std::sqrt(s);
}
// ‖A‖∞ = sqrt(Σ squares of the coefficients with e0) = ‖A ∨ o‖ = ‖A*‖.
template <int D>
double ideal_norm(const Multivector<D>& a) {
  double s = 0;
  for (BladeMask m = 1; m < a.size; m += 2) s += a.c[m] * a.c[m];
  return std::sqrt(s);
}

// ---- motors -------------------------------------------------------------------------------------

// Sandwich M X M̃.
template <int D>
constexpr Multivector<D> sandwich(const Multivector<D>& m, const Multivector<D>& x) {
  return geometric(geometric(m, x), reverse(m));
}

namespace detail {
template <int D>
bool only_grades(const Multivector<D>& a, unsigned allowed) {
  double scale = 0;
  for (double x : a.c) scale = std::max(scale, std::abs(x));
  for (BladeMask m = 0; m < a.size; ++m)
    if (!(allowed >> clifford::grade_of(m) & 1) && std::abs(a.c[m]) > 1e-12 * scale) return false;
  return true;
}
}  // namespace detail

// exp of a bivector B: closed form when B² is a scalar (rotation cos/sin, translation 1 + B), the
// screw form when d = 3 (B² = scalar + e0123 part); scaled-and-squared Taylor series otherwise
// (non-simple bivectors in d ≥ 4).
template <int D>
Multivector<D> exp(const Multivector<D>& b) {
  const Multivector<D> b2 = geometric(b, b);
  for (double x : b2.c)
    if (!std::isfinite(x)) throw std::domain_error("pgad::exp: the argument is not finite");
  if (detail::only_grades(b2, 1u)) {
    const clifford::SimpleExp e = clifford::simple_exp(b2.c[0]);
    return scalar<D>(e.c0) + e.cB * b;
  }
  if constexpr (D == 3) {
    const clifford::StudyExp e = clifford::study_exp(b2.c[0], b2.c[15]);
    return scalar<D>(e.c0) + blade<D>(15, e.cI) + e.cL * b + e.cIL * geometric(blade<D>(15), b);
  }
  double size = 0;
  for (double x : b.c) size += std::abs(x);
  if (!std::isfinite(size)) throw std::domain_error("pgad::exp: the argument is not finite");
  int k = 0;
  for (; size > 0.5; size /= 2) ++k;
  const Multivector<D> small = std::ldexp(1.0, -k) * b;
  Multivector<D> sum = scalar<D>(1), term = scalar<D>(1);
  for (int i = 1; i <= 30; ++i) {
    term = (1.0 / i) * geometric(term, small);
    sum += term;
  }
  for (int i = 0; i < k; ++i) sum = geometric(sum, sum);
  return sum;
}

// log of a normalised motor: closed form when its bivector part squares to a scalar (any d), the
// screw form for d = 3. Throws std::domain_error otherwise (no closed form in d ≥ 4).
template <int D>
Multivector<D> log(const Multivector<D>& m) {
  const Multivector<D> b = grade(m, 2);
  const Multivector<D> b2 = geometric(b, b);
  if (detail::only_grades(m, 1u | 4u) && detail::only_grades(b2, 1u))
    return clifford::simple_log(m.c[0], b2.c[0]) * b;
  if constexpr (D == 3) {
    const clifford::StudyLog l =
        clifford::study_log(m.c[0], norm(b), m.c[Multivector<D>::pseudoscalar]);
    return l.cL * b + l.cIL * geometric(blade<D>(Multivector<D>::pseudoscalar), b);
  }
  throw std::domain_error("pgad::log: no closed form for this motor");
}

}  // namespace pgamesh::pgad
