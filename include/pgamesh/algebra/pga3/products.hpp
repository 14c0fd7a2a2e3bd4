// Hand-specialised products between grade types: the meet (outer product, paper eq. 2.1), the
// symmetric inner product, the geometric products that give motors, and the dual/undual. Each is
// the general Multivector product (multivector.hpp) restricted to the grades involved; the tests
// check every one against it. Coordinates: plane n + d e0, line direction l / moment m,
// point weight w / weighted position P (grades.hpp).
#pragma once

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/quaternion.hpp"

namespace pgamesh::pga3 {

// ---- meet: outer product
// --------------------------------------------------------------------------

/// p1 ∧ p2: the line where two planes meet, direction n1 × n2, moment d1 n2 − d2 n1. Parallel
/// planes give an ideal line (zero direction).
template <class T>
constexpr Line<T> meet(const Plane<T>& a, const Plane<T>& b) {
  const Vec3<T> d = cross(a.normal(), b.normal());
  const Vec3<T> m = a.e0 * b.normal() - b.e0 * a.normal();
  return line_from_plucker(d, m);
}
/// L ∧ p (paper eq. 4.11, readable form in docs/conventions.md §12): weighted position n × m − d l,
/// weight n·l. A line parallel to the plane gives an ideal point (weight 0, the line's direction
/// times −d) — never a division by zero; euclidean() of it is infinite, check weight() first.
template <class T>
constexpr Point<T> meet(const Line<T>& l, const Plane<T>& p) {
  const Vec3<T> n = p.normal(), dir = l.direction();
  const Vec3<T> w = cross(n, l.moment()) - p.e0 * dir;
  return {.e123 = dot(n, dir), .e032 = w.x, .e013 = w.y, .e021 = w.z};
}
/// p ∧ L = L ∧ p (grades 1 and 2 commute under ∧: (−1)^(1·2) = 1).
template <class T>
constexpr Point<T> meet(const Plane<T>& p, const Line<T>& l) {
  return meet(l, p);
}
/// p1 ∧ p2 ∧ p3: the common point of three planes (paper §4; weight = det of the normals).
template <class T>
constexpr Point<T> meet(const Plane<T>& a, const Plane<T>& b, const Plane<T>& c) {
  return meet(meet(a, b), c);
}
/// p ∧ v: the e0123 coefficient, equal to p ∨ v (the plane equation at v, eq. 4.10).
template <class T>
constexpr T meet(const Plane<T>& p, const Point<T>& v) {
  return p.e1 * v.e032 + p.e2 * v.e013 + p.e3 * v.e021 + p.e0 * v.e123;
}
/// v ∧ p = −(p ∧ v) (grades 3 and 1: (−1)^3).
template <class T>
constexpr T meet(const Point<T>& v, const Plane<T>& p) {
  return -meet(p, v);
}
/// L1 ∧ L2: the e0123 coefficient m1·l2 + m2·l1; zero when the lines are coplanar.
template <class T>
constexpr T meet(const Line<T>& a, const Line<T>& b) {
  return dot(a.moment(), b.direction()) + dot(b.moment(), a.direction());
}

/// a ^ b = meet(a, b).
template <class T>
constexpr Line<T> operator^(const Plane<T>& a, const Plane<T>& b) {
  return meet(a, b);
}
/// l ^ p = meet(l, p).
template <class T>
constexpr Point<T> operator^(const Line<T>& l, const Plane<T>& p) {
  return meet(l, p);
}
/// p ^ l = meet(p, l).
template <class T>
constexpr Point<T> operator^(const Plane<T>& p, const Line<T>& l) {
  return meet(p, l);
}
/// p ^ v = meet(p, v) (e0123 coefficient).
template <class T>
constexpr T operator^(const Plane<T>& p, const Point<T>& v) {
  return meet(p, v);
}
/// v ^ p = meet(v, p) (e0123 coefficient).
template <class T>
constexpr T operator^(const Point<T>& v, const Plane<T>& p) {
  return meet(v, p);
}
/// a ^ b = meet(a, b) for lines (e0123 coefficient).
template <class T>
constexpr T operator^(const Line<T>& a, const Line<T>& b) {
  return meet(a, b);
}

// ---- symmetric inner product ⟨A_r B_s⟩_|r−s|
// -----------------------------------------------------

/// p1 · p2 = n1·n2 (cosine of the angle between unit planes).
template <class T>
constexpr T inner(const Plane<T>& a, const Plane<T>& b) {
  return dot(a.normal(), b.normal());
}
/// L1 · L2 = −l1·l2.
template <class T>
constexpr T inner(const Line<T>& a, const Line<T>& b) {
  return -dot(a.direction(), b.direction());
}
/// v1 · v2 = −w1 w2.
template <class T>
constexpr T inner(const Point<T>& a, const Point<T>& b) {
  return -a.e123 * b.e123;
}
/// p · L: the plane through L perpendicular to p — normal l × n, e0 coefficient −n·m.
template <class T>
constexpr Plane<T> inner(const Plane<T>& p, const Line<T>& l) {
  const Vec3<T> n = p.normal();
  return plane(cross(l.direction(), n), T(-dot(n, l.moment())));
}
/// L · p = −(p · L).
template <class T>
constexpr Plane<T> inner(const Line<T>& l, const Plane<T>& p) {
  const Vec3<T> n = p.normal();
  return plane(cross(n, l.direction()), dot(n, l.moment()));
}
/// p · v: the line through v perpendicular to p — direction w n, moment P × n.
template <class T>
constexpr Line<T> inner(const Plane<T>& p, const Point<T>& v) {
  const Vec3<T> n = p.normal();
  return line_from_plucker(v.e123 * n, cross(v.weighted(), n));
}
/// v · p = p · v.
template <class T>
constexpr Line<T> inner(const Point<T>& v, const Plane<T>& p) {
  return inner(p, v);
}
/// L · v: the plane through v perpendicular to L — normal −w l, e0 coefficient l·P.
template <class T>
constexpr Plane<T> inner(const Line<T>& l, const Point<T>& v) {
  const Vec3<T> dir = l.direction();
  return plane(-v.e123 * dir, dot(dir, v.weighted()));
}
/// v · L = L · v.
template <class T>
constexpr Plane<T> inner(const Point<T>& v, const Line<T>& l) {
  return inner(l, v);
}

/// a | b = inner(a, b).
template <class A, class B>
constexpr auto operator|(const A& a, const B& b) -> decltype(inner(a, b)) {
  return inner(a, b);
}

// ---- geometric products of equal grades: motors
// -----------------------------------------------------

/// p1 p2 = n1·n2 + (p1 ∧ p2): a rotation about their common line by twice their angle (or a
/// translation by twice their distance, for parallel planes) when both are normalized.
template <class T>
constexpr Motor<T> geometric_product(const Plane<T>& a, const Plane<T>& b) {
  const Line<T> l = meet(a, b);
  return {.s = inner(a, b),
          .e23 = l.e23,
          .e31 = l.e31,
          .e12 = l.e12,
          .e01 = l.e01,
          .e02 = l.e02,
          .e03 = l.e03};
}
/// L1 L2 = (0, −l1) (0, −l2) + ε ((0, −l1)(0, m2) + (0, m1)(0, −l2)) (quaternion.hpp).
template <class T>
constexpr Motor<T> geometric_product(const Line<T>& a, const Line<T>& b) {
  const detail::Quat<T> ea{T(0), -a.direction()}, eb{T(0), -b.direction()};
  const detail::Quat<T> ia{T(0), a.moment()}, ib{T(0), b.moment()};
  const detail::Quat<T> q = ea * eb, c = ea * ib + ia * eb;
  return detail::motor_from(q, c);
}
/// v1 v2 = −w1 w2 + ε (w2 P1 − w1 P2) (quaternion.hpp): a translation by twice the distance.
template <class T>
constexpr Motor<T> geometric_product(const Point<T>& a, const Point<T>& b) {
  const Vec3<T> c = b.e123 * a.weighted() - a.e123 * b.weighted();
  return {.s = -a.e123 * b.e123, .e01 = c.x, .e02 = c.y, .e03 = c.z};
}
/// a * b = geometric_product(a, b) for two planes.
template <class T>
constexpr Motor<T> operator*(const Plane<T>& a, const Plane<T>& b) {
  return geometric_product(a, b);
}
/// a * b = geometric_product(a, b) for two lines.
template <class T>
constexpr Motor<T> operator*(const Line<T>& a, const Line<T>& b) {
  return geometric_product(a, b);
}
/// a * b = geometric_product(a, b) for two points.
template <class T>
constexpr Motor<T> operator*(const Point<T>& a, const Point<T>& b) {
  return geometric_product(a, b);
}

// ---- dual and undual (docs/conventions.md §3 table)
// ------------------------------------------------------------

/// p*: e0 → e123, e1 → e032, e2 → e013, e3 → e021.
template <class T>
constexpr Point<T> dual(const Plane<T>& p) {
  return {.e123 = p.e0, .e032 = p.e1, .e013 = p.e2, .e021 = p.e3};
}
/// v*: e021 → −e3, e013 → −e2, e032 → −e1, e123 → −e0.
template <class T>
constexpr Plane<T> dual(const Point<T>& v) {
  return {-v.e123, -v.e032, -v.e013, -v.e021};
}
/// L*: swaps direction and moment (e01 ↔ e23, e02 ↔ e31, e03 ↔ e12).
template <class T>
constexpr Line<T> dual(const Line<T>& l) {
  return line_from_plucker(l.moment(), l.direction());
}
/// p^(−*): e0 → −e123, e1 → −e032, e2 → −e013, e3 → −e021.
template <class T>
constexpr Point<T> undual(const Plane<T>& p) {
  return {.e123 = -p.e0, .e032 = -p.e1, .e013 = -p.e2, .e021 = -p.e3};
}
/// v^(−*): e021 → e3, e013 → e2, e032 → e1, e123 → e0.
template <class T>
constexpr Plane<T> undual(const Point<T>& v) {
  return {v.e123, v.e032, v.e013, v.e021};
}
/// L^(−*) = L* (grade 2 rows of the docs/conventions.md §3 table agree).
template <class T>
constexpr Line<T> undual(const Line<T>& l) {
  return dual(l);
}
/// !p = dual(p).
template <class T>
constexpr Point<T> operator!(const Plane<T>& p) {
  return dual(p);
}
/// !v = dual(v).
template <class T>
constexpr Plane<T> operator!(const Point<T>& v) {
  return dual(v);
}
/// !L = dual(L).
template <class T>
constexpr Line<T> operator!(const Line<T>& l) {
  return dual(l);
}

}  // namespace pgamesh::pga3
