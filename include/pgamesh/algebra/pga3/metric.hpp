// Euclidean measurements and projections with the grade types: the plane side test (paper
// eq. 4.10), signed distances, distances between points and lines, angles, and orthogonal
// projections built from inner products and meets (project v on p = (p · v) ∧ p).
#pragma once

#include <cmath>
#include <limits>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/join.hpp"
#include "pgamesh/algebra/pga3/norm.hpp"
#include "pgamesh/algebra/pga3/products.hpp"

namespace pgamesh::pga3 {

/// The side test p ∨ v = a x + b y + c z + d (paper eq. 4.10), scaled by the point's weight:
/// > 0 on the side the normal points to, < 0 behind, 0 on the plane.
template <class T>
constexpr T side(const Plane<T>& p, const Point<T>& v) {
  return join(p, v);
}

/// Signed distance of v from p: (p ∨ v)/(‖p‖ w) (positive on the normal's side).
template <class T>
T signed_distance(const Plane<T>& p, const Point<T>& v) {
  return join(p, v) / (norm(p) * v.e123);
}
/// Distance between two Euclidean points: ‖a ∨ b‖/|w_a w_b| (paper Table 3: the norm of the
/// edge carrier is its length).
template <class T>
T distance(const Point<T>& a, const Point<T>& b) {
  return norm(join(a, b)) / std::abs(a.e123 * b.e123);
}
/// Distance of v from the line L: ‖L ∨ v‖/(‖L‖ |w|) (twice the triangle area over the base).
template <class T>
T distance(const Line<T>& l, const Point<T>& v) {
  return norm(join(l, v)) / (norm(l) * std::abs(v.e123));
}
/// Distance of v from the line L (same as distance(L, v)).
template <class T>
T distance(const Point<T>& v, const Line<T>& l) {
  return distance(l, v);
}
/// Distance between two lines: |L1 ∨ L2|/|l1 × l2| for skew lines; for (nearly) parallel lines,
/// |l1 × l2| ≤ √ε |l1| |l2|, the distance of a point of L2 from L1.
template <class T>
T distance(const Line<T>& a, const Line<T>& b) {
  const Vec3<T> la = a.direction(), lb = b.direction();
  const T cr = length(cross(la, lb));
  if (cr > std::sqrt(std::numeric_limits<T>::epsilon()) * length(la) * length(lb))
    return std::abs(join(a, b)) / cr;
  // The point of L2 nearest the origin, lb × mb / |lb|², as a weighted point (weight |lb|²).
  const Vec3<T> q = cross(lb, b.moment());
  return distance(a, Point<T>{.e123 = dot(lb, lb), .e032 = q.x, .e013 = q.y, .e021 = q.z});
}

/// Angle between two planes (between their normals), in [0, π].
template <class T>
T angle(const Plane<T>& a, const Plane<T>& b) {
  return std::atan2(length(cross(a.normal(), b.normal())), dot(a.normal(), b.normal()));
}
/// Angle between two lines (between their directions), in [0, π].
template <class T>
T angle(const Line<T>& a, const Line<T>& b) {
  return std::atan2(length(cross(a.direction(), b.direction())), dot(a.direction(), b.direction()));
}
/// Angle between a line and a plane, in [0, π/2] (0 when the line is parallel to the plane).
template <class T>
T angle(const Line<T>& l, const Plane<T>& p) {
  return std::atan2(std::abs(dot(l.direction(), p.normal())),
                    length(cross(l.direction(), p.normal())));
}
/// Angle between a plane and a line (same as angle(l, p)).
template <class T>
T angle(const Plane<T>& p, const Line<T>& l) {
  return angle(l, p);
}

/// The foot of the perpendicular from v to p: (p · v) ∧ p, weight ‖p‖² w (normalize to read it).
template <class T>
constexpr Point<T> project(const Point<T>& v, const Plane<T>& p) {
  return meet(inner(p, v), p);
}
/// The foot of the perpendicular from v to L: (L · v) ∧ L, weight −‖L‖² w (normalize to read it).
template <class T>
constexpr Point<T> project(const Point<T>& v, const Line<T>& l) {
  return meet(inner(l, v), l);
}
/// The orthogonal projection of L onto p: (L · p) ∧ p (direction l ‖p‖² − n (n·l)); an ideal
/// line when L is perpendicular to p.
template <class T>
constexpr Line<T> project(const Line<T>& l, const Plane<T>& p) {
  return meet(inner(l, p), p);
}
/// The plane through v parallel to p, with p's orientation: w n·x − n·P = 0.
template <class T>
constexpr Plane<T> project(const Plane<T>& p, const Point<T>& v) {
  return plane(v.e123 * p.normal(), T(-dot(p.normal(), v.weighted())));
}
/// The line through v parallel to L, with L's orientation: direction w l, moment P × l.
template <class T>
constexpr Line<T> project(const Line<T>& l, const Point<T>& v) {
  return line_from_plucker(v.e123 * l.direction(), cross(v.weighted(), l.direction()));
}

}  // namespace pgamesh::pga3
