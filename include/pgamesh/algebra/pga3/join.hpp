// The join (regressive product) A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2) between grade types, as
// `join(a, b)` and `a & b`. Joins of points are carriers: a line (edge), a plane (face), a scalar
// (tetrahedron, 6 × signed volume). Signs: docs/conventions.md §5 (klein and ganja.js differ on
// some, §4).
#pragma once

#include "pgamesh/algebra/pga3/grades.hpp"

namespace pgamesh::pga3 {

/// a ∨ b: direction w_a P_b − w_b P_a, moment P_a × P_b (paper eq. 3.10 for unit weights).
template <class T>
constexpr Line<T> join(const Point<T>& a, const Point<T>& b) {
  const Vec3<T> pa = a.weighted(), pb = b.weighted();
  const Vec3<T> d = a.e123 * pb - b.e123 * pa;
  const Vec3<T> m = cross(pa, pb);
  return {m.x, m.y, m.z, d.z, d.y, d.x};
}

/// L ∨ v: normal d × P + w m, e0 coefficient −m·P (docs/conventions.md §5:
/// v0 ∨ v1 ∨ v2 = n − det e0).
template <class T>
constexpr Plane<T> join(const Line<T>& l, const Point<T>& v) {
  const Vec3<T> d = l.direction(), m = l.moment(), p = v.weighted();
  const Vec3<T> n = cross(d, p) + v.e123 * m;
  return {-dot(m, p), n.x, n.y, n.z};
}

/// v ∨ L = L ∨ v (grades 3 and 2: the sign (−1)^((4−3)(4−2)) is +1).
template <class T>
constexpr Plane<T> join(const Point<T>& v, const Line<T>& l) {
  return join(l, v);
}

/// p ∨ v = a x + b y + c z + d for a unit-weight point (paper eq. 4.10); v ∨ p is its negative.
template <class T>
constexpr T join(const Plane<T>& p, const Point<T>& v) {
  return p.e1 * v.e032 + p.e2 * v.e013 + p.e3 * v.e021 + p.e0 * v.e123;
}
/// v ∨ p = −(p ∨ v) (docs/conventions.md §5).
template <class T>
constexpr T join(const Point<T>& v, const Plane<T>& p) {
  return -join(p, v);
}

/// v0 ∨ v1 ∨ v2: the carrier of a triangle, normal (v1 − v0) × (v2 − v0), e0 coefficient −det
/// (paper eq. 3.12, docs/conventions.md §5).
template <class T>
constexpr Plane<T> join(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
  return join(join(a, b), c);
}

/// L1 ∨ L2: a scalar, zero when the lines meet (coplanar); l1·m2 + l2·m1 in the Plücker
/// coordinates (the dual's ∧ with direction and moment swapped, eq. 2.2). For L1 = a ∨ b and
/// L2 = c ∨ d it equals a ∨ b ∨ c ∨ d.
template <class T>
constexpr T join(const Line<T>& a, const Line<T>& b) {
  return dot(a.direction(), b.moment()) + dot(b.direction(), a.moment());
}

/// v0 ∨ v1 ∨ v2 ∨ v3 = det[v1 − v0, v2 − v0, v3 − v0] (paper eq. 3.14, docs/conventions.md §5).
template <class T>
constexpr T join(const Point<T>& a, const Point<T>& b, const Point<T>& c, const Point<T>& d) {
  return join(join(a, b, c), d);
}

/// a & b = a ∨ b.
template <class T>
constexpr Line<T> operator&(const Point<T>& a, const Point<T>& b) {
  return join(a, b);
}
/// l & v = l ∨ v.
template <class T>
constexpr Plane<T> operator&(const Line<T>& l, const Point<T>& v) {
  return join(l, v);
}
/// v & l = v ∨ l.
template <class T>
constexpr Plane<T> operator&(const Point<T>& v, const Line<T>& l) {
  return join(v, l);
}
/// p & v = p ∨ v.
template <class T>
constexpr T operator&(const Plane<T>& p, const Point<T>& v) {
  return join(p, v);
}
/// v & p = v ∨ p.
template <class T>
constexpr T operator&(const Point<T>& v, const Plane<T>& p) {
  return join(v, p);
}
/// a & b = a ∨ b for two lines.
template <class T>
constexpr T operator&(const Line<T>& a, const Line<T>& b) {
  return join(a, b);
}

}  // namespace pgamesh::pga3
