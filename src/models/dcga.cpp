// DCGA R(8,2) quadrics and quartics on the general engine (docs/models-quadrics.md §3;
// Breuils eqs. 2–18, 50–56).
#include "pgamesh/models/dcga.hpp"

#include <cmath>

#include "pgamesh/algebra/clifford/products.hpp"
#include "quadric_blades.hpp"

namespace pgamesh::dcga {

namespace {

enum Gen { eo1, e1, e2, e3, ei1, eo2, e4, e5, e6, ei2 };

Multivector g(int k, double c = 1.0) {
  return clifford::basis_blade(clifford::BladeMask{1} << k, c);
}
Multivector wedge(int a, int b) {
  return clifford::outer(algebra(), g(a), g(b));
}

void check_axis(int i, const char* who) {
  if (i < 0 || i > 2) throw ModelError(std::string(who) + ": axis out of range 0..2");
}

const std::array<Multivector, 15>& extraction_table() {
  static const std::array<Multivector, 15> t = [] {
    std::array<Multivector, 15> o;
    o[0] = wedge(e4, e1);  // eq. 6
    o[1] = wedge(e5, e2);
    o[2] = wedge(e6, e3);
    o[3] = 0.5 * (wedge(e5, e1) + wedge(e4, e2));  // eq. 8
    o[4] = 0.5 * (wedge(e6, e1) + wedge(e4, e3));
    o[5] = 0.5 * (wedge(e5, e3) + wedge(e6, e2));
    o[6] = 0.5 * (wedge(e1, ei2) + wedge(ei1, e4));  // eq. 7
    o[7] = 0.5 * (wedge(e2, ei2) + wedge(ei1, e5));
    o[8] = 0.5 * (wedge(e3, ei2) + wedge(ei1, e6));
    o[9] = -wedge(ei1, ei2);                       // eq. 6
    o[10] = -(wedge(eo1, ei2) + wedge(ei1, eo2));  // from eq. 4's ½ r² (eo1∧einf2 + einf1∧eo2)
    o[11] = wedge(e1, eo2) + wedge(eo1, e4);       // from ½ x r² (e1∧einf2 + einf1∧e4)
    o[12] = wedge(e2, eo2) + wedge(eo1, e5);
    o[13] = wedge(e3, eo2) + wedge(eo1, e6);
    o[14] = -4.0 * wedge(eo1, eo2);  // from ¼ r⁴ einf1∧einf2
    return o;
  }();
  return t;
}

const std::array<Multivector, 10>& reciprocal_table() {
  static const std::array<Multivector, 10> t = [] {
    std::array<Multivector, 10> o;  // eqs. 50–51
    o[0] = wedge(e1, e4);
    o[1] = wedge(e2, e5);
    o[2] = wedge(e3, e6);
    o[3] = wedge(e1, e5) + wedge(e2, e4);
    o[4] = wedge(e1, e6) + wedge(e3, e4);
    o[5] = wedge(e3, e5) + wedge(e2, e6);
    o[6] = wedge(e1, eo2) + wedge(eo1, e4);
    o[7] = wedge(e2, eo2) + wedge(eo1, e5);
    o[8] = wedge(e3, eo2) + wedge(eo1, e6);
    o[9] = wedge(eo1, eo2);
    return o;
  }();
  return t;
}

}  // namespace

const clifford::Algebra& algebra() {
  static const clifford::Algebra a = *clifford::make_algebra("dcga");
  return a;
}

Multivector cga_point(const Vec3d& p, int copy) {
  if (copy != 1 && copy != 2) throw ModelError("dcga::cga_point: copy must be 1 or 2");
  const int o = copy == 1 ? eo1 : eo2, x = copy == 1 ? e1 : e4, inf = copy == 1 ? ei1 : ei2;
  const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  return g(o) + g(x, p[0]) + g(x + 1, p[1]) + g(x + 2, p[2]) + g(inf, 0.5 * r2);
}

Multivector point(const Vec3d& p) {
  return clifford::outer(algebra(), cga_point(p, 1), cga_point(p, 2));
}

Multivector extraction_operator(int m) {
  if (m < 0 || m > 14) throw ModelError("dcga::extraction_operator: monomial out of range 0..14");
  return extraction_table()[static_cast<std::size_t>(m)];
}

Multivector reciprocal_operator(int m) {
  if (m < 0 || m > 9) throw ModelError("dcga::reciprocal_operator: monomial out of range 0..9");
  return reciprocal_table()[static_cast<std::size_t>(m)];
}

Multivector differential_operator(int axis) {
  check_axis(axis, "dcga::differential_operator");
  return wedge(e1 + axis, ei1) + wedge(e4 + axis, ei2);
}

Multivector quadric(const Quadric& q) {
  Multivector out;
  for (std::size_t m = 0; m < 10; ++m)
    if (q.k[m] != 0) out = out + q.k[m] * extraction_table()[m];
  return out;
}

Quadric coefficients(const Multivector& q) {
  Quadric out;
  for (std::size_t m = 0; m < 10; ++m)
    out.k[m] = clifford::scalar_product(algebra(), reciprocal_table()[m], q);
  return out;
}

double value(const Multivector& q, const Vec3d& p) {
  return clifford::scalar_product(algebra(), q, point(p));
}

Vec3d gradient(const Multivector& q, const Vec3d& p) {
  const Multivector x = point(p);
  Vec3d n{};
  for (int k = 0; k < 3; ++k)
    n[static_cast<std::size_t>(k)] = clifford::scalar_product(
        algebra(), clifford::commutator(algebra(), differential_operator(k), q), x);
  return n;
}

Multivector tangent_plane(const Multivector& q, const Vec3d& p) {
  const Vec3d n = gradient(q, p);
  const Multivector n1 = g(e1, n[0]) + g(e2, n[1]) + g(e3, n[2]);
  const Multivector n2 = g(e4, n[0]) + g(e5, n[1]) + g(e6, n[2]);
  const double delta = clifford::scalar_product(algebra(), n1, cga_point(p, 1));  // eq. 18
  return clifford::outer(algebra(), n1 + g(ei1, delta), n2 + g(ei2, delta));
}

Vec3d point_coordinates(const Multivector& x) {
  const double w = clifford::scalar_product(algebra(), x, extraction_table()[9]);
  if (!(w != 0) || !std::isfinite(w))
    throw ModelError("dcga::point_coordinates: X·T_1 is zero or not finite (not a finite point)");
  const Multivector xn = x / w;
  return {clifford::scalar_product(algebra(), extraction_table()[6], xn),
          clifford::scalar_product(algebra(), extraction_table()[7], xn),
          clifford::scalar_product(algebra(), extraction_table()[8], xn)};
}

Multivector translator(const Vec3d& t) {
  const clifford::Algebra& a = algebra();
  const Multivector t1 = g(e1, t[0]) + g(e2, t[1]) + g(e3, t[2]);
  const Multivector t2 = g(e4, t[0]) + g(e5, t[1]) + g(e6, t[2]);
  const Multivector T1 = clifford::scalar(1) - 0.5 * clifford::geometric(a, t1, g(ei1));
  const Multivector T2 = clifford::scalar(1) - 0.5 * clifford::geometric(a, t2, g(ei2));
  return clifford::geometric(a, T1, T2);
}

Multivector rotor(int i, int j, double theta) {
  check_axis(i, "dcga::rotor");
  check_axis(j, "dcga::rotor");
  if (i == j) throw ModelError("dcga::rotor: needs two different axes");
  const clifford::Algebra& a = algebra();
  const double c = std::cos(theta / 2), s = std::sin(theta / 2);
  const Multivector R1 = clifford::scalar(c) - s * clifford::geometric(a, g(e1 + i), g(e1 + j));
  const Multivector R2 = clifford::scalar(c) - s * clifford::geometric(a, g(e4 + i), g(e4 + j));
  return clifford::geometric(a, R1, R2);
}

Multivector transform(const Multivector& v, const Multivector& q) {
  return clifford::pruned(clifford::sandwich(algebra(), v, q), 1e-15 * clifford::max_abs_coeff(q));
}

Quartic from_quadric(const Quadric& q) {
  Quartic s;
  for (std::size_t m = 0; m < 10; ++m) s.k[m] = q.k[m];
  return s;
}

double value(const Quartic& s, const Vec3d& p) {
  const double x = p[0], y = p[1], z = p[2], r2 = x * x + y * y + z * z;
  const std::array<double, 15> m = {x * x, y * y, z * z, x * y,  x * z,  y * z,  x,      y,
                                    z,     1.0,   r2,    x * r2, y * r2, z * r2, r2 * r2};
  double v = 0;
  for (std::size_t n = 0; n < 15; ++n) v += s.k[n] * m[n];
  return v;
}

Multivector quartic(const Quartic& s) {
  Multivector out;
  for (std::size_t m = 0; m < 15; ++m)
    if (s.k[m] != 0) out = out + s.k[m] * extraction_table()[m];
  return out;
}

Quartic torus(double big, double small) {
  if (!std::isfinite(big) || !std::isfinite(small))
    throw ModelError("dcga::torus: radii must be finite");
  const double u = big * big - small * small;
  Quartic s;
  s.k[14] = 1;              // r⁴
  s.k[10] = 2 * u;          // r²
  s.k[9] = u * u;           // 1
  s.k[0] = -4 * big * big;  // x²
  s.k[1] = -4 * big * big;  // y²
  return s;
}

Quartic dupin_cyclide(double a, double c, double mu) {
  if (!std::isfinite(a) || !std::isfinite(c) || !std::isfinite(mu) || !(a > 0) || std::abs(c) > a)
    throw ModelError("dcga::dupin_cyclide: needs finite a > 0 and |c| <= a");
  const double b2 = a * a - c * c, u = b2 - mu * mu;
  Quartic s;
  s.k[14] = 1;
  s.k[10] = 2 * u;
  s.k[9] = u * u - 4 * c * c * mu * mu;
  s.k[0] = -4 * a * a;
  s.k[6] = 8 * a * c * mu;
  s.k[1] = -4 * b2;
  return s;
}

std::vector<std::pair<std::string, double>> nonzero_blades(const Multivector& x) {
  return quadric::detail::named_terms(x, generator_names);
}

}  // namespace pgamesh::dcga
