// Internal: the even subalgebra of PGA R(3,0,1) is the dual quaternions, and the motor kernels are
// written with them. With I3 = e123 and ε = e0123 (ε² = 0, ε commutes with even elements):
//   Motor  s + b·(e23, e31, e12) + m·(e01, e02, e03) + p e0123 = q + ε c,
//          q = (s, −b)  (Hamilton quaternion, i = −e23, j = −e31, k = −e12: i j = k),
//          c = (p, m);
//   Line   direction l, moment m  =  (0, −l) + ε (0, m);
//   Point  w e123 + P·(e032, e013, e021)  =  w I3 − ε P   (P a vector, e032 = −ε e1);
//   Plane  n·(e1, e2, e3) + d e0  =  n + d e0           (e0 = −ε I3).
// The sandwich formulas in motor.hpp follow from these; tests compare them with the general
// 16-component product.
#pragma once

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::pga3::detail {

template <class T>
struct Quat {
  T w{};
  Vec3<T> v{};
};

template <class T>
constexpr Quat<T> operator*(const Quat<T>& a, const Quat<T>& b) {
  return {a.w * b.w - dot(a.v, b.v), a.w * b.v + b.w * a.v + cross(a.v, b.v)};
}
template <class T>
constexpr Quat<T> operator+(const Quat<T>& a, const Quat<T>& b) {
  return {a.w + b.w, a.v + b.v};
}
template <class T>
constexpr Quat<T> operator-(const Quat<T>& a, const Quat<T>& b) {
  return {a.w - b.w, a.v - b.v};
}
template <class T>
constexpr Quat<T> operator*(T s, const Quat<T>& a) {
  return {s * a.w, s * a.v};
}
template <class T>
constexpr Quat<T> conj(const Quat<T>& a) {
  return {a.w, -a.v};
}
/// Four-dimensional dot product (= scalar part of a b*).
template <class T>
constexpr T dot4(const Quat<T>& a, const Quat<T>& b) {
  return a.w * b.w + dot(a.v, b.v);
}
/// q x q* for a vector x, not divided by |q|²: (w² − v·v) x + 2 (v·x) v + 2 w (v × x).
template <class T>
constexpr Vec3<T> rotate(const Quat<T>& q, const Vec3<T>& x) {
  return (q.w * q.w - dot(q.v, q.v)) * x + T(2) * dot(q.v, x) * q.v + T(2) * q.w * cross(q.v, x);
}

/// q of M = q + ε c: (s, −(e23, e31, e12)).
template <class T>
constexpr Quat<T> real_part(const Motor<T>& m) {
  return {m.s, {-m.e23, -m.e31, -m.e12}};
}
/// c of M = q + ε c: (e0123, (e01, e02, e03)).
template <class T>
constexpr Quat<T> dual_part(const Motor<T>& m) {
  return {m.e0123, {m.e01, m.e02, m.e03}};
}
/// The motor q + ε c.
template <class T>
constexpr Motor<T> motor_from(const Quat<T>& q, const Quat<T>& c) {
  return {.s = q.w,
          .e23 = -q.v.x,
          .e31 = -q.v.y,
          .e12 = -q.v.z,
          .e0123 = c.w,
          .e01 = c.v.x,
          .e02 = c.v.y,
          .e03 = c.v.z};
}
}  // namespace pgamesh::pga3::detail
