// The exponential of a bivector (Line) and the logarithm and square root of a motor, in closed
// form, robust at tiny angles (series for the cancelling terms) and for pure translations (no
// division by the angle). With the dual-quaternion form of quaternion.hpp, a bivector B is
// u + ε v with u = −l (direction), v = m (moment), θ = |u|, and B² = −(θ + ε δ)², θ δ = u·v:
//   exp(B) = cos θ + u sinc θ + ε [ −(u·v) sinc θ + v sinc θ + u (u·v) (cos θ − sinc θ)/θ² ].
// Also: the rotor about an arbitrary line, and the motor taking one plane/line/point to another,
// √(B A⁻¹).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
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

/// Σ c_k x^k, summed in pairs (Estrin's scheme): (c_0 + x c_1) + x² (c_2 + x c_3) + …, so that
/// N coefficients cost about log₂ N levels of multiply-adds instead of N in a row.
template <class T, std::size_t N>
constexpr T polynomial(const std::array<T, N>& c, T x) {
  if constexpr (N == 1) {
    return c[0];
  } else {
    std::array<T, (N + 1) / 2> pairs{};
    for (std::size_t k = 0; k < N / 2; ++k) pairs[k] = c[2 * k] + x * c[2 * k + 1];
    if constexpr (N % 2 == 1) pairs[N / 2] = c[N - 1];
    return polynomial(pairs, x * x);
  }
}

/// The Taylor coefficients in θ² of cos θ, sinc θ and (cos θ − sinc θ)/θ², k = 0 … N − 1:
/// (−1)^k/(2k)!, (−1)^k/(2k+1)! and (−1)^(k+1) (2k+2)/(2k+3)!, rounded once to T.
enum class Series { cos, sinc, cos_minus_sinc_over_sq };
template <class T, std::size_t N>
constexpr std::array<T, N> taylor_coefficients(Series series) {
  std::array<T, N> c{};
  long double factorial = 1;  // n! for the n of term k
  int n = 0;
  const int first = series == Series::cos ? 0 : series == Series::sinc ? 1 : 3;
  for (std::size_t k = 0; k < N; ++k) {
    while (n < first + 2 * int(k)) factorial *= ++n;
    const long double sign = k % 2 == 0 ? 1 : -1;
    c[k] = series == Series::cos_minus_sinc_over_sq ? T(-sign * (2 * k + 2) / factorial)
                                                    : T(sign / factorial);
  }
  return c;
}

/// Half-angles θ up to π/2 (turns up to a half turn), where exp takes the series in θ²: 12 terms
/// leave truncation errors below 2e−17 there (the first omitted term of cos θ, θ^24/24!, is
/// 8e−20; of (cos θ − sinc θ)/θ², 3e−20), and the terms are at most 1.3 in magnitude.
template <class T>
inline constexpr T kSeriesBoundSq = T(2.4674011002723395);  // (π/2)²
inline constexpr std::size_t kSeriesTerms = 12;

/// The factors of exp (the header's formula): cos θ, sinc θ and g = (cos θ − sinc θ)/θ².
template <class T>
struct ExpFactors {
  T cos, sinc, g;
};
/// ExpFactors from θ², for θ² ≤ (π/2)²: series, no square root, no division, no sine or cosine.
template <class T>
ExpFactors<T> exp_factors_series(T t2) {
  static constexpr auto kCos = taylor_coefficients<T, kSeriesTerms>(Series::cos);
  static constexpr auto kSinc = taylor_coefficients<T, kSeriesTerms>(Series::sinc);
  static constexpr auto kG = taylor_coefficients<T, kSeriesTerms>(Series::cos_minus_sinc_over_sq);
  return {polynomial(kCos, t2), polynomial(kSinc, t2), polynomial(kG, t2)};
}
/// The same for any θ² (beyond (π/2)²: θ = √θ², one sine and cosine, two divisions).
template <class T>
ExpFactors<T> exp_factors(T t2) {
  if (t2 <= kSeriesBoundSq<T>) return exp_factors_series(t2);
  const T theta = std::sqrt(t2), cos_theta = std::cos(theta), sinc_theta = sinc(theta);
  return {cos_theta, sinc_theta, (cos_theta - sinc_theta) / t2};
}

/// (cos θ − sinc θ)/θ² (the direct form cancels for small θ, its error about ε/θ²: the series
/// takes over below π/2).
template <class T>
T cos_minus_sinc_over_sq(T theta) {
  return exp_factors(theta * theta).g;
}
}  // namespace detail

/// exp(B) of a bivector B (a Line; not necessarily simple): a normalized motor. exp(−θ/2 L)
/// rotates by θ about the unit line L; exp(−½ t·(e01, e02, e03)) = translator(t)
/// (docs/conventions.md §7).
template <class T>
Motor<T> exp(const Line<T>& b) {
  const Vec3<T> l = b.direction(), m = b.moment();
  // Half-angles up to π/2 take series in θ² (no square root, division or sine on the way).
  const detail::ExpFactors<T> f = detail::exp_factors(dot(l, l));
  const T cos_theta = f.cos, sc = f.sinc, g = f.g;
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
/// It inverts exp's formula at the top of this file (motors as in docs/conventions.md §7):
/// q = cos θ + u sinc θ gives θ and the axis u/θ, and the dual part gives v.
template <class T>
Line<T> log(const Motor<T>& mo) {
  const detail::Quat<T> q = detail::real_part(mo), c = detail::dual_part(mo);
  const T sn = length(q.v), w = q.w;
  const bool turns = sn > T(0);
  // Everything that does not need θ comes before atan2, whose call clobbers every vector
  // register: what is computed after it lengthens the chain (the division 1/sin θ did).
  Vec3<T> axis;
  T inv_sn{};  // 1 / sin θ, where the motor turns
  if (turns) {
    inv_sn = T(1) / sn;
    axis = inv_sn * q.v;
  } else {
    const T cl = length(c.v);
    axis = cl > T(0) ? c.v / cl : Vec3<T>{T(1), T(0), T(0)};
  }
  // Split v along the axis: c∥ = v∥ cos θ, c_w = −v∥ sin θ, c⊥ = v⊥ sinc θ.
  const T c_par = dot(c.v, axis);
  const Vec3<T> c_perp = c.v - c_par * axis;
  const Vec3<T> v_par = (c_par * w - c.w * sn) * axis;
  const T theta = std::atan2(sn, w);
  const T ratio = turns ? theta * inv_sn : T(1);  // θ / sin θ = 1/sinc θ (1 without a turn)
  return line_from_plucker(-theta * axis, ratio * c_perp + v_par);
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
