// Motors (even elements: rotations, translations, screws) — composition, reverse, normalisation,
// inverse, the rotor and translator constructors of docs/conventions.md §7 and the sandwich
// X ↦ M X M̃ on every grade. The kernels use the dual-quaternion form M = q + ε c of quaternion.hpp.
#pragma once

#include <cmath>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/quaternion.hpp"

namespace pgamesh::pga3 {

namespace detail {
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
  return {q.w, c.v.x, c.v.y, c.v.z, -q.v.z, -q.v.y, -q.v.x, c.w};
}
}  // namespace detail

/// The geometric product A B of two motors, (q_a + ε c_a)(q_b + ε c_b) =
/// q_a q_b + ε (q_a c_b + c_a q_b). As a motion, B acts first: (A B) X (A B)~ = A (B X B̃) Ã.
template <class T>
constexpr Motor<T> geometric_product(const Motor<T>& a, const Motor<T>& b) {
  using detail::dual_part, detail::real_part;
  const auto qa = real_part(a), qb = real_part(b), ca = dual_part(a), cb = dual_part(b);
  return detail::motor_from(qa * qb, qa * cb + ca * qb);
}
/// A * B = geometric_product(A, B): the motion B followed by A.
template <class T>
constexpr Motor<T> operator*(const Motor<T>& a, const Motor<T>& b) {
  return geometric_product(a, b);
}
/// A *= B: A ← A B.
template <class T>
constexpr Motor<T>& operator*=(Motor<T>& a, const Motor<T>& b) {
  return a = a * b;
}

/// The reverse M̃: the bivector part changes sign (grade k picks up (−1)^(k(k−1)/2)).
template <class T>
constexpr Motor<T> reverse(const Motor<T>& m) {
  return {m.s, -m.e01, -m.e02, -m.e03, -m.e12, -m.e31, -m.e23, m.e0123};
}
/// ~M = reverse(M).
template <class T>
constexpr Motor<T> operator~(const Motor<T>& m) {
  return reverse(m);
}

/// M / sqrt(M M̃), with M M̃ = |q|² + 2 ε (q·c) a dual number: the result has M M̃ = 1 exactly
/// (unit q and q·c = 0, the Study condition), so its sandwich is a rigid motion. The zero motor
/// is returned unchanged.
template <class T>
Motor<T> normalized(const Motor<T>& m) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const T r2 = dot4(q, q);
  if (r2 == T(0)) return m;
  const T inv_r = T(1) / std::sqrt(r2);
  // (a + ε b)^(−1/2) = a^(−1/2) − ε b / (2 a^(3/2)), a = |q|², b = 2 q·c.
  const T dual = -dot4(q, c) * inv_r * inv_r * inv_r;
  return detail::motor_from(inv_r * q, inv_r * c + dual * q);
}

/// M⁻¹ = M̃ (M M̃)⁻¹, (a + ε b)⁻¹ = 1/a − ε b/a² (a = |q|², b = 2 q·c). Defined when q ≠ 0;
/// equals M̃ for a normalized motor.
template <class T>
constexpr Motor<T> inverse(const Motor<T>& m) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const T a = dot4(q, q);
  const T alpha = T(1) / a, beta = T(-2) * dot4(q, c) / (a * a);
  return detail::motor_from(alpha * conj(q), alpha * conj(c) + beta * conj(q));
}

/// The rotor turning by +angle (radians, right-handed) about the axis through the origin with
/// direction `axis`: R = cos(θ/2) − sin(θ/2) (a_x e23 + a_y e31 + a_z e12), a = axis/|axis|
/// (docs/conventions.md §7) = exp(−θ/2 (a_x e23 + a_y e31 + a_z e12)). A zero axis gives the
/// identity.
template <class T>
Motor<T> rotor(T angle, Vec3<T> axis) {
  const T len = length(axis);
  if (len == T(0)) return identity_motor<T>();
  const T c = std::cos(angle / 2), s = std::sin(angle / 2) / len;
  return {c, T(0), T(0), T(0), -s * axis.z, -s * axis.y, -s * axis.x, T(0)};
}

/// The translator by t: T = 1 − ½ (t_x e01 + t_y e02 + t_z e03) (docs/conventions.md §7)
/// = exp(−½ t·e0i).
template <class T>
constexpr Motor<T> translator(Vec3<T> t) {
  return {T(1), -t.x / 2, -t.y / 2, -t.z / 2, T(0), T(0), T(0), T(0)};
}

/// M X M̃ for a point X = w I3 − ε P: weight |q|² w, weighted position q P q* + w t with
/// t = 2 (c_w q_v − q_w c_v + c_v × q_v) the translation (−2 vec(c q*)). For a normalized M,
/// the rigid motion of the point (a direction, w = 0, is only rotated).
template <class T>
constexpr Point<T> apply(const Motor<T>& m, const Point<T>& x) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const T w = x.e123;
  const Vec3<T> t = T(2) * (c.w * q.v - q.w * c.v + cross(c.v, q.v));
  const Vec3<T> p = detail::rotate(q, x.weighted()) + w * t;
  return {p.z, p.y, p.x, dot4(q, q) * w};
}

/// M p M̃ for a plane p = n + d e0: normal q n q*, e0 coefficient |q|² d + 2 Re(q n c*)
/// (= d − n·t for a unit rotation-free motor translating by t).
template <class T>
constexpr Plane<T> apply(const Motor<T>& m, const Plane<T>& p) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const Vec3<T> n = p.normal();
  const Vec3<T> rn = detail::rotate(q, n);
  const T d =
      dot4(q, q) * p.e0 + T(2) * (-c.w * dot(q.v, n) + q.w * dot(n, c.v) + dot(cross(q.v, n), c.v));
  return {d, rn.x, rn.y, rn.z};
}

/// M L M̃ for a line L = (0, −l) + ε (0, m): direction q l q*, moment q m q* − 2 vec(q l c*)
/// (= m + t × l for a translation by t).
template <class T>
constexpr Line<T> apply(const Motor<T>& mo, const Line<T>& line) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(mo), c = dual_part(mo);
  const Vec3<T> l = line.direction();
  const detail::Quat<T> ql{-dot(q.v, l), q.w * l + cross(q.v, l)};  // q l
  const Vec3<T> qlc = c.w * ql.v - ql.w * c.v - cross(ql.v, c.v);   // vec(q l c*)
  return line_from_plucker(detail::rotate(q, l), detail::rotate(q, line.moment()) - T(2) * qlc);
}

/// M N M̃ for a motor N (conjugation: the motion N seen in the frame moved by M).
template <class T>
constexpr Motor<T> apply(const Motor<T>& m, const Motor<T>& n) {
  return m * n * reverse(m);
}

}  // namespace pgamesh::pga3
