// Scalar closed forms behind exp and log of bivectors, shared by the general engine and the
// compile-time PGA R(d,0,1), so each formula lives in one place.
#pragma once

#include <cmath>

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

}  // namespace pgamesh::clifford
