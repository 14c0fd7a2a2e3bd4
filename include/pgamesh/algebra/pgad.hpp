// PGA R(d,0,1) for a compile-time dimension d (1 ≤ d ≤ 7): dense multivectors of 2^(d+1)
// coefficients indexed by blade bitmask (bit 0 = e0, bit i = e_i), products from tables built at
// compile time. Conventions follow docs/conventions.md §1–§7 in any d: e0² = 0, e_i² = 1; the Hodge
// dual e_J e_J* = I = e0 e1 … ed; the join A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2); the point x ↦
// (e0 + Σ x_i e_i)*, so o ∨ v1 ∨ … ∨ vd = det[v1 … vd] and S ∨ o = (−1)^d o ∨ S. For d = 3 the
// coefficients agree with pga3 (named blades there: e032 = −e023, …).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/blade.hpp"
#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/divided_differences.hpp"
#include "pgamesh/algebra/clifford/real_roots.hpp"

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
// Symmetric inner product Σ ⟨A_r B_s⟩_|r−s| (docs/conventions.md §4 `|`).
template <int D>
constexpr Multivector<D> inner(const Multivector<D>& a, const Multivector<D>& b) {
  return detail::product(a, b,
                         [](BladeMask i, BladeMask j) { return (i & ~j) == 0 || (j & ~i) == 0; });
}

// Hodge dual, e_J e_J* = I (docs/conventions.md §3).
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

// The point x = (e0 + Σ x_i e_i)* (docs/conventions.md §2; for d = 3:
// e123 + x e032 + y e013 + z e021).
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

// ---- norms and the Euclidean split (docs/conventions.md §6, paper eq. 3.1) ----------------------

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
// 2021): a bivector of R(d,0,1), d ≤ 7, is a sum of commuting simple bivectors — at most three
// rotations F_j (F_j² = λ_j = −μ_j < 0, about orthogonal Euclidean planes) and one translation T
// (T² = 0) — so exp and log have closed forms.

// The commuting simple parts of a bivector: B = Σ_j rotation[j] + translation.
template <int D>
struct BivectorSplit {
  std::array<Multivector<D>, 3> rotation{};
  std::array<double, 3> square{};  // λ_j = rotation[j]²
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

// Relative gap below which invariant_split calls two rotation planes isoclinic (equal angles):
// there the planes are not unique and the Lagrange projectors onto them lose their digits.
inline constexpr double isoclinic_gap = 1e-6;

// Elementary symmetric functions of the squared rotation angles μ_j = −λ_j of a bivector B with
// B² = b2. With W = B ∧ B / 2 = Σ_(i<j) F_i F_j and T = B ∧ B ∧ B / 6 = B ∧ W / 3 = F1 F2 F3
// (blades with e0 square to 0, so only the Euclidean parts reach a scalar part):
// Σ μ_j = −⟨B²⟩₀, Σ_(i<j) μ_i μ_j = ⟨W²⟩₀ ((F_i F_j)² = λ_i λ_j) and μ1 μ2 μ3 = −⟨T²⟩₀
// ((F1 F2 F3)² = λ1 λ2 λ3) — the coefficients of the invariant decomposition's characteristic
// polynomial μ³ − e1 μ² + e2 μ − e3 (e3 = 0 for d ≤ 5: at most two planes).
struct PlaneInvariants {
  double e1, e2, e3;
};
template <int D>
PlaneInvariants plane_invariants(const Multivector<D>& b, const Multivector<D>& b2) {
  const Multivector<D> w = 0.5 * grade(b2, 4);
  PlaneInvariants p{-b2.c[0], geometric(w, w).c[0], 0.0};
  if constexpr (D >= 6) {
    const Multivector<D> t = (1.0 / 3) * outer(b, w);
    p.e3 = -geometric(t, t).c[0];
  }
  return p;
}

// The squared angles μ1 ≥ μ2 ≥ μ3 ≥ 0, roots of μ³ − e1 μ² + e2 μ − e3 (all real, in [0, e1]):
// the quadratic formula without cancellation when e3 = 0, else Viète's
// (clifford::cubic_real_roots).
inline std::array<double, 3> squared_angles(const PlaneInvariants& p) {
  std::array<double, 3> mu{};
  if (p.e1 <= 0) return mu;
  if (p.e3 == 0) {
    mu[0] = 0.5 * (p.e1 + std::sqrt(std::max(p.e1 * p.e1 - 4 * p.e2, 0.0)));
    mu[1] = std::max(p.e2, 0.0) / mu[0];
    return mu;
  }
  const std::array<double, 3> r = clifford::cubic_real_roots(p.e1, p.e2, p.e3);
  for (std::size_t i = 0; i < 3; ++i) mu[i] = std::max(r[2 - i], 0.0);
  return mu;
}

// Functions of Y = −B² (and of the even part E of a motor, itself cos√Y) live in grades 0, 4, 8:
// the blade pairs of two such elements that land there. A product of two of them also has
// grade-2 and grade-6 terms, but for commuting factors (polynomials in one Y) they cancel —
// e_A e_B = −e_B e_A for grade-4 blades sharing 3 or 1 generators — so leaving them out is exact
// and skips most of the dense product.
struct BladePair {
  BladeMask a, b;
  signed char sign;
};
template <int D>
constexpr bool is_commuting_pair(BladeMask a, BladeMask b) {
  auto in_grades_0_4_8 = [](BladeMask m) {
    const int g = clifford::grade_of(m);
    return g == 0 || g == 4 || g == 8;
  };
  return in_grades_0_4_8(a) && in_grades_0_4_8(b) && in_grades_0_4_8(a ^ b) &&
         product_table<D>.gp[a][b] != 0;
}
template <int D>
constexpr std::size_t commuting_pair_count() {
  std::size_t n = 0;
  for (BladeMask a = 0; a < Multivector<D>::size; ++a)
    for (BladeMask b = 0; b < Multivector<D>::size; ++b) n += is_commuting_pair<D>(a, b);
  return n;
}
template <int D>
constexpr auto make_commuting_pairs() {
  std::array<BladePair, commuting_pair_count<D>()> pairs{};
  std::size_t n = 0;
  for (BladeMask a = 0; a < Multivector<D>::size; ++a)
    for (BladeMask b = 0; b < Multivector<D>::size; ++b)
      if (is_commuting_pair<D>(a, b)) pairs[n++] = {a, b, product_table<D>.gp[a][b]};
  return pairs;
}
template <int D>
inline constexpr auto commuting_pairs = make_commuting_pairs<D>();

// A B for commuting A, B of grades 0, 4, 8 (functions of one Y), over commuting_pairs only.
template <int D>
Multivector<D> commuting_product(const Multivector<D>& a, const Multivector<D>& b) {
  Multivector<D> r{};
  for (const BladePair& p : commuting_pairs<D>) r.c[p.a ^ p.b] += p.sign * a.c[p.a] * b.c[p.b];
  return r;
}

// The Newton forms Σ_n coefficients[q][n] Π_(i<n) (Y − nodes[i]) of K functions of Y
// (clifford::divided_differences_of), Y of grades 0, 4, 8: the basis products Π_(i<n) (Y − x_i)
// are formed once and shared.
template <int D, std::size_t K>
std::array<Multivector<D>, K> newton_forms(const Multivector<D>& y,
                                           const std::vector<double>& nodes,
                                           const std::array<std::vector<double>, K>& coefficients) {
  std::array<Multivector<D>, K> r{};
  Multivector<D> basis = scalar<D>(1);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    if (n > 0) basis = commuting_product(basis, y - scalar<D>(nodes[n - 1]));
    for (std::size_t q = 0; q < K; ++q) r[q] += coefficients[q][n] * basis;
  }
  return r;
}

// Each value twice, ascending: Hermite nodes, so that nilpotent parts of the element (a
// translation commuting with the rotations) get the first derivative of the function.
inline std::vector<double> doubled_nodes(std::vector<double> values) {
  const std::size_t n = values.size();
  for (std::size_t i = 0; i < n; ++i) values.push_back(values[i]);
  std::sort(values.begin(), values.end());
  return values;
}

// exp of a bivector B of R(d,0,1), 4 ≤ d ≤ 7, without choosing planes. The power series splits
// into even and odd terms: exp(B) = cos√Y + (sin√Y / √Y) B with Y = −B² (an element of grades 0,
// 4 that commutes with B). With the invariant decomposition B = Σ ψ_j Ĵ_j + T (Ĵ_j² = −1), the
// idempotents P_ε = Π_(j≥2) (1 − ε_j Ĵ_1 Ĵ_j)/2 give B P_ε = ω_ε Ĵ_1 P_ε, ω_ε = ψ1 ± ψ2 ± ψ3, so
// Y = Σ_ε ω_ε² P_ε + N with N nilpotent (N = −2 T Σ ψ_j Ĵ_j, N² = 0). A function of Y is then its
// Hermite interpolation at the nodes ω_ε² (each double), in Newton form: exact whatever the
// angles — isoclinic planes (equal ψ: coinciding nodes), nearly isoclinic ones (clustered nodes,
// clifford::divided_differences stays accurate), zero planes — and continuous across all of them.
// Isoclinic example: exp(ψ (Ĵ1 + Ĵ2)) = cos²ψ + (cos ψ sin ψ / ψ) B + (sin²ψ / ψ²) W.
template <int D>
Multivector<D> exp_by_angle_sums(const Multivector<D>& b, const Multivector<D>& b2) {
  const PlaneInvariants p = plane_invariants(b, b2);
  std::vector<double> y;
  if constexpr (D <= 5) {
    // (ψ1 ± ψ2)² = μ1 + μ2 ± 2 √(μ1 μ2) straight from the invariants
    const double root = std::sqrt(std::max(p.e2, 0.0));
    y = {std::max(p.e1 - 2 * root, 0.0), p.e1 + 2 * root};
  } else {
    const std::array<double, 3> mu = squared_angles(p);
    const double psi[3] = {std::sqrt(mu[0]), std::sqrt(mu[1]), std::sqrt(mu[2])};
    for (double s2 : {1.0, -1.0})
      for (double s3 : {1.0, -1.0}) {
        const double omega = psi[0] + s2 * psi[1] + s3 * psi[2];
        y.push_back(omega * omega);
      }
  }
  const std::vector<double> nodes = doubled_nodes(y);
  auto width = [](double c) { return 0.5 * std::max(1.0, std::sqrt(std::abs(c))); };
  // cos√y and sin√y/√y in one table: one Taylor computation serves both
  const std::array<std::vector<double>, 2> dd = clifford::divided_differences_of<2>(
      nodes, std::vector<int>(nodes.size(), 0),
      [](double x, int) {
        const clifford::CosSincSqrt v = clifford::cos_sinc_sqrt(x);
        return std::array<double, 2>{v.cos_sqrt, v.sinc_sqrt};
      },
      [](double c, int n, int) {
        clifford::CosSincTaylor t = clifford::cos_sinc_sqrt_taylor(c, n);
        return std::array<std::vector<double>, 2>{std::move(t.cos_sqrt), std::move(t.sinc_sqrt)};
      },
      [&width](double c, int) { return width(c); });
  const std::array<Multivector<D>, 2> f =
      newton_forms(-1.0 * (grade(b2, 0) + grade(b2, 4)), nodes, dd);
  return f[0] + geometric(f[1], b);
}

// log of a normalised motor M of R(d,0,1), 4 ≤ d ≤ 7, without choosing planes: the inverse of
// exp_by_angle_sums. M = E + O with E = ⟨M⟩₀ + ⟨M⟩₄ + ⟨M⟩₈ = cos√Y and O = ⟨M⟩₂ + ⟨M⟩₆
// = (sin√Y / √Y) B, so B = h(E) O with h(cos θ) = θ / sin θ (analytic for cos θ > −1, = 1 at
// θ = 0). E = Σ_ε cos ω_ε P_ε + nilpotent, and ⟨P_ε⟩₀ = 2^(1−k) (k = 2 planes for d ≤ 5, 3
// above; ideal and grade-4 parts have no scalar part), so the moments ⟨E^n⟩₀ are the mean powers
// of the nodes cos ω_ε: d ≤ 5, cos ω_± = ⟨E⟩₀ ± √(⟨E²⟩₀ − ⟨E⟩₀²); d ≥ 6, the four roots of the
// quartic whose power sums are 4 ⟨E^n⟩₀ (Newton's identities).
// h takes each ω_ε in [0, π]. For d ≤ 5 any such pair ω_± = ψ1 ± ψ2 is consistent: every motor
// has a log with |ψ1| + |ψ2| ≤ π. For d ≥ 6 four values ω_ε = ψ1 ± ψ2 ± ψ3 must satisfy
// ω_++ + ω_−− = ω_+− + ω_−+; when |ψ1| + |ψ2| + |ψ3| > π the principal values may not, which
// shows as a grade-6 part of h(E) O. Then some nodes take the next branch (θ − 2π)/sin θ: the
// assignments are tried with the fewest shifted nodes first, and the first whose result is a
// bivector is the log. Throws std::domain_error if none is (an angle of exactly π between
// coinciding nodes).
template <int D>
Multivector<D> log_by_angle_sums(const Multivector<D>& m) {
  const Multivector<D> e = grade(m, 0) + grade(m, 4) + grade(m, 8);
  const Multivector<D> o = grade(m, 2) + grade(m, 6);
  std::vector<double> c;
  if constexpr (D <= 5) {
    const double m1 = e.c[0], m2 = geometric(e, e).c[0];
    const double kappa = std::sqrt(std::max(m2 - m1 * m1, 0.0));
    c = {m1 - kappa, m1 + kappa};
  } else {
    double p[5] = {4, 0, 0, 0, 0};  // power sums Σ_ε cos^n ω_ε
    Multivector<D> power = scalar<D>(1);
    for (int n = 1; n <= 4; ++n) {
      power = commuting_product(power, e);
      p[n] = 4 * power.c[0];
    }
    // Newton's identities: elementary symmetric functions of the four nodes
    const double s1 = p[1], s2 = (s1 * p[1] - p[2]) / 2, s3 = (s2 * p[1] - s1 * p[2] + p[3]) / 3,
                 s4 = (s3 * p[1] - s2 * p[2] + s1 * p[3] - p[4]) / 4;
    c = clifford::real_roots({s4, -s3, s2, -s1, 1.0}, -1 - 1e-9, 1 + 1e-9);
  }
  const std::vector<double> nodes = doubled_nodes(c);
  // h is singular at c = −1 (θ = π), the shifted branch at c = 1: a run's spread stays well
  // inside the Taylor radius
  auto value = [](double x, int shifted) {
    return shifted ? clifford::shifted_angle_over_sine_of_cosine(x)
                   : clifford::angle_over_sine_of_cosine(x);
  };
  auto taylor = [](double x, int count, int shifted) {
    return shifted ? clifford::shifted_angle_over_sine_taylor(x, count)
                   : clifford::angle_over_sine_taylor(x, count);
  };
  auto width = [](double x, int shifted) {
    return std::min(0.2, 0.25 * (shifted ? 1 - x : 1 + x));
  };
  const unsigned assignments = 1u << c.size();
  for (int shifted_count = 0; shifted_count <= static_cast<int>(c.size()); ++shifted_count) {
    for (unsigned shift = 0; shift < assignments; ++shift) {
      if (clifford::grade_of(shift) != shifted_count) continue;
      std::vector<int> branch(nodes.size());
      for (std::size_t i = 0; i < nodes.size(); ++i)
        for (std::size_t j = 0; j < c.size(); ++j)
          if (nodes[i] == c[j]) branch[i] = static_cast<int>(shift >> j & 1u);
      const std::vector<double> dd =
          clifford::divided_differences(nodes, branch, value, taylor, width);
      const Multivector<D> full = geometric(newton_forms<D, 1>(e, nodes, {dd})[0], o);
      const Multivector<D> b = grade(full, 2);
      if constexpr (D <= 5) return b;
      if (norm(grade(full, 6)) + ideal_norm(grade(full, 6)) <= 1e-9 * (1 + norm(b) + ideal_norm(b)))
        return b;
    }
  }
  throw std::domain_error(
      "pgad::log: no bivector log found (a rotation angle of π shared by coinciding nodes)");
}
}  // namespace detail

// The invariant decomposition of a bivector B of R(d,0,1), d ≤ 7: the Euclidean part B_E splits
// into ≤ 3 plane rotations F_Ej, the ideal part e0 t into the components t_j of t in those planes,
// which move the rotation centres (F_j = F_Ej + e0 t_j is still simple, F_j² = λ_j), and the rest
// t_⊥, the translation e0 t_⊥ along the directions orthogonal to every plane; all parts commute.
// The plane of F_j is the eigenspace of S x = −⟨⟨x B_E⟩₁ B_E⟩₁ for μ_j = −λ_j (μ_j are the roots
// of plane_invariants' cubic), projected onto by the Lagrange polynomial
// P_j = Π_(i≠j) (S − μ_i)/(μ_j − μ_i) (with μ = 0 among the others when the planes do not fill
// R^d), and F_Ej = ½ Σ_a e_a ∧ P_j ⟨e_a B_E⟩₁ (a bivector from its skew map). Throws
// std::domain_error when two planes are isoclinic (equal angles: the planes are not unique; exp
// and log do not need them).
template <int D>
BivectorSplit<D> invariant_split(const Multivector<D>& b) {
  BivectorSplit<D> s{};
  const Multivector<D> bivector = grade(b, 2);
  const Multivector<D> f = detail::euclidean_part(bivector);
  const std::array<double, 3> mu =
      detail::squared_angles(detail::plane_invariants(f, geometric(f, f)));
  int planes = 0;
  for (double x : mu)
    if (x > 1e-14 * mu[0]) ++planes;
  for (int i = 0; i < planes; ++i)
    for (int j = i + 1; j < planes; ++j)
      if (mu[static_cast<std::size_t>(i)] - mu[static_cast<std::size_t>(j)] <=
          detail::isoclinic_gap * mu[0])
        throw std::domain_error("pgad: isoclinic rotation planes have no unique invariant split");
  s.rotations = planes;
  const bool kernel = D > 2 * planes;
  auto skew = [&f](const Multivector<D>& x) { return grade(geometric(x, f), 1); };
  auto project = [&](Multivector<D> x, int j) {
    const double mj = mu[static_cast<std::size_t>(j)];
    for (int i = 0; i < planes; ++i) {
      const double mi = mu[static_cast<std::size_t>(i)];
      if (i != j) x = (1.0 / (mj - mi)) * (-1.0 * skew(skew(x)) - mi * x);
    }
    if (kernel) x = (-1.0 / mj) * skew(skew(x));
    return x;
  };
  const Multivector<D> t = detail::ideal_vector(bivector);
  Multivector<D> rest = t;
  for (int j = 0; j < planes; ++j) {
    Multivector<D> fj{};
    for (int a = 0; a < D; ++a) {
      const Multivector<D> ea = blade<D>(BladeMask{2} << a);
      fj += 0.5 * outer(ea, project(skew(ea), j));
    }
    const Multivector<D> tj = project(t, j);
    const auto J = static_cast<std::size_t>(j);
    s.rotation[J] = fj + detail::e0_times(tj);
    s.square[J] = -mu[J];
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
// screw form when d = 3 (B² = scalar + e0123 part), and for 4 ≤ d ≤ 7 the closed form in the
// angle sums (detail::exp_by_angle_sums: any number of rotation planes up to three, isoclinic or
// not, and a translation); the series for arguments that are not bivectors.
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
  if constexpr (D >= 4) {
    if (detail::only_grades(b, 1u << 2)) return detail::exp_by_angle_sums(b, b2);
  }
  return exp_series(b);
}

// log of a normalised motor (M M̃ = 1, even grades): closed form when its bivector part squares
// to a scalar (any d), the screw form for d = 3, and for 4 ≤ d ≤ 7 the closed form in the angle
// sums (detail::log_by_angle_sums; isoclinic planes included). Principal range: rotation angles
// |ψ1| + |ψ2| + |ψ3| < π. Throws std::domain_error when M is not a normalised motor.
template <int D>
Multivector<D> log(const Multivector<D>& m) {
  double scale = 0;
  for (double x : m.c) scale = std::max(scale, std::abs(x));
  const Multivector<D> unit = geometric(m, reverse(m)) - scalar<D>(1);
  double off = 0;
  for (BladeMask i = 0; i < m.size; ++i) {
    off = std::max(off, std::abs(unit.c[i]));
    if (clifford::grade_of(i) % 2) off = std::max(off, std::abs(m.c[i]) / std::max(scale, 1.0));
  }
  if (!(off <= 1e-8))
    throw std::domain_error(
        "pgad::log: the argument is not a normalised motor (odd grades, or M M̃ ≠ 1 by " +
        std::to_string(off) + ")");
  const Multivector<D> b = grade(m, 2);
  const Multivector<D> b2 = geometric(b, b);
  if (detail::only_grades(m, 1u | 4u) && detail::only_grades(b2, 1u))
    return clifford::simple_log(m.c[0], b2.c[0]) * b;
  if constexpr (D == 3) {
    const clifford::StudyLog l =
        clifford::study_log(m.c[0], norm(b), m.c[Multivector<D>::pseudoscalar]);
    return l.cL * b + l.cIL * geometric(blade<D>(Multivector<D>::pseudoscalar), b);
  }
  if constexpr (D >= 4) return detail::log_by_angle_sums(m);
  throw std::domain_error("pgad::log: no closed form for this motor");
}

}  // namespace pgamesh::pgad
