// Scalar closed forms behind exp and log of bivectors, shared by the general engine and the
// compile-time PGA R(d,0,1), so each formula lives in one place.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

namespace pgamesh::clifford {

// exp(B) = c0 + cB·B when B² = beta is a scalar: cos/sin (beta < 0), cosh/sinh (beta > 0),
// 1 + B (beta = 0).
struct SimpleExp {
  double c0, cB;
};
inline SimpleExp simple_exp(double beta) {
  const double psi = std::sqrt(std::abs(beta));
  if (psi < 1e-8) return {1.0 + beta / 2, 1.0 + beta / 6};  // series, exact at beta = 0
  if (beta < 0) return {std::cos(psi), std::sin(psi) / psi};
  return {std::cosh(psi), std::sinh(psi) / psi};
}

// log(s + B) = cB·B for a normalised rotor s + B with B² = beta a scalar: the inverse of
// simple_exp (angle atan2(sqrt(−beta), s), rapidity atanh(sqrt(beta)/s), or B/s when beta = 0).
inline double simple_log(double s, double beta) {
  const double b = std::sqrt(std::abs(beta));
  if (b < 1e-12 * std::abs(s) || b == 0) return 1.0 / s;
  if (beta < 0) return std::atan2(b, s) / b;
  return std::atanh(b / s) / b;
}

// Screw motions in R(3,0,1): a bivector L with L² = s + t I (I = e0123, I² = 0) is
// Ψ Û with Û² = −1 and the dual angle Ψ = ψ + δ I, ψ = sqrt(−s), δ = −t/(2ψ). Then
// exp(L) = cos Ψ + (sin Ψ / Ψ) L = c0 + cI·I + cL·L + cIL·(I L).
struct StudyExp {
  double c0, cI, cL, cIL;
};
inline StudyExp study_exp(double s, double t) {
  const double psi = std::sqrt(std::max(-s, 0.0));
  if (psi < 1e-8) {  // series: cos Ψ ≈ 1 − Ψ²/2, sin Ψ/Ψ ≈ 1 − Ψ²/6 with Ψ² = −L²
    return {1.0 + s / 2, t / 2, 1.0 + s / 6, 0.0};
  }
  const double delta = -t / (2 * psi);
  const double sn = std::sin(psi), cs = std::cos(psi);
  return {cs, -delta * sn, sn / psi, delta * (psi * cs - sn) / (psi * psi)};
}

// log of a normalised R(3,0,1) motor m0 + B + m7 I (m0² + |B_E|² = 1): with ψ = atan2(|B_E|, m0)
// and δ = −m7 / sin ψ, log M = (ψ + δ I) B / sin Ψ = cL·B + cIL·(I B).
struct StudyLog {
  double cL, cIL;
};
inline StudyLog study_log(double m0, double euclidean_norm, double m7) {
  const double sn = euclidean_norm;
  if (sn < 1e-12) return {1.0 / m0, 0.0};  // a translation: log(1 + B) = B
  const double psi = std::atan2(sn, m0);
  const double delta = -m7 / sn;
  return {psi / sn, delta * (sn - psi * std::cos(psi)) / (sn * sn)};
}

// ---- functions of a commuting bivector or motor part (see divided_differences.hpp) -------------
// exp(B) = cos√Y + sinc√Y · B with Y = −B² (the power series of exp split into even and odd
// terms), and log M = (θ / sin θ)(E) · O for M = E + O with E = cos θ (docs/clifford.md). Each
// function gives its value and its Taylor coefficients about any centre, so that its divided
// differences over clustered arguments stay accurate.

// cos√y and sin√y/√y (y ≥ 0; cosh and sinh for y < 0).
struct CosSincSqrt {
  double cos_sqrt, sinc_sqrt;
};
inline CosSincSqrt cos_sinc_sqrt(double y) {
  if (std::abs(y) < 1e-4) {  // Taylor, exact at 0 where sin√y/√y is 0/0
    return {1 - y / 2 * (1 - y / 12 * (1 - y / 30)), 1 - y / 6 * (1 - y / 20 * (1 - y / 42))};
  }
  if (y < 0) {
    const double r = std::sqrt(-y);
    return {std::cosh(r), std::sinh(r) / r};
  }
  const double r = std::sqrt(y);
  return {std::cos(r), std::sin(r) / r};
}

namespace detail {
// The first n coefficients of p(x + z) for p(x) = Σ p_k x^k: a_m = Σ_(k≥m) p_k C(k, m) z^(k−m), by
// repeated synthetic division by (x − z) (each pass is Horner's scheme; after pass m, p_m is a_m),
// n passes of p.size() multiply-adds.
inline std::vector<double> taylor_shift(std::vector<double> p, double z, std::size_t n) {
  for (std::size_t m = 0; m < n && m < p.size(); ++m)
    for (std::size_t k = p.size() - 1; k > m; --k) p[k - 1] += z * p[k];
  p.resize(n, 0.0);
  return p;
}
}  // namespace detail

// Taylor coefficients a_0 … a_(count−1) of cos√y and of sin√y/√y about y = c: for |c| ≤ 4 by
// re-centring their series about 0 (Σ (−y)^k/(2k)!, Σ (−y)^k/(2k+1)!; no cancellation there), for
// c > 4 from the derivatives, which follow from C' = −S/2 and 2y S' = C − S:
// C^(n+1) = −S^(n)/2, S^(n+1) = (C^(n) − (2n+1) S^(n)) / (2c).
struct CosSincTaylor {
  std::vector<double> cos_sqrt, sinc_sqrt;
};
inline CosSincTaylor cos_sinc_sqrt_taylor(double c, int count) {
  const auto n = static_cast<std::size_t>(count);
  CosSincTaylor t{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0)};
  if (c > 4) {
    const CosSincSqrt v = cos_sinc_sqrt(c);
    double cd = v.cos_sqrt, sd = v.sinc_sqrt, factorial = 1;
    for (std::size_t m = 0; m < n; ++m) {
      t.cos_sqrt[m] = cd / factorial;
      t.sinc_sqrt[m] = sd / factorial;
      const double next_s = (cd - (2.0 * static_cast<double>(m) + 1) * sd) / (2 * c);
      cd = -sd / 2;
      sd = next_s;
      factorial *= static_cast<double>(m + 1);
    }
    return t;
  }
  // a_m = Σ_(k≥m) b_k C(k, m) c^(k−m) (detail::taylor_shift); terms fall like |c|^k/(2k)!, 40
  // beyond m are plenty.
  const std::size_t kmax = n + 40;
  std::vector<double> bc(kmax + 1), bs(kmax + 1);  // (−1)^k/(2k)!, (−1)^k/(2k+1)!
  bc[0] = bs[0] = 1;
  for (std::size_t k = 0; k < kmax; ++k) {
    const double kd = static_cast<double>(k);
    bc[k + 1] = bc[k] * (-1.0 / ((2 * kd + 1) * (2 * kd + 2)));
    bs[k + 1] = bs[k] * (-1.0 / ((2 * kd + 2) * (2 * kd + 3)));
  }
  return {detail::taylor_shift(std::move(bc), c, n), detail::taylor_shift(std::move(bs), c, n)};
}

// θ / sin θ as a function of c = cos θ (θ = acos c ∈ [0, π)): analytic for c > −1, including
// c = 1 where it is 1. About c = 1 its Taylor coefficients solve (1 − c²) h' = c h − 1:
// g_0 = 1, g_n = −n g_(n−1) / (2n + 1) (radius 2).
inline double angle_over_sine_of_cosine(double c) {
  if (std::abs(c - 1) < 0.125) {
    double sum = 0, g = 1, power = 1;
    for (int k = 0; k < 60; ++k) {
      sum += g * power;
      g *= -(k + 1.0) / (2.0 * k + 3);
      power *= c - 1;
    }
    return sum;
  }
  return std::acos(c) / std::sqrt((1 - c) * (1 + c));
}

// Taylor coefficients of θ / sin θ (c = cos θ) about c0: for c0 ≥ −½ the series about 1
// re-centred (its terms g_k C(k, m) (c0 − 1)^(k−m) all have the sign (−1)^m: no cancellation);
// below, the recurrence from (1 − c²) h' = c h − 1:
// a_1 = (c0 a_0 − 1)/(1 − c0²), a_(n+1) = ((2n+1) c0 a_n + n a_(n−1)) / ((1 − c0²)(n+1)).
namespace detail {
// Taylor coefficients about c0 (|c0| < 1) of a solution of (1 − c²) f' = c f − r with f(c0) = f0:
// a_1 = (c0 a_0 − r)/(1 − c0²), a_(n+1) = ((2n+1) c0 a_n + n a_(n−1)) / ((1 − c0²)(n+1)).
// r = 1: θ / sin θ; r = 0: 1 / sin θ = (1 − c²)^(−1/2).
inline std::vector<double> arc_taylor(double c0, double f0, double r, std::size_t n) {
  std::vector<double> a(n, 0.0);
  const double q = (1 - c0) * (1 + c0);
  a[0] = f0;
  if (n > 1) a[1] = (c0 * a[0] - r) / q;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double kd = static_cast<double>(k);
    a[k + 1] = ((2 * kd + 1) * c0 * a[k] + kd * a[k - 1]) / (q * (kd + 1));
  }
  return a;
}
}  // namespace detail

inline std::vector<double> angle_over_sine_taylor(double c0, int count) {
  const auto n = static_cast<std::size_t>(count);
  if (c0 < -0.5) return detail::arc_taylor(c0, angle_over_sine_of_cosine(c0), 1.0, n);
  const double z = c0 - 1;
  // terms fall like (|z|/2)^k; stop when below 1e-20 of the leading one
  const double ratio = std::max(std::abs(z) / 2, 1e-3);
  const std::size_t kmax = n + static_cast<std::size_t>(std::ceil(-46.0 / std::log(ratio)));
  std::vector<double> g(kmax + 1);
  g[0] = 1;
  for (std::size_t k = 0; k < kmax; ++k)
    g[k + 1] = g[k] * (-(static_cast<double>(k) + 1) / (2.0 * static_cast<double>(k) + 3));
  return detail::taylor_shift(std::move(g), z, n);
}

// The next branch: (θ − 2π) / sin θ = h(c) − 2π / √(1 − c²) as a function of c = cos θ
// (singular at c = 1 instead of c = −1), and its Taylor coefficients about c0 ∈ (−1, 1).
inline double shifted_angle_over_sine_of_cosine(double c) {
  return angle_over_sine_of_cosine(c) - 2 * std::numbers::pi / std::sqrt((1 - c) * (1 + c));
}
inline std::vector<double> shifted_angle_over_sine_taylor(double c0, int count) {
  std::vector<double> a = angle_over_sine_taylor(c0, count);
  const std::vector<double> g = detail::arc_taylor(c0, 1 / std::sqrt((1 - c0) * (1 + c0)), 0.0,
                                                   static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < a.size(); ++k) a[k] -= 2 * std::numbers::pi * g[k];
  return a;
}

}  // namespace pgamesh::clifford
