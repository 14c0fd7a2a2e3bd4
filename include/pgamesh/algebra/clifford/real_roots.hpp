// Real roots of a polynomial whose roots are all real (the characteristic polynomials of the
// commuting parts of a bivector or motor: squared rotation angles, cosines of the angle sums).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pgamesh::clifford {

// Value of the polynomial Σ coeffs[i] x^i (Horner).
inline double polynomial_value(const std::vector<double>& coeffs, double x) {
  double v = 0;
  for (std::size_t i = coeffs.size(); i-- > 0;) v = v * x + coeffs[i];
  return v;
}

// The n roots, ascending, of the degree-n polynomial Σ coeffs[i] x^i (coeffs[n] ≠ 0) when all of
// them are real and lie in [lo, hi]. By Rolle the critical points c_1 ≤ … ≤ c_(n−1) interlace the
// roots, so with c_0 = lo and c_n = hi root i lies in [c_(i−1), c_i]: bisection when p changes
// sign there, else the root is multiple and sits at the critical point where |p| is least. Found
// recursively from the derivative; no iteration can diverge and multiple roots come out as
// accurately as the data allow (ε^(1/m) for an m-fold root).
inline std::vector<double> real_roots(const std::vector<double>& coeffs, double lo, double hi) {
  const std::size_t n = coeffs.size() - 1;
  if (n == 0) return {};
  if (n == 1) return {std::clamp(-coeffs[0] / coeffs[1], lo, hi)};
  std::vector<double> derivative(n);
  for (std::size_t i = 1; i <= n; ++i) derivative[i - 1] = static_cast<double>(i) * coeffs[i];
  std::vector<double> ends = {lo};
  for (double c : real_roots(derivative, lo, hi)) ends.push_back(c);
  ends.push_back(hi);
  std::vector<double> roots;
  for (std::size_t i = 0; i < n; ++i) {
    double a = ends[i], b = ends[i + 1];
    double pa = polynomial_value(coeffs, a), pb = polynomial_value(coeffs, b);
    if ((pa < 0) == (pb < 0) || pa == 0 || pb == 0) {
      roots.push_back(std::abs(pa) <= std::abs(pb) ? a : b);
      continue;
    }
    for (int it = 0; it < 200 && b - a > 0; ++it) {
      const double m = 0.5 * (a + b);
      if (m <= a || m >= b) break;
      const double pm = polynomial_value(coeffs, m);
      if (pm == 0) {
        a = b = m;
        break;
      }
      if ((pm < 0) == (pa < 0)) {
        a = m;
        pa = pm;
      } else {
        b = m;
      }
    }
    roots.push_back(0.5 * (a + b));
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

// The three roots, ascending, of x³ − e1 x² + e2 x − e3 when all are real (Viète's
// trigonometric form): x = e1/3 + z with z³ + p z + q = 0, p = e2 − e1²/3 ≤ 0,
// q = −2 e1³/27 + e1 e2/3 − e3, z_k = 2 √(−p/3) cos(φ/3 − 2πk/3), cos φ = (3q / 2p) √(−3/p).
// The roots sum to e1 to round-off and a (nearly) triple root spreads only by √(|p|), i.e. by
// √ε of the scale rather than the ε^(1/3) of an iteration on the polynomial.
inline std::array<double, 3> cubic_real_roots(double e1, double e2, double e3) {
  const double shift = e1 / 3;
  const double p = e2 - e1 * shift;
  const double q = (-2.0 / 27) * e1 * e1 * e1 + e1 * e2 / 3 - e3;
  if (!(p < 0)) return {shift, shift, shift};
  const double r = std::sqrt(-p / 3);
  const double phi = std::acos(std::clamp(1.5 * q / (p * r), -1.0, 1.0));
  constexpr double third = 2.0943951023931957;  // 2π/3
  std::array<double, 3> x = {shift + 2 * r * std::cos(phi / 3),
                             shift + 2 * r * std::cos(phi / 3 - third),
                             shift + 2 * r * std::cos(phi / 3 - 2 * third)};
  std::sort(x.begin(), x.end());
  return x;
}

}  // namespace pgamesh::clifford
