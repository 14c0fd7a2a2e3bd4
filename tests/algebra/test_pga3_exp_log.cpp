// Motor exponential, logarithm and square root in closed form: against the rotor/translator
// constructors, against the power series of the general product, exp(log M) = M and
// log(exp B) = B for screws, pure rotations, pure translations and tiny angles (no NaN), and the
// motor taking one plane, line or point to another. Float and double.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

using namespace pgamesh::test;

template <class T>
class Pga3ExpLog : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Pga3ExpLog, Scalars);

template <class T>
T tol() {
  return std::is_same_v<T, float> ? T(2e-5) : T(1e-13);
}

template <class T>
::testing::AssertionResult motor_near(const Motor<T>& a, const Motor<T>& b, T eps) {
  return mv_near(to_multivector(a), to_multivector(b),
                 double(eps) / (64 * double(std::numeric_limits<T>::epsilon())));
}

template <class T>
bool finite(const Motor<T>& m) {
  for (T x : to_multivector(m).c)
    if (!std::isfinite(x)) return false;
  return true;
}

// Random screw bivector: direction of length up to `angle_scale`, arbitrary moment.
template <class T>
Line<T> random_bivector(std::mt19937& r, T angle_scale, T moment_scale = T(2)) {
  Line<T> b = random_line<T>(r);
  const Vec3<T> l = b.direction() * angle_scale, m = b.moment() * moment_scale;
  return line_from_plucker(l, m);
}

TYPED_TEST(Pga3ExpLog, ExpMatchesRotorAndTranslator) {
  using T = TypeParam;
  std::mt19937 r(21);
  for (int i = 0; i < 100; ++i) {
    const Vec3<T> axis = random_line<T>(r).direction(), t = random_line<T>(r).moment();
    const T angle = Num<T>::random(r) * T(6);
    const Vec3<T> a = axis / length(axis);
    // rotor(θ, a) = exp(−θ/2 (a_x e23 + a_y e31 + a_z e12)) (docs/conventions.md §7).
    EXPECT_TRUE(motor_near(exp(line_from_plucker((-angle / 2) * a, Vec3<T>{})), rotor(angle, axis),
                           tol<T>()));
    // translator(t) = exp(−½ t·(e01, e02, e03)).
    EXPECT_TRUE(
        motor_near(exp(line_from_plucker(Vec3<T>{}, T(-0.5) * t)), translator(t), tol<T>()));
  }
}

// exp(B) against Σ Bᵏ/k! with the general 16-component product (double only: the series is
// the reference).
TEST(Pga3ExpLogFixed, ExpMatchesPowerSeries) {
  std::mt19937 r(22);
  for (int i = 0; i < 50; ++i) {
    const Line<double> b = random_bivector<double>(r, 1.5);
    const Multivector<double> bm = to_multivector(b);
    Multivector<double> sum = scalar(1.0), term = scalar(1.0);
    for (int k = 1; k < 40; ++k) {
      term = term * bm / double(k);
      sum = sum + term;
    }
    EXPECT_TRUE(mv_near(to_multivector(exp(b)), sum, 4)) << i;
  }
}

TYPED_TEST(Pga3ExpLog, ExpLogRoundTripOnScrews) {
  using T = TypeParam;
  std::mt19937 r(23);
  for (int i = 0; i < 200; ++i) {
    // Half-angle |l| < π/2 ... just under π: log returns the bivector itself.
    const Line<T> b = random_bivector<T>(r, T(1.7));
    const Motor<T> m = exp(b);
    EXPECT_TRUE(motor_near(m * ~m, identity_motor<T>(), 4 * tol<T>()));
    const Line<T> back = log(m);
    EXPECT_TRUE(mv_near(to_multivector(back), to_multivector(b), 100)) << i;
    EXPECT_TRUE(motor_near(exp(back), m, 4 * tol<T>()));
  }
}

TYPED_TEST(Pga3ExpLog, TinyAnglesAndPureTranslations) {
  using T = TypeParam;
  std::mt19937 r(24);
  const T angles[] = {T(0),   T(1e-30), T(1e-12), T(1e-7),   T(1e-4), T(0.01),
                      T(0.1), T(0.5),   T(0.999), T(1.0001), T(1.2)};
  for (T half_angle : angles) {
    for (int i = 0; i < 20; ++i) {
      const Vec3<T> axis = random_line<T>(r).direction();
      const Vec3<T> l = (half_angle / length(axis)) * axis;
      const Line<T> b = line_from_plucker(l, random_line<T>(r).moment());
      const Motor<T> m = exp(b);
      ASSERT_TRUE(finite(m)) << half_angle;
      const Line<T> back = log(m);
      ASSERT_TRUE(finite(exp(back)));
      EXPECT_TRUE(mv_near(to_multivector(back), to_multivector(b), 10)) << half_angle;
      // The series/direct switch at θ = 1 is seamless: compare with the general series.
      if constexpr (std::is_same_v<T, double>) {
        const Multivector<double> bm = to_multivector(b);
        Multivector<double> sum = scalar(1.0), term = scalar(1.0);
        for (int k = 1; k < 30; ++k) {
          term = term * bm / double(k);
          sum = sum + term;
        }
        EXPECT_TRUE(mv_near(to_multivector(m), sum, 2)) << half_angle;
      }
    }
  }
  // Identity and pure translations: no NaN, exact translator.
  EXPECT_EQ(exp(Line<T>{}), identity_motor<T>());
  const Line<T> zero = log(identity_motor<T>());
  EXPECT_EQ(zero, Line<T>{});
  const Vec3<T> t{T(3), T(-1), T(2)};
  const Line<T> lt = log(translator(t));
  EXPECT_EQ(lt, line_from_plucker(Vec3<T>{}, T(-0.5) * t));
}

// exp's factors cos θ, sinc θ (series in θ² up to θ = π/2, libm beyond) against long double's
// cosl and sinl, on both sides of π/2: within 2.3e−16 of the reference (one ulp of 1 is 2.2e−16).
TEST(Pga3ExpLogFixed, ExpFactorsMatchExtendedPrecision) {
  for (long double t = 0.0L; t < 3.2L; t += 0.0007L) {
    const detail::ExpFactors<double> f = detail::exp_factors(double(t * t));
    const long double theta = std::sqrt(static_cast<long double>(double(t * t)));
    const long double sinc = theta == 0 ? 1.0L : std::sin(theta) / theta;
    EXPECT_NEAR(f.cos, double(std::cos(theta)), 2.3e-16) << double(t);
    EXPECT_NEAR(f.sinc, double(sinc), 2.3e-16) << double(t);
  }
  const detail::ExpFactors<float> g = detail::exp_factors(1.5f);
  EXPECT_NEAR(g.cos, std::cos(std::sqrt(1.5)), 2e-7);
  EXPECT_NEAR(g.sinc, std::sin(std::sqrt(1.5)) / std::sqrt(1.5), 2e-7);
}

// Both branches of (cos θ − sinc θ)/θ² (series below θ = π/2) against long double references:
// the direct formula above θ = 0.05 (64-bit mantissa; the cancellation costs log10(1/θ²) < 3 of
// its ~19 digits), 12 terms of the series below.
TEST(Pga3ExpLogFixed, SeriesBranchMatchesExtendedPrecision) {
  for (long double t = 0.001L; t < 4.0L; t *= 1.07L) {
    long double ref = 0;
    if (t > 0.05L) {
      ref = (std::cos(t) - std::sin(t) / t) / (t * t);
    } else {
      long double fact = 6, sign = -1, power = 1;  // (2k+1)!, (−1)^k, θ^(2k−2) for k = 1
      for (int k = 1; k <= 12; ++k) {
        ref += sign * 2 * k / fact * power;
        fact *= (2 * k + 2) * (2 * k + 3);
        sign = -sign;
        power *= t * t;
      }
    }
    const double got = detail::cos_minus_sinc_over_sq(double(t));
    EXPECT_NEAR(got, double(ref), 4e-16) << double(t);
  }
  EXPECT_DOUBLE_EQ(detail::cos_minus_sinc_over_sq(0.0), -1.0 / 3);
  EXPECT_EQ(detail::sinc(0.0), 1.0);
  EXPECT_EQ(detail::sinc(1e-300), 1.0);
}

TEST(Pga3ExpLogFixed, HalfTurnsAndFullTurns) {
  // A half turn about z through (1, 0, 0): θ/2 = π/2, log recovers the axis line.
  const Line<double> axis = line_through(Vec3d{1, 0, 0}, Vec3d{0, 0, 1});
  const Motor<double> half = rotor(M_PI, axis);
  const Vec3d p = half(point(2.0, 0.0, 5.0)).euclidean();
  EXPECT_NEAR(p.x, 0.0, 1e-15);
  EXPECT_NEAR(p.y, 0.0, 1e-15);
  EXPECT_NEAR(p.z, 5.0, 1e-15);
  EXPECT_TRUE(mv_near(to_multivector(log(half)), to_multivector((-M_PI / 2) * axis)));
  // A full turn about the same axis is −1 (θ/2 = π): finite, and exp(log) returns it.
  const Motor<double> full{.s = -1};
  const Line<double> lf = log(full);
  EXPECT_TRUE(finite(exp(lf)));
  EXPECT_TRUE(mv_near(to_multivector(exp(lf)), to_multivector(full)));
  const Motor<double> full_shift = translator(Vec3d{0, 0, 2}) * full;
  EXPECT_TRUE(mv_near(to_multivector(exp(log(full_shift))), to_multivector(full_shift)));
}

TYPED_TEST(Pga3ExpLog, SquareRoot) {
  using T = TypeParam;
  std::mt19937 r(25);
  for (int i = 0; i < 100; ++i) {
    const Motor<T> m = exp(random_bivector<T>(r, T(1.4)));
    const Motor<T> h = sqrt(m);
    EXPECT_TRUE(motor_near(h * h, m, 4 * tol<T>()));
    EXPECT_TRUE(motor_near(h, exp(T(0.5) * log(m)), 4 * tol<T>()));
  }
}

template <class T, class X>
::testing::AssertionResult same_up_to_scale(const X& got, const X& want) {
  // Compare normalized elements (a motor between normalized objects returns normalized ones).
  return mv_near(to_multivector(normalized(got)), to_multivector(normalized(want)),
                 std::is_same_v<T, float> ? 200 : 50);
}

TYPED_TEST(Pga3ExpLog, MotorBetweenPlanesLinesPoints) {
  using T = TypeParam;
  std::mt19937 r(26);
  for (int i = 0; i < 100; ++i) {
    const Motor<T> move = exp(random_bivector<T>(r, T(1.2)));
    const Plane<T> pa = random_plane<T>(r), pb = apply(move, pa);
    const Motor<T> mp = motor_between(pa, pb);
    EXPECT_TRUE((same_up_to_scale<T>(apply(mp, pa), pb)));
    const Line<T> la = line_through(random_line<T>(r).moment(), random_line<T>(r).direction());
    const Line<T> lb = apply(move, la);
    const Motor<T> ml = motor_between(la, lb);
    EXPECT_TRUE((same_up_to_scale<T>(apply(ml, la), lb)));
    const Point<T> va = point(random_line<T>(r).moment()), vb = point(random_line<T>(r).moment());
    const Motor<T> mv = motor_between(va, vb);
    EXPECT_TRUE((same_up_to_scale<T>(apply(mv, va), vb)));
    // Between points it is the translator by their difference.
    EXPECT_TRUE(motor_near(mv, translator(vb.euclidean() - va.euclidean()), 4 * tol<T>()));
  }
}

}  // namespace
}  // namespace pgamesh::pga3
