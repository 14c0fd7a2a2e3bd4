// The exponential of a bivector (Line) and the logarithm and square root of a motor, in closed
// form, robust at tiny angles (series for the cancelling terms) and for pure translations (no
// division by the angle). With the dual-quaternion form of quaternion.hpp, a bivector B is
// u + ε v with u = −l (direction), v = m (moment), θ = |u|, and B² = −(θ + ε δ)², θ δ = u·v:
//   exp(B) = cos θ + u sinc θ + ε [ −(u·v) sinc θ + v sinc θ + u (u·v) (cos θ − sinc θ)/θ² ].
// Also: the rotor about an arbitrary line, and the motor taking one plane/line/point to another,
// √(B A⁻¹).
#pragma once

#include <cmath>
#include <type_traits>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/linear.hpp"
#include "pgamesh/algebra/pga3/motor.hpp"
#include "pgamesh/algebra/pga3/norm.hpp"
#include "pgamesh/algebra/pga3/products.hpp"

namespace pgamesh::pga3 {

namespace detail {
/// sin θ / θ, exactly 1 at 0 (std::sin(θ)/θ is accurate for every θ ≠ 0).
template <class T>
T sinc(T theta) {
  return theta == T(0) ? T(1) : std::sin(theta) / theta;
}
/// (cos θ − sinc θ)/θ² from θ and the cos θ and sinc θ already at hand; below |θ| = 1 the Taylor
/// series Σ_{k=1..10} (−1)^k 2k/(2k+1)! θ^(2k−2) (the direct form cancels for small θ: its error
/// is about ε/θ²; the first omitted series term is below 4e−19 at θ = 1; float needs the first
/// six terms). The coefficients are rounded once, at compile time, so the series costs a few
/// multiply-adds and no division. For float and double both forms are computed and one is
/// selected, without a branch: random angles straddle |θ| = 1 and a mispredicted branch cost more
/// than the series.
template <class T>
T cos_minus_sinc_over_sq(T theta, T cos_theta, T sinc_theta) {
  const T t2 = theta * theta;
  // (−1)^k 2k/(2k+1)!, k = 1..10.
  constexpr double kCoef[] = {-1.0 / 3.0,
                              1.0 / 30.0,
                              -1.0 / 840.0,
                              1.0 / 45360.0,
                              -1.0 / 3991680.0,
                              1.0 / 518918400.0,
                              -1.0 / 93405312000.0,
                              1.0 / 22230464256000.0,
                              -1.0 / 6758061133824000.0,
                              1.0 / 2554547108585472000.0};
  constexpr int kTerms = std::is_same_v<T, float> ? 6 : 10;
  const auto series = [&] {
    T sum = T(0);
    for (int k = kTerms - 1; k >= 0; --k) sum = T(kCoef[k]) + t2 * sum;
    return sum;
  };
  const bool small = std::abs(theta) < T(1);
  if constexpr (std::is_floating_point_v<T>) {
    // θ = 0 gives 0/0 in the unused direct form: harmless, it is not selected.
    const T direct = (cos_theta - sinc_theta) / t2, approx = series();
    return small ? approx : direct;
  } else {
    return small ? series() : (cos_theta - sinc_theta) / t2;
  }
}
/// (cos θ − sinc θ)/θ².
template <class T>
T cos_minus_sinc_over_sq(T theta) {
  return cos_minus_sinc_over_sq(theta, T(std::cos(theta)), sinc(theta));
}
}  // namespace detail

/// exp(B) of a bivector B (a Line; not necessarily simple): a normalized motor. exp(−θ/2 L)
/// rotates by θ about the unit line L; exp(−½ t·(e01, e02, e03)) = translator(t)
/// (docs/conventions.md §7).
template <class T>
Motor<T> exp(const Line<T>& b) {
  const Vec3<T> l = b.direction(), m = b.moment();
  const T theta = length(l);
  // One sin and one cos of the same angle: the compiler makes them a single sincos call.
  const T cos_theta = std::cos(theta), sin_theta = std::sin(theta);
  const T sc = theta == T(0) ? T(1) : sin_theta / theta;
  const T g = detail::cos_minus_sinc_over_sq(theta, cos_theta, sc);
  const T lm = dot(l, m);      // = u·v with u = −l, v = m up to the sign absorbed below
  const Vec3<T> rot = sc * l;  // (e23, e31, e12) = −(u sinc θ)
  const Vec3<T> ideal = sc * m + (lm * g) * l;  // v sinc θ + u (u·v) g
  return {.s = cos_theta,
          .e23 = rot.x,
          .e31 = rot.y,
          .e12 = rot.z,
          .e0123 = lm * sc,
          .e01 = ideal.x,
          .e02 = ideal.y,
          .e03 = ideal.z};
}

/// log(M) of a normalized motor: the bivector B with exp(B) = M and half-angle
/// θ = atan2(|q_v|, q_w) ∈ [0, π] (M and −M are the same motion; negate M first, when its
/// scalar part is negative, for the shortest screw). Pure translations (θ = 0) return
/// −½ t·(e01, e02, e03); θ = π picks the axis from the translation part (or x if there is none).
template <class T>
Line<T> log(const Motor<T>& mo) {
  const detail::Quat<T> q = detail::real_part(mo), c = detail::dual_part(mo);
  const T sn = length(q.v), w = q.w;
  const T theta = std::atan2(sn, w);
  Vec3<T> axis;
  T ratio;  // θ / sin θ
  if (sn > T(0)) {
    const T inv = T(1) / sn;
    axis = inv * q.v;
    ratio = theta * inv;
  } else {
    const T cl = length(c.v);
    axis = cl > T(0) ? c.v / cl : Vec3<T>{T(1), T(0), T(0)};
    ratio = T(1);
  }
  // Split v along the axis: c∥ = v∥ cos θ, c_w = −v∥ sin θ, c⊥ = v⊥ sinc θ.
  const T c_par = dot(c.v, axis);
  const Vec3<T> c_perp = c.v - c_par * axis;
  const Vec3<T> v = ratio * c_perp + (c_par * w - c.w * sn) * axis;
  return line_from_plucker(-theta * axis, v);
}

/// √M of a normalized motor: normalized(1 + M) (1 + M = √M · 2 cosh(B/2), a dual scalar times
/// √M). Undefined for M = −1 + ε·… (a full turn), where 1 + M has no Euclidean part.
template <class T>
Motor<T> sqrt(const Motor<T>& m) {
  Motor<T> one_plus = m;
  one_plus.s += T(1);
  return normalized(one_plus);
}

/// The rotor turning by +angle (right-handed) about the line `axis` (any weight, not ideal):
/// exp(−θ/2 L̂), L̂ = axis/‖axis‖.
template <class T>
Motor<T> rotor(T angle, const Line<T>& axis) {
  return exp((-angle / 2) * normalized(axis));
}

/// The motor M = √(B A⁻¹) with M A M̃ = B for normalized planes A, B (A⁻¹ = A). Both are
/// normalized here; opposite planes (B = −A moved) have no such motor (1 + BA = 0).
template <class T>
Motor<T> motor_between(const Plane<T>& a, const Plane<T>& b) {
  return sqrt(normalized(b) * normalized(a));
}
/// The motor M = √(B A⁻¹) with M A M̃ = B for lines (normalized here; A⁻¹ = −A). Lines of
/// opposite orientation (B A⁻¹ = −1 …) have no such motor.
template <class T>
Motor<T> motor_between(const Line<T>& a, const Line<T>& b) {
  return sqrt(-(normalized(b) * normalized(a)));
}
/// The translator M = √(B A⁻¹) with M A M̃ = B for Euclidean points (normalized here; A⁻¹ = −A).
template <class T>
Motor<T> motor_between(const Point<T>& a, const Point<T>& b) {
  return sqrt(-(normalized(b) * normalized(a)));
}

}  // namespace pgamesh::pga3
