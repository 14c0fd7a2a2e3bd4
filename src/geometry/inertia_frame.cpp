#include "pgamesh/geometry/inertia_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pgamesh {

namespace {

using Vector = pga3::Plane<double>;  // a vector a e1 + b e2 + c e3 (a plane through the origin)
using Rotor = pga3::Motor<double>;

// Products and sandwiches in the quaternion order, whose bits the mass properties keep from one
// version to the next (docs/pga3.md "Two summation orders").
Rotor product(const Rotor& a, const Rotor& b) {
  return pga3::quaternion_order::geometric_product(a, b);
}
Vector turn(const Rotor& r, const Vector& v) {
  return pga3::quaternion_order::apply(r, v);
}

Vector basis_vector(int i) {
  return pga3::plane(i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0, 0.0);
}

// e_i · v: the i-th coordinate of a vector.
double component(const Vector& v, int i) {
  return v.normal()[i];
}

// The axis whose rotor is exp(−½ φ e_pq) = rotor(φ, axis): e12 ↔ z, e13 = −e31 ↔ −y, e23 ↔ x
// (docs/conventions.md §7: R = cos(θ/2) − sin(θ/2)(a_x e23 + a_y e31 + a_z e12)).
Vec3d pivot_axis(int p, int q) {
  if (p == 0 && q == 1) return {0, 0, 1};
  if (p == 0 && q == 2) return {0, -1, 0};
  return {1, 0, 0};
}

// eq. 5.7 as corrected (docs/conventions.md §11): I′_i = Σ_j (e_j · (R̃_k e_i R_k)) R_k I_j R̃_k.
std::array<Vector, 3> turn_rows(const std::array<Vector, 3>& rows, const Rotor& rk) {
  std::array<Vector, 3> turned, out{};
  for (int j = 0; j < 3; ++j) turned[j] = turn(rk, rows[j]);
  const Rotor rk_rev = pga3::reverse(rk);
  for (int i = 0; i < 3; ++i) {
    const Vector back = turn(rk_rev, basis_vector(i));
    for (int j = 0; j < 3; ++j) {
      const double w = component(back, j);
      out[i].e1 += w * turned[j].e1;
      out[i].e2 += w * turned[j].e2;
      out[i].e3 += w * turned[j].e3;
    }
  }
  return out;
}

bool converged(const std::array<Vector, 3>& rows) {
  for (int p = 0; p < 3; ++p)
    for (int q = p + 1; q < 3; ++q) {
      const double apq = std::abs(component(rows[p], q));
      const double scale = std::sqrt(std::abs(component(rows[p], p) * component(rows[q], q)));
      if (apq > std::numeric_limits<double>::epsilon() / 4 * scale &&
          apq > std::numeric_limits<double>::min())
        return false;
    }
  return true;
}

}  // namespace

JacobiResult rotor_jacobi(const Mat3& m) {
  std::array<Vector, 3> rows;
  for (int j = 0; j < 3; ++j) rows[j] = pga3::plane(m[j][0], m[j][1], m[j][2], 0.0);
  JacobiResult r;
  constexpr int max_sweeps = 32;
  while (r.sweeps < max_sweeps && !converged(rows)) {
    ++r.sweeps;
    for (const auto& [p, q] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
      const double apq = component(rows[p], q);
      if (apq == 0) continue;
      // eqs. 5.8, 5.9 with sgn(0) := +1 (docs/conventions.md §11); t = tan φ is the smaller root,
      // |φ| ≤ π/4.
      const double tau = (component(rows[q], q) - component(rows[p], p)) / (2 * apq);
      const double t = (tau >= 0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1 + tau * tau));
      const Rotor rk = pga3::rotor(std::atan(t), pivot_axis(p, q));
      rows = turn_rows(rows, rk);
      r.rotor = product(rk, r.rotor);  // R ← R_k R
      ++r.rotations;
    }
  }
  r.rotor = pga3::normalized(r.rotor);
  for (int i = 0; i < 3; ++i) r.diagonal[i] = component(rows[i], i);
  return r;
}

namespace {

// u_i = R̃ e_i R (docs/conventions.md §11).
Vec3d eigenvector(const Rotor& r, int i) {
  return turn(pga3::reverse(r), basis_vector(i)).normal();
}

// The index of the largest-|·| component, the first one when several are equal to rounding.
int dominant_component(Vec3d u) {
  const double m = std::max({std::abs(u.x), std::abs(u.y), std::abs(u.z)});
  for (int i = 0; i < 3; ++i)
    if (std::abs(u[i]) >= m * (1 - 1e-12)) return i;
  return 0;
}

Vec3d unit(int i) {
  return basis_vector(i).normal();
}

}  // namespace

PrincipalFrame principal_frame(const Mat3& tensor, double degeneracy_tolerance) {
  const JacobiResult j = rotor_jacobi(tensor);
  std::array<double, 3> d = j.diagonal;
  Rotor r = j.rotor;
  // Sort ascending by quarter turns in the (p, q) plane: S̃ e_p S = ±e_q and S̃ e_q S = ∓e_p, so the
  // eigenvectors R̃ S̃ e_i S R of the composed rotor S R swap places (up to sign) with their
  // moments, and the frame stays right-handed.
  for (const auto& [p, q] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{0, 1}}) {
    if (d[q] < d[p]) {
      const int axis = 3 - p - q;
      r = product(pga3::rotor(std::numbers::pi / 2, unit(axis)), r);
      std::swap(d[p], d[q]);
    }
  }
  // Sign rule: axes 0 and 1 point along their dominant component. A half turn about frame axis k
  // flips the two other axes.
  const bool flip0 = eigenvector(r, 0)[dominant_component(eigenvector(r, 0))] < 0;
  const bool flip1 = eigenvector(r, 1)[dominant_component(eigenvector(r, 1))] < 0;
  if (flip0 || flip1) {
    const int k = flip0 && flip1 ? 2 : (flip0 ? 1 : 0);
    r = product(pga3::rotor(std::numbers::pi, unit(k)), r);
  }
  PrincipalFrame f;
  f.moments = d;
  f.rotor = pga3::normalized(pga3::reverse(r));  // rotor e_i rotor~ = R̃ e_i R = u_i
  if (f.rotor.s < 0) f.rotor = -1.0 * f.rotor;
  for (int i = 0; i < 3; ++i) f.axes[i] = turn(f.rotor, basis_vector(i)).normal();
  const double scale = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  f.degenerate =
      d[1] - d[0] <= degeneracy_tolerance * scale || d[2] - d[1] <= degeneracy_tolerance * scale;
  f.sweeps = j.sweeps;
  f.rotations = j.rotations;
  return f;
}

}  // namespace pgamesh
