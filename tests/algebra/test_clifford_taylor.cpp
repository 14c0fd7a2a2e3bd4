// Taylor coefficients and divided differences behind pgad's closed-form exp and log: the
// re-centred series (synthetic division) against the independent derivative recurrences on both
// sides of the switch between them, and divided differences against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/divided_differences.hpp"

namespace clifford = pgamesh::clifford;

namespace {

double relative_diff(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::abs(b));
}

}  // namespace

TEST(CliffordTaylor, ShiftOfACubic) {
  // (x + z)³ = z³ + 3z² x + 3z x² + x³
  const double z = -1.5;
  const std::vector<double> a = clifford::detail::taylor_shift({0, 0, 0, 1}, z, 4);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_DOUBLE_EQ(a[0], z * z * z);
  EXPECT_DOUBLE_EQ(a[1], 3 * z * z);
  EXPECT_DOUBLE_EQ(a[2], 3 * z);
  EXPECT_DOUBLE_EQ(a[3], 1);
}

TEST(CliffordTaylor, CosSincAgreeAcrossTheSwitchToTheDerivativeRecurrence) {
  // c ≤ 4: the series about 0 re-centred; c > 4: C' = −S/2, 2y S' = C − S
  const clifford::CosSincTaylor below = clifford::cos_sinc_sqrt_taylor(4 - 1e-12, 12);
  const clifford::CosSincTaylor above = clifford::cos_sinc_sqrt_taylor(4 + 1e-12, 12);
  for (std::size_t m = 0; m < 12; ++m) {
    const double scale = std::pow(4.0, static_cast<double>(m));  // coefficients fall like 1/4^m
    EXPECT_LT(std::abs(below.cos_sqrt[m] - above.cos_sqrt[m]) * scale, 1e-12) << m;
    EXPECT_LT(std::abs(below.sinc_sqrt[m] - above.sinc_sqrt[m]) * scale, 1e-12) << m;
  }
  // and the closed-form values and first derivatives at y = 1: cos 1, −sin 1 / 2
  const clifford::CosSincTaylor at1 = clifford::cos_sinc_sqrt_taylor(1.0, 2);
  EXPECT_LT(relative_diff(at1.cos_sqrt[0], std::cos(1.0)), 1e-15);
  EXPECT_LT(relative_diff(at1.cos_sqrt[1], -std::sin(1.0) / 2), 1e-15);
  EXPECT_LT(relative_diff(at1.sinc_sqrt[0], std::sin(1.0)), 1e-15);
}

TEST(CliffordTaylor, AngleOverSineAgreesAcrossTheSwitchToTheRecurrence) {
  // c0 ≥ −½: the series about 1 re-centred; below: (1 − c²) h' = c h − 1
  const std::vector<double> below = clifford::angle_over_sine_taylor(-0.5 - 1e-12, 10);
  const std::vector<double> above = clifford::angle_over_sine_taylor(-0.5 + 1e-12, 10);
  // the centres differ by 2e-12: a_m moves by ≈ 2e-12 (m + 1) a_(m+1)
  for (std::size_t m = 0; m < 10; ++m) EXPECT_LT(relative_diff(above[m], below[m]), 1e-10) << m;
  // h(cos θ) = θ / sin θ at cos θ = −½ + 1e-12
  const double theta = std::acos(-0.5 + 1e-12);
  EXPECT_LT(relative_diff(above[0], theta / std::sin(theta)), 1e-14);
}

TEST(CliffordTaylor, DividedDifferencesOfExpAtClusteredNodes) {
  // exp[x_0 … x_n] at coincident nodes is e^c / n!; at nodes c, c + h: (e^(c+h) − e^c) / h
  auto value = [](double x) { return std::exp(x); };
  auto taylor = [](double c, int count) {
    std::vector<double> a(static_cast<std::size_t>(count));
    double f = std::exp(c);
    for (std::size_t m = 0; m < a.size(); ++m) {
      a[m] = f;
      f /= static_cast<double>(m + 1);
    }
    return a;
  };
  auto width = [](double) { return 0.5; };
  const std::vector<double> same =
      clifford::divided_differences({0.3, 0.3, 0.3}, value, taylor, width);
  EXPECT_LT(relative_diff(same[1], std::exp(0.3)), 1e-15);
  EXPECT_LT(relative_diff(same[2], std::exp(0.3) / 2), 1e-15);
  for (double h : {0.4, 1e-2, 1e-5, 1e-9}) {
    const std::vector<double> pair =
        clifford::divided_differences({0.3, 0.3 + h}, value, taylor, width);
    // e^0.3 (e^h − 1)/h without cancellation
    EXPECT_LT(relative_diff(pair[1], std::exp(0.3) * std::expm1(h) / h), 2e-15) << h;
  }
}
