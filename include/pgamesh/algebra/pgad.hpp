// PGA R(d,0,1) for a compile-time dimension d (1 ≤ d ≤ 7): dense multivectors of 2^(d+1)
// coefficients indexed by blade bitmask (bit 0 = e0, bit i = e_i), products from tables built at
// compile time. Conventions follow ERRATA §0.1 in any d: e0² = 0, e_i² = 1; the Hodge dual
// e_J e_J* = I = e0 e1 … ed; the join A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2); the point
// x ↦ (e0 + Σ x_i e_i)*, so o ∨ v1 ∨ … ∨ vd = det[v1 … vd] and S ∨ o = (−1)^d o ∨ S.
// For d = 3 the coefficients agree with pga3 (named blades there: e032 = −e023, …).
#pragma once

#include <algorithm>
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

// ---- invariant decomposition (Roelfs & De Keninck, "Graded symmetry groups: plane and simple",
// 2021): a bivector of R(d,0,1), d ≤ 5, is a sum of commuting simple bivectors — at most two
// rotations F_j (F_j² = λ_j < 0, about orthogonal Euclidean planes) and one translation T (T² = 0)
// — so exp and log have closed forms factor by factor.

// The commuting simple parts of a bivector: B = Σ_j rotation[j] + translation.
template <int D>
struct BivectorSplit {
  std::array<Multivector<D>, 2> rotation{};
  std::array<double, 2> square{};  // λ_j = rotation[j]²
  int rotations = 0;
  Multivector<D> translation{};
};

namespace detail {
// Blades without e0 (the Euclidean part A_E of the split A = A_E + e0 A_I).
template <int D>
constexpr Multivector<D> euclidean_part(const Multivector<D>& a) {
  return euclidean_split(a).euclidean;
}
// The Euclidean vector t of the ideal bivector part e0 t = Σ t_i e0i, and back.
template <int D>
constexpr Multivector<D> ideal_vector(const Multivector<D>& b) {
  Multivector<D> t{};
  for (int i = 0; i < D; ++i) t.c[BladeMask{2} << i] = b.c[(BladeMask{2} << i) | 1u];
  return t;
}
template <int D>
constexpr Multivector<D> e0_times(const Multivector<D>& t) {
  Multivector<D> b{};
  for (int i = 0; i < D; ++i) b.c[(BladeMask{2} << i) | 1u] = t.c[BladeMask{2} << i];
  return b;
}
// Projection of the Euclidean vector x onto the plane of the Euclidean bivector F (F² = λ < 0):
// ⟨⟨x F⟩₁ F⟩₁ / λ.
template <int D>
Multivector<D> project_on_plane(const Multivector<D>& x, const Multivector<D>& f, double lambda) {
  return (1.0 / lambda) * grade(geometric(grade(geometric(x, f), 1), f), 1);
}

// Relative gap below which two rotation planes count as isoclinic (equal λ): there the split is
// not unique and the closed form F1 = (F W − λ1 F)/(λ2 − λ1) loses its digits.
inline constexpr double isoclinic_gap = 1e-6;

// Splits a Euclidean bivector of at most two planes, F = F1 + F2 with F_j² = λ_j: W = F ∧ F / 2
// = F1 F2, so λ1 + λ2 = ⟨F²⟩₀, λ1 λ2 = ⟨W²⟩₀ and F W = λ2 F1 + λ1 F2, whence
// F1 = (F W − λ1 F)/(λ2 − λ1) (the k = 2 case of the invariant decomposition). Returns the
// number of planes (0, 1 or 2), or −1 when two planes are (nearly) isoclinic.
template <int D>
int split_euclidean(const Multivector<D>& f, std::array<Multivector<D>, 2>& parts,
                    std::array<double, 2>& squares) {
  const Multivector<D> f2 = geometric(f, f);
  const Multivector<D> w = 0.5 * grade(f2, 4);
  const double sum = f2.c[0];                   // λ1 + λ2 ≤ 0
  const double product = geometric(w, w).c[0];  // λ1 λ2 ≥ 0
  if (sum == 0) return 0;
  if (std::abs(product) <= 1e-28 * sum * sum) {  // a single plane
    parts = {f, Multivector<D>{}};
    squares = {sum, 0.0};
    return 1;
  }
  const double disc = std::max(sum * sum - 4 * product, 0.0);
  const double l1 = 0.5 * (sum - std::sqrt(disc));  // the larger rotation, no cancellation
  const double l2 = product / l1;
  if (l2 - l1 <= isoclinic_gap * std::abs(l1)) return -1;
  parts[0] = (1.0 / (l2 - l1)) * (grade(geometric(f, w), 2) - l1 * f);
  parts[1] = f - parts[0];
  squares = {l1, l2};
  return 2;
}
}  // namespace detail

// The invariant decomposition of a bivector B of R(d,0,1), 4 ≤ d ≤ 5 (and d ≤ 3, where it is
// Chasles' screw): the Euclidean part B_E splits into ≤ 2 plane rotations F_Ej; the ideal part
// e0 t splits into the components t_j of t in those planes, which move the rotation centres
// (F_j = F_Ej + e0 t_j is still simple, F_j² = λ_j), and the rest t_⊥, the translation e0 t_⊥
// along the directions orthogonal to every plane; all parts commute. Throws std::domain_error
// when two planes are isoclinic (equal angles: the planes are not unique).
template <int D>
BivectorSplit<D> invariant_split(const Multivector<D>& b) {
  static_assert(D <= 5, "at most two rotation planes: d ≤ 5");
  BivectorSplit<D> s{};
  std::array<Multivector<D>, 2> fe{};
  const int planes = detail::split_euclidean(detail::euclidean_part(grade(b, 2)), fe, s.square);
  if (planes < 0)
    throw std::domain_error("pgad: isoclinic rotation planes have no unique invariant split");
  s.rotations = planes;
  Multivector<D> rest = detail::ideal_vector(b);
  for (int j = 0; j < planes; ++j) {
    const auto J = static_cast<std::size_t>(j);
    const Multivector<D> tj = detail::project_on_plane(detail::ideal_vector(b), fe[J], s.square[J]);
    s.rotation[J] = fe[J] + detail::e0_times(tj);
    rest = rest - tj;
  }
  s.translation = detail::e0_times(rest);
  return s;
}

// exp of an invariant split: (1 + T) Π_j (c_j + s_j/ψ_j F_j) with the simple closed form for each
// commuting factor (F_j² = λ_j = −ψ_j²).
template <int D>
Multivector<D> exp_of_split(const BivectorSplit<D>& s) {
  Multivector<D> r = scalar<D>(1) + s.translation;
  for (int j = 0; j < s.rotations; ++j) {
    const auto J = static_cast<std::size_t>(j);
    const clifford::SimpleExp e = clifford::simple_exp(s.square[J]);
    r = geometric(r, scalar<D>(e.c0) + e.cB * s.rotation[J]);
  }
  return r;
}

// exp by scaling and squaring: exp(B) = exp(B / 2^k)^(2^k) with |B / 2^k| ≤ ½, Taylor to 30
// terms. Any multivector; the reference the closed forms are tested against.
template <int D>
Multivector<D> exp_series(const Multivector<D>& b) {
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

// exp of a bivector B: closed form when B² is a scalar (rotation cos/sin, translation 1 + B), the
// screw form when d = 3 (B² = scalar + e0123 part), the invariant decomposition when d = 4, 5
// (commuting rotations and a translation); the series otherwise (isoclinic planes, d ≥ 6).
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
  if constexpr (D == 4 || D == 5) {
    if (detail::only_grades(b, 1u << 2)) {
      std::array<Multivector<D>, 2> fe{};
      std::array<double, 2> squares{};
      if (detail::split_euclidean(detail::euclidean_part(b), fe, squares) >= 0)
        return exp_of_split(invariant_split(b));
    }
  }
  return exp_series(b);
}

namespace detail {
// log of a normalised motor M of R(d,0,1), d = 4, 5, whose bivector is not simple, by the
// invariant decomposition. M = (1 + e0 w) Π_j (c_j + s_j (F̂_j + e0 u_j)) with unit rotations
// F̂_j (F̂_j² = −1) about orthogonal planes, u_j in plane j, w orthogonal to every plane.
//  1. The Euclidean part M_E = Π_j (c_j + s_j F̂_j) has ⟨M_E⟩₂ = s1 c2 F̂1 + c1 s2 F̂2, which splits
//     into its planes like any Euclidean bivector; ⟨M_E⟩₄ = s1 s2 F̂1 F̂2. With a0 = c1 c2,
//     a1 = s1 c2, a2 = c1 s2, a12 = s1 s2: θ1 + θ2 = atan2(a1 + a2, a0 − a12) and
//     θ1 − θ2 = atan2(a1 − a2, a0 + a12), robust whatever the angles (principal range
//     |θ1| + |θ2| ≤ π).
//  2. M M̃_E = 1 + e0 x with x = w + Σ_j s_j (c_j u_j − s_j u_j F̂_j) (e0² = 0), so the plane-j
//     part x_j of x gives u_j = (c_j x_j + s_j x_j F̂_j)/s_j and the rest is w.
// Then log M = Σ_j θ_j (F̂_j + e0 u_j) + e0 w.
template <int D>
Multivector<D> log_by_invariant_split(const Multivector<D>& m) {
  const Multivector<D> me = euclidean_part(m);
  const Multivector<D> h = grade(me, 4);
  std::array<Multivector<D>, 2> g{};
  std::array<double, 2> gl{};
  int planes = split_euclidean(grade(me, 2), g, gl);
  if (planes < 0)
    throw std::domain_error(
        "pgad::log: isoclinic rotation planes (equal angles) have no unique log");
  std::array<Multivector<D>, 2> unit{};
  std::array<double, 2> a{};
  for (int j = 0; j < planes; ++j) {
    const auto J = static_cast<std::size_t>(j);
    a[J] = std::sqrt(-gl[J]);
    unit[J] = (1.0 / a[J]) * g[J];
  }
  const double h_norm = norm(h);
  if (planes == 1 && h_norm > 1e-12) {
    // c = 0 in one plane hides the other from ⟨M_E⟩₂; it is F̂1⁻¹ ⟨M_E⟩₄ normalised.
    unit[1] = (1.0 / h_norm) * grade(geometric(-1.0 * unit[0], h), 2);
    planes = 2;
  } else if (planes == 0 && h_norm > 1e-12) {
    throw std::domain_error(
        "pgad::log: isoclinic rotation planes (equal angles) have no unique log");
  }
  std::array<double, 2> theta{};
  if (planes == 2) {
    const double a12 = geometric(h, reverse(geometric(unit[0], unit[1]))).c[0];
    const double sum = std::atan2(a[0] + a[1], me.c[0] - a12);
    const double diff = std::atan2(a[0] - a[1], me.c[0] + a12);
    theta = {0.5 * (sum + diff), 0.5 * (sum - diff)};
  } else if (planes == 1) {
    theta[0] = std::atan2(a[0], me.c[0]);
  }
  const Multivector<D> x = ideal_vector(geometric(m, reverse(me)));
  Multivector<D> w = x, out{};
  for (int j = 0; j < planes; ++j) {
    const auto J = static_cast<std::size_t>(j);
    const double c = std::cos(theta[J]), s = std::sin(theta[J]);
    const Multivector<D> xj = project_on_plane(x, unit[J], -1.0);
    const Multivector<D> turned = grade(geometric(xj, unit[J]), 1);
    // θ u_j = (θ/s)(c x_j + s x_j F̂_j); θ/s → 1 as θ → 0
    const double ratio = (s == 0) ? 1.0 : theta[J] / s;
    out = out + theta[J] * unit[J] + e0_times(ratio * (c * xj + s * turned));
    w = w - xj;
  }
  return out + e0_times(w);
}
}  // namespace detail

// log of a normalised motor: closed form when its bivector part squares to a scalar (any d), the
// screw form for d = 3, the invariant decomposition for d = 4, 5 (principal range: rotation
// angles |θ1| + |θ2| ≤ π). Throws std::domain_error otherwise: isoclinic rotations (equal angles
// in two planes: no unique log), d ≥ 6 with a non-simple bivector.
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
  if constexpr (D == 4 || D == 5) {
    if (detail::only_grades(m, 0b1010101u)) return detail::log_by_invariant_split(m);
  }
  throw std::domain_error("pgad::log: no closed form for this motor");
}

}  // namespace pgamesh::pgad
