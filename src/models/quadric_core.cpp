// Values, gradients, tangent planes, line intersections and direct transforms of quadrics
// (docs/models-quadrics.md §1–§5).
#include <algorithm>
#include <cmath>
#include <string>

#include "pgamesh/models/quadric.hpp"

namespace pgamesh::quadric {

namespace {

bool finite3(const Vec3d& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

}  // namespace

std::array<double, 10> monomials(const Vec3d& p) {
  const double x = p[0], y = p[1], z = p[2];
  return {x * x, y * y, z * z, x * y, x * z, y * z, x, y, z, 1.0};
}

double value(const Quadric& q, const Vec3d& p) {
  const double x = p[0], y = p[1], z = p[2];
  const auto& k = q.k;
  // Horner-like grouping: x(a x + d y + e z + g) + y(b y + f z + h) + z(c z + i) + j.
  return x * (k[0] * x + k[3] * y + k[4] * z + k[6]) + y * (k[1] * y + k[5] * z + k[7]) +
         z * (k[2] * z + k[8]) + k[9];
}

Vec3d gradient(const Quadric& q, const Vec3d& p) {
  const double x = p[0], y = p[1], z = p[2];
  const auto& k = q.k;
  return {2 * k[0] * x + k[3] * y + k[4] * z + k[6], 2 * k[1] * y + k[3] * x + k[5] * z + k[7],
          2 * k[2] * z + k[4] * x + k[5] * y + k[8]};
}

Vec3d unit_normal(const Quadric& q, const Vec3d& p) {
  const Vec3d n = gradient(q, p);
  const double len = std::hypot(n[0], n[1], n[2]);
  if (!(len > 0) || !std::isfinite(len))
    throw ModelError("quadric::unit_normal: the gradient is zero or not finite at this point");
  return {n[0] / len, n[1] / len, n[2] / len};
}

std::array<double, 4> tangent_plane(const Quadric& q, const Vec3d& p) {
  const Vec3d n = gradient(q, p);
  return {n[0], n[1], n[2], -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2])};
}

Mat3 matrix3(const Quadric& q) {
  const auto& k = q.k;
  return {{{k[0], k[3] / 2, k[4] / 2}, {k[3] / 2, k[1], k[5] / 2}, {k[4] / 2, k[5] / 2, k[2]}}};
}

Mat4 matrix4(const Quadric& q) {
  const auto& k = q.k;
  return {{{k[0], k[3] / 2, k[4] / 2, k[6] / 2},
           {k[3] / 2, k[1], k[5] / 2, k[7] / 2},
           {k[4] / 2, k[5] / 2, k[2], k[8] / 2},
           {k[6] / 2, k[7] / 2, k[8] / 2, k[9]}}};
}

Quadric from_matrix4(const Mat4& m) {
  auto s = [&](int r, int c) { return m[r][c] + m[c][r]; };
  return Quadric{
      {m[0][0], m[1][1], m[2][2], s(0, 1), s(0, 2), s(1, 2), s(0, 3), s(1, 3), s(2, 3), m[3][3]}};
}

Quadric normalized(const Quadric& q) {
  double norm2 = 0, mx = 0;
  for (double c : q.k) {
    norm2 += c * c;
    mx = std::max(mx, std::abs(c));
  }
  if (mx == 0) return q;
  double s = std::sqrt(norm2);
  for (double c : q.k)
    if (std::abs(c) >= 1e-3 * mx) {
      if (c < 0) s = -s;
      break;
    }
  Quadric out;
  for (std::size_t n = 0; n < 10; ++n) out.k[n] = q.k[n] / s;
  return out;
}

void check_finite(const Quadric& q) {
  for (double c : q.k)
    if (!std::isfinite(c)) throw ModelError("quadric: a coefficient is NaN or infinite");
}

Quadric ellipsoid(const Vec3d& c, const Vec3d& r) {
  Quadric q;
  q.k[9] = -1;
  for (int n = 0; n < 3; ++n) {
    if (!(r[n] != 0) || !std::isfinite(r[n]) || !std::isfinite(c[n]))
      throw ModelError("quadric::ellipsoid: semi-axes must be finite and non-zero");
    const double w = 1 / (r[n] * r[n]);
    q.k[n] = w;
    q.k[6 + n] = -2 * w * c[n];
    q.k[9] += w * c[n] * c[n];
  }
  return q;
}

Quadric sphere(const Vec3d& c, double radius) {
  return ellipsoid(c, {radius, radius, radius});
}

std::string_view to_string(LineKind kind) {
  switch (kind) {
    case LineKind::two:
      return "two";
    case LineKind::tangent:
      return "tangent";
    case LineKind::one:
      return "one";
    case LineKind::none:
      return "none";
    case LineKind::contained:
      return "contained";
  }
  return "none";
}

LineIntersection intersect_line(const Quadric& q, const Vec3d& o, const Vec3d& d, double tol) {
  if (!finite3(o) || !finite3(d))
    throw ModelError("quadric::intersect_line: origin or direction is not finite");
  if (d[0] == 0 && d[1] == 0 && d[2] == 0)
    throw ModelError("quadric::intersect_line: the direction is zero");
  const auto& k = q.k;
  const double qa = k[0] * d[0] * d[0] + k[1] * d[1] * d[1] + k[2] * d[2] * d[2] +
                    k[3] * d[0] * d[1] + k[4] * d[0] * d[2] + k[5] * d[1] * d[2];
  const Vec3d g = gradient(q, o);
  const double qb = g[0] * d[0] + g[1] * d[1] + g[2] * d[2];
  const double qc = value(q, o);
  LineIntersection out;
  out.quadratic = {qa, qb, qc};
  auto put = [&](double t) {
    out.t[static_cast<std::size_t>(out.count)] = t;
    out.points[static_cast<std::size_t>(out.count)] = {o[0] + t * d[0], o[1] + t * d[1],
                                                       o[2] + t * d[2]};
    ++out.count;
  };
  // Scale of A relative to the line: A is zero when it is within tol of |B|, |C|-sized terms.
  const double scale = std::abs(qa) + std::abs(qb) + std::abs(qc);
  const bool a_zero = qa == 0 || std::abs(qa) <= tol * scale;
  if (a_zero) {
    const bool b_zero = qb == 0 || std::abs(qb) <= tol * scale;
    const bool c_zero = qc == 0 || std::abs(qc) <= tol * scale;
    if (b_zero) {
      out.kind = c_zero ? LineKind::contained : LineKind::none;
      return out;
    }
    out.kind = LineKind::one;
    put(-qc / qb);
    return out;
  }
  const double disc = qb * qb - 4 * qa * qc;
  const double disc_scale = qb * qb + 4 * std::abs(qa * qc);
  if (disc == 0 || std::abs(disc) <= tol * disc_scale) {
    out.kind = LineKind::tangent;
    put(-qb / (2 * qa));
    return out;
  }
  if (disc < 0) {
    out.kind = LineKind::none;
    return out;
  }
  out.kind = LineKind::two;
  const double root = std::sqrt(disc);
  const double qq = -0.5 * (qb + (qb >= 0 ? root : -root));
  double t1 = qq / qa, t2 = qc / qq;
  if (t1 > t2) std::swap(t1, t2);
  put(t1);
  put(t2);
  return out;
}

Quadric substitute(const Quadric& q, const Mat3& a, const Vec3d& b) {
  const Mat4 m = matrix4(q);
  Mat4 h{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) h[r][c] = a[r][c];
    h[r][3] = b[r];
  }
  h[3][3] = 1;
  Mat4 mh{}, out{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int n = 0; n < 4; ++n) mh[r][c] += m[r][n] * h[n][c];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int n = 0; n < 4; ++n) out[r][c] += h[n][r] * mh[n][c];
  return from_matrix4(out);
}

Quadric translate(const Quadric& q, const Vec3d& t) {
  return substitute(q, {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, {-t[0], -t[1], -t[2]});
}

Quadric rotate(const Quadric& q, const Mat3& r) {
  Mat3 rt{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) rt[a][b] = r[b][a];
  return substitute(q, rt, {0, 0, 0});
}

Mat3 plane_rotation(int i, int j, double theta) {
  if (i < 0 || i > 2 || j < 0 || j > 2 || i == j)
    throw ModelError("quadric::plane_rotation: needs two different axes 0..2");
  Mat3 r{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const double c = std::cos(theta), s = std::sin(theta);
  r[i][i] = c;
  r[j][j] = c;
  r[j][i] = s;  // e_i ↦ c e_i + s e_j
  r[i][j] = -s;
  return r;
}

Mat3 axis_rotation(const Vec3d& axis, double theta) {
  const double len = std::hypot(axis[0], axis[1], axis[2]);
  if (!(len > 0) || !std::isfinite(len))
    throw ModelError("quadric::axis_rotation: the axis is zero or not finite");
  const double x = axis[0] / len, y = axis[1] / len, z = axis[2] / len;
  const double c = std::cos(theta), s = std::sin(theta), u = 1 - c;
  return {{{c + x * x * u, x * y * u - z * s, x * z * u + y * s},
           {y * x * u + z * s, c + y * y * u, y * z * u - x * s},
           {z * x * u - y * s, z * y * u + x * s, c + z * z * u}}};
}

}  // namespace pgamesh::quadric
