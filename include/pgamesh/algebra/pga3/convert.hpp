// Conversions between the grade types and the 16-component Multivector: each grade type embeds
// into a Multivector, and grade projection (to_plane, to_line, to_point, to_motor) reads the
// matching coefficients back, dropping every other grade.
#pragma once

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/multivector.hpp"

namespace pgamesh::pga3 {

/// The plane as a multivector (grade 1).
template <class T>
constexpr Multivector<T> to_multivector(const Plane<T>& p) {
  Multivector<T> m;
  m[kE0] = p.e0, m[kE1] = p.e1, m[kE2] = p.e2, m[kE3] = p.e3;
  return m;
}
/// The line as a multivector (grade 2).
template <class T>
constexpr Multivector<T> to_multivector(const Line<T>& l) {
  Multivector<T> m;
  m[kE01] = l.e01, m[kE02] = l.e02, m[kE03] = l.e03;
  m[kE12] = l.e12, m[kE31] = l.e31, m[kE23] = l.e23;
  return m;
}
/// The point as a multivector (grade 3).
template <class T>
constexpr Multivector<T> to_multivector(const Point<T>& v) {
  Multivector<T> m;
  m[kE021] = v.e021, m[kE013] = v.e013, m[kE032] = v.e032, m[kE123] = v.e123;
  return m;
}
/// The motor as a multivector (grades 0, 2, 4).
template <class T>
constexpr Multivector<T> to_multivector(const Motor<T>& mo) {
  Multivector<T> m;
  m[kS] = mo.s, m[kE01] = mo.e01, m[kE02] = mo.e02, m[kE03] = mo.e03;
  m[kE12] = mo.e12, m[kE31] = mo.e31, m[kE23] = mo.e23, m[kE0123] = mo.e0123;
  return m;
}
/// ⟨A⟩_1 as a Plane.
template <class T>
constexpr Plane<T> to_plane(const Multivector<T>& m) {
  return {m[kE0], m[kE1], m[kE2], m[kE3]};
}
/// ⟨A⟩_2 as a Line.
template <class T>
constexpr Line<T> to_line(const Multivector<T>& m) {
  return {m[kE01], m[kE02], m[kE03], m[kE12], m[kE31], m[kE23]};
}
/// ⟨A⟩_3 as a Point.
template <class T>
constexpr Point<T> to_point(const Multivector<T>& m) {
  return {.e123 = m[kE123], .e032 = m[kE032], .e013 = m[kE013], .e021 = m[kE021]};
}
/// ⟨A⟩_0 + ⟨A⟩_2 + ⟨A⟩_4 as a Motor.
template <class T>
constexpr Motor<T> to_motor(const Multivector<T>& m) {
  return {.s = m[kS],
          .e23 = m[kE23],
          .e31 = m[kE31],
          .e12 = m[kE12],
          .e0123 = m[kE0123],
          .e01 = m[kE01],
          .e02 = m[kE02],
          .e03 = m[kE03]};
}

}  // namespace pgamesh::pga3
