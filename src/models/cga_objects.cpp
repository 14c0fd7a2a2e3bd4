// Conformal objects from points and from parameters (docs/models-cga.md §3, §4).
#include "pgamesh/models/cga_objects.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "pgamesh/models/cga_motor.hpp"

namespace pgamesh::cga {

namespace {

// Below this relative size an edge, area or volume counts as zero: a few ulps of the inputs.
constexpr double degenerate = 64 * std::numeric_limits<double>::epsilon();

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void require_distinct(Vec3d a, Vec3d b, const char* what) {
  const double scale = std::max(length(a), length(b));
  if (length(b - a) <= degenerate * scale)
    throw ModelError(std::string(what) + ": two of the points coincide");
}

// |(b − a) × (c − a)| relative to |b − a| |c − a|: zero for collinear points.
void require_not_collinear(Vec3d a, Vec3d b, Vec3d c, const char* what) {
  require_distinct(a, b, what);
  require_distinct(a, c, what);
  require_distinct(b, c, what);
  const Vec3d u = b - a, v = c - a;
  const double sine = length(cross(u, v)) / (length(u) * length(v));
  if (!(sine > degenerate))
    throw ModelError(std::string(what) + ": the points are collinear (sine of their angle " +
                     num(sine) + ")");
}

// Moves an element built about `origin` back to absolute coordinates.
template <GradeMask G>
Multivector<G> moved(const Multivector<G>& x, Vec3d origin) {
  if (origin.x == 0 && origin.y == 0 && origin.z == 0) return x;
  return sandwich(translator(origin), x);
}

}  // namespace

void require_finite(Vec3d p, const char* what) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw ModelError(std::string(what) + ": a coordinate is not finite (NaN or infinite)");
}

Bivector point_pair(Vec3d p1, Vec3d p2) {
  require_finite(p1, "cga::point_pair");
  require_finite(p2, "cga::point_pair");
  require_distinct(p1, p2, "cga::point_pair");
  return moved(up({}) ^ up(p2 - p1), p1);  // Hitzer eq. 6 about p1
}

Bivector flat_point(Vec3d p) {
  require_finite(p, "cga::flat_point");
  return up(p) ^ einf();
}

Trivector line(Vec3d p1, Vec3d p2) {
  require_finite(p1, "cga::line");
  require_finite(p2, "cga::line");
  require_distinct(p1, p2, "cga::line");
  return line_from_point(p1, p2 - p1);
}

Trivector line_from_point(Vec3d p, Vec3d d) {
  require_finite(p, "cga::line_from_point");
  require_finite(d, "cga::line_from_point");
  if (!(length(d) > 0)) throw ModelError("cga::line_from_point: the direction is zero");
  // Hitzer eq. 16 with p1 = p, p2 = p + d: d N + (p ∧ d) ∧ e_∞, and d N = e_o ∧ d ∧ e_∞.
  Trivector x;
  auto set = [&](BladeMask m, double c) { x.c[static_cast<std::size_t>(x.index_of(m))] = c; };
  set(eo_mask | e1_mask | einf_mask, d.x);
  set(eo_mask | e2_mask | einf_mask, d.y);
  set(eo_mask | e3_mask | einf_mask, d.z);
  const Vec3d m = cross(p, d);  // p ∧ d = m_x e23 + m_y e31 + m_z e12
  set(e2_mask | e3_mask | einf_mask, m.x);
  set(e1_mask | e3_mask | einf_mask, -m.y);
  set(e1_mask | e2_mask | einf_mask, m.z);
  return x;
}

Trivector circle(Vec3d p1, Vec3d p2, Vec3d p3) {
  for (Vec3d p : {p1, p2, p3}) require_finite(p, "cga::circle");
  require_not_collinear(p1, p2, p3, "cga::circle");
  return moved(up({}) ^ up(p2 - p1) ^ up(p3 - p1), p1);  // Hitzer eq. 20 about p1
}

Quadvector plane(Vec3d p1, Vec3d p2, Vec3d p3) {
  for (Vec3d p : {p1, p2, p3}) require_finite(p, "cga::plane");
  require_not_collinear(p1, p2, p3, "cga::plane");
  return moved(up({}) ^ up(p2 - p1) ^ up(p3 - p1) ^ einf(), p1);  // Hitzer eq. 36 about p1
}

Quadvector sphere(Vec3d p1, Vec3d p2, Vec3d p3, Vec3d p4) {
  for (Vec3d p : {p1, p2, p3, p4}) require_finite(p, "cga::sphere");
  require_not_collinear(p1, p2, p3, "cga::sphere");
  require_distinct(p1, p4, "cga::sphere");
  require_distinct(p2, p4, "cga::sphere");
  require_distinct(p3, p4, "cga::sphere");
  const Vec3d a = p2 - p1, b = p3 - p1, c = p4 - p1;
  const double rel =
      std::abs(dot(a, cross(b, c))) / (length(a) * length(b) * length(c));  // |det| / (|a||b||c|)
  if (!(rel > degenerate))
    throw ModelError("cga::sphere: the four points are coplanar (relative volume " + num(rel) +
                     "): they span a plane, not a sphere");
  return moved(up({}) ^ up(a) ^ up(b) ^ up(c), p1);  // Hitzer eq. 43 about p1
}

Vector dual_sphere_r2(Vec3d center, double radius_squared) {
  require_finite(center, "cga::dual_sphere");
  if (!std::isfinite(radius_squared))
    throw ModelError("cga::dual_sphere: the squared radius is not finite");
  Vector s = up(center);
  s.c[4] -= 0.5 * radius_squared;
  return s;
}

Vector dual_sphere(Vec3d center, double radius) {
  if (!(radius >= 0) || !std::isfinite(radius))
    throw ModelError("cga::dual_sphere: the radius must be finite and >= 0 (got " + num(radius) +
                     "); use dual_sphere_r2 for an imaginary sphere");
  return dual_sphere_r2(center, radius * radius);
}

Vector dual_plane(Vec3d normal, double distance) {
  require_finite(normal, "cga::dual_plane");
  const double len = length(normal);
  if (!(len > 0)) throw ModelError("cga::dual_plane: the normal is zero");
  if (!std::isfinite(distance)) throw ModelError("cga::dual_plane: the distance is not finite");
  const Vec3d n = normal / len;
  Vector p;
  p.c = {0.0, n.x, n.y, n.z, distance};
  return p;
}

Bivector dual_circle(Vec3d center, Vec3d normal, double radius) {
  require_finite(normal, "cga::dual_circle");
  const double len = length(normal);
  if (!(len > 0)) throw ModelError("cga::dual_circle: the normal is zero");
  // π ∧ σ (not σ ∧ π): undual of this is oriented like P1 ∧ P2 ∧ P3 with normal n̂.
  return dual_plane(normal, dot(normal / len, center)) ^ dual_sphere(center, radius);
}

Bivector dual_line(Vec3d p, Vec3d d) {
  return dual(line_from_point(p, d));
}

Quadvector sphere_from_center(Vec3d center, double radius) {
  return undual(dual_sphere(center, radius));
}

Quadvector plane_from_normal(Vec3d normal, double distance) {
  return -undual(dual_plane(normal, distance));
}

Trivector circle_from_center(Vec3d center, Vec3d normal, double radius) {
  return undual(dual_circle(center, normal, radius));
}

}  // namespace pgamesh::cga
