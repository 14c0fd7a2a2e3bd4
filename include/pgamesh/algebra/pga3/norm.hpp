// Norms (docs/conventions.md §6, paper §3): the Euclidean norm ‖A‖ is the root of the sum of
// squares of the coefficients without e0, the ideal norm ‖A‖∞ = ‖A ∨ o‖ = ‖A*‖ that of the
// coefficients with e0. The Euclidean norm of a k-simplex carrier is k! × its magnitude (paper
// Tables 3, 4).
#pragma once

#include <cmath>

#include "pgamesh/algebra/pga3/grades.hpp"

namespace pgamesh::pga3 {

/// ‖p‖ = |normal|.
template <class T>
T norm(const Plane<T>& p) {
  using std::sqrt;  // and sqrt(Double4) by argument-dependent lookup
  return sqrt(p.e1 * p.e1 + p.e2 * p.e2 + p.e3 * p.e3);
}
/// ‖p‖∞ = |d|.
template <class T>
T ideal_norm(const Plane<T>& p) {
  return std::abs(p.e0);
}
/// ‖L‖ = |direction| (length of the edge v0 ∨ v1).
template <class T>
T norm(const Line<T>& l) {
  return std::sqrt(l.e12 * l.e12 + l.e31 * l.e31 + l.e23 * l.e23);
}
/// ‖L‖∞ = |moment|.
template <class T>
T ideal_norm(const Line<T>& l) {
  return std::sqrt(l.e01 * l.e01 + l.e02 * l.e02 + l.e03 * l.e03);
}
/// ‖v‖ = |weight|.
template <class T>
T norm(const Point<T>& v) {
  return std::abs(v.e123);
}
/// ‖v‖∞ = |w·(x, y, z)|.
template <class T>
T ideal_norm(const Point<T>& v) {
  return std::sqrt(v.e021 * v.e021 + v.e013 * v.e013 + v.e032 * v.e032);
}
/// ‖M‖ = sqrt(s² + e12² + e31² + e23²); 1 for a normalized motor.
template <class T>
T norm(const Motor<T>& m) {
  return std::sqrt(m.s * m.s + m.e12 * m.e12 + m.e31 * m.e31 + m.e23 * m.e23);
}
/// ‖M‖∞ = sqrt(e01² + e02² + e03² + e0123²).
template <class T>
T ideal_norm(const Motor<T>& m) {
  return std::sqrt(m.e01 * m.e01 + m.e02 * m.e02 + m.e03 * m.e03 + m.e0123 * m.e0123);
}

/// p / ‖p‖: unit normal, e0 coefficient = −(signed distance of the origin). A plane with zero
/// normal (the ideal plane) is returned unchanged.
template <class T>
Plane<T> normalized(const Plane<T>& p) {
  const T n = norm(p);
  return n == T(0) ? p : Plane<T>{p.e0 / n, p.e1 / n, p.e2 / n, p.e3 / n};
}
/// L / ‖L‖: unit direction. An ideal line (zero direction) is divided by its ideal norm instead.
template <class T>
Line<T> normalized(const Line<T>& l) {
  T n = norm(l);
  if (n == T(0)) n = ideal_norm(l);
  if (n == T(0)) return l;
  return {l.e01 / n, l.e02 / n, l.e03 / n, l.e12 / n, l.e31 / n, l.e23 / n};
}
/// v / weight: e123 = 1, so the other coefficients are the coordinates. A direction (weight 0)
/// is scaled to unit length instead.
template <class T>
Point<T> normalized(const Point<T>& v) {
  const T w = v.e123 != T(0) ? v.e123 : ideal_norm(v);
  if (w == T(0)) return v;
  return {.e123 = v.e123 / w, .e032 = v.e032 / w, .e013 = v.e013 / w, .e021 = v.e021 / w};
}

}  // namespace pgamesh::pga3
