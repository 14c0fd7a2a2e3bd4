// QCGA R(9,6) quadrics (docs/models-quadrics.md §4; Breuils eqs. 45–46, 60–62, 69–70, 74).
#include "pgamesh/models/qcga.hpp"

#include <cmath>

#include "pgamesh/algebra/clifford/products.hpp"
#include "quadric_blades.hpp"

namespace pgamesh::qcga {

namespace {
constexpr std::size_t kE = 0, kO = 3, kI = 9;  // offsets of e1.., eo1.., einf1..
}

const clifford::Algebra& algebra() {
  static const clifford::Algebra a = *clifford::make_algebra("qcga");
  return a;
}

double inner(const Vector& x, const Vector& y) {
  double s = x.v[0] * y.v[0] + x.v[1] * y.v[1] + x.v[2] * y.v[2];
  for (std::size_t k = 0; k < 6; ++k) s -= x.v[kO + k] * y.v[kI + k] + x.v[kI + k] * y.v[kO + k];
  return s;
}

Vector point(const Vec3d& p) {
  const double x = p[0], y = p[1], z = p[2];
  return Vector{
      {x, y, z, 1, 1, 1, 0, 0, 0, 0.5 * x * x, 0.5 * y * y, 0.5 * z * z, x * y, x * z, y * z}};
}

Vector dual_quadric(const Quadric& q) {
  const auto& k = q.k;
  const double j3 = -k[9] / 3;
  return Vector{{k[6], k[7], k[8], -2 * k[0], -2 * k[1], -2 * k[2], -k[3], -k[4], -k[5], j3, j3, j3,
                 0, 0, 0}};
}

Quadric coefficients(const Vector& s) {
  // Q^{x²} = ½ einf1, …, Q^{xy} = einf4, …, Q^x = e1, …, Q^1 = eo1 + eo2 + eo3 (eq. 60):
  // einf_k·eo_k = −1, so Q^{x²}·q* = −½ q*_eo1, Q^{xy}·q* = −q*_eo4, Q^1·q* = −Σ q*_einf1..3.
  const auto& v = s.v;
  return Quadric{{-0.5 * v[kO + 0], -0.5 * v[kO + 1], -0.5 * v[kO + 2], -v[kO + 3], -v[kO + 4],
                  -v[kO + 5], v[kE + 0], v[kE + 1], v[kE + 2],
                  -(v[kI + 0] + v[kI + 1] + v[kI + 2])}};
}

double value(const Vector& s, const Vec3d& p) {
  // inner(point(p), q*) written out: 12 products (the QCGA point test).
  const double x = p[0], y = p[1], z = p[2];
  const auto& v = s.v;
  return x * v[0] + y * v[1] + z * v[2] - (v[kI + 0] + v[kI + 1] + v[kI + 2]) -
         (0.5 * x * x * v[kO + 0] + 0.5 * y * y * v[kO + 1] + 0.5 * z * z * v[kO + 2] +
          x * y * v[kO + 3] + x * z * v[kO + 4] + y * z * v[kO + 5]);
}

Vec3d normal(const Vector& s, const Vec3d& p) {
  // eq. 45: n_1 = ((x·e1) einf1 + (x·e2) einf4 + (x·e3) einf5 + e1)·q*, and alike.
  const auto& v = s.v;
  const double x = p[0], y = p[1], z = p[2];
  return {-(x * v[kO + 0] + y * v[kO + 3] + z * v[kO + 4]) + v[0],
          -(y * v[kO + 1] + x * v[kO + 3] + z * v[kO + 5]) + v[1],
          -(z * v[kO + 2] + x * v[kO + 4] + y * v[kO + 5]) + v[2]};
}

Vector tangent_plane(const Vector& s, const Vec3d& p) {
  const Vec3d n = normal(s, p);
  const double d = (n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / 3;
  Vector out;
  out.v[0] = n[0];
  out.v[1] = n[1];
  out.v[2] = n[2];
  out.v[kI + 0] = out.v[kI + 1] = out.v[kI + 2] = d;
  return out;
}

Vec3d point_coordinates(const Vector& x) {
  const double w = -(x.v[kO + 0] + x.v[kO + 1] + x.v[kO + 2]) / 3;  // x·e∞
  if (!(w != 0) || !std::isfinite(w))
    throw ModelError("qcga::point_coordinates: x·e∞ is zero or not finite (not a finite point)");
  return {-x.v[0] / w, -x.v[1] / w, -x.v[2] / w};
}

quadric::LineIntersection intersect_line(const Vector& s, const Vec3d& o, const Vec3d& d) {
  return quadric::intersect_line(coefficients(s), o, d);
}

Vector quadric_from_points(std::span<const Vec3d, 9> pts) {
  return dual_quadric(quadric::through_nine_points(pts));
}

clifford::Multivector to_clifford(const Vector& x) {
  clifford::Multivector out;
  for (std::size_t k = 0; k < 15; ++k)
    if (x.v[k] != 0) out.terms.push_back({clifford::BladeMask{1} << k, x.v[k]});
  return out;
}

Vector from_clifford(const clifford::Multivector& x) {
  Vector out;
  for (const clifford::Term& t : x.terms) {
    if (clifford::grade_of(t.mask) != 1) {
      if (t.coeff == 0) continue;
      throw ModelError("qcga::from_clifford: the multivector has a part outside grade 1");
    }
    for (std::size_t k = 0; k < 15; ++k)
      if (t.mask == clifford::BladeMask{1} << k) out.v[k] = t.coeff;
  }
  return out;
}

clifford::Multivector quadric_from_points_ga(std::span<const Vec3d, 9> pts) {
  const clifford::Algebra& a = algebra();
  for (const Vec3d& p : pts)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw ModelError("qcga::quadric_from_points_ga: a point coordinate is NaN or infinite");
  clifford::Multivector x = to_clifford(point(pts[0]));
  for (std::size_t n = 1; n < 9; ++n) x = clifford::outer(a, x, to_clifford(point(pts[n])));
  auto eo = [](std::size_t k, double c) {
    return clifford::basis_blade(clifford::BladeMask{1} << (kO + k), c);
  };
  clifford::Multivector io = clifford::outer(a, eo(0, 1) - eo(1, 1), eo(1, 1) - eo(2, 1));
  for (std::size_t k = 3; k < 6; ++k) io = clifford::outer(a, io, eo(k, 1));
  x = clifford::outer(a, x, io);
  return clifford::grade(clifford::metric_dual(a, x), 1);
}

std::vector<std::pair<std::string, double>> nonzero_blades(const Vector& x) {
  return quadric::detail::named_terms(to_clifford(x), generator_names);
}

}  // namespace pgamesh::qcga
