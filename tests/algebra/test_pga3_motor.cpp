// Motors against closed forms: rotors against Rodrigues' rotation formula, translators against
// vector addition, composition against applying one motion after the other; normalisation and
// inverse; the sandwich on points, directions, planes and lines. Float and double.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

template <class T>
struct Tol;
template <>
struct Tol<double> {
  static constexpr double value = 1e-12;
};
template <>
struct Tol<float> {
  static constexpr float value = 2e-5f;
};

template <class T>
Vec3<T> random_vec(std::mt19937& rng, T scale = 1) {
  std::uniform_real_distribution<T> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

// Rodrigues: x cos θ + (a × x) sin θ + a (a·x)(1 − cos θ), a a unit axis.
template <class T>
Vec3<T> rodrigues(Vec3<T> x, Vec3<T> axis, T angle) {
  const Vec3<T> a = axis / length(axis);
  return std::cos(angle) * x + std::sin(angle) * cross(a, x) +
         (dot(a, x) * (T(1) - std::cos(angle))) * a;
}

template <class T>
void expect_near(Vec3<T> got, Vec3<T> want, T tol) {
  const T scale = std::max(T(1), length(want));
  EXPECT_NEAR(got.x, want.x, tol * scale);
  EXPECT_NEAR(got.y, want.y, tol * scale);
  EXPECT_NEAR(got.z, want.z, tol * scale);
}

template <class T>
class Pga3Motor : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Pga3Motor, Scalars);

TYPED_TEST(Pga3Motor, RotorMatchesRodrigues) {
  using T = TypeParam;
  std::mt19937 rng(7);
  std::uniform_real_distribution<T> ang(T(-6), T(6));
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> axis = random_vec<T>(rng), x = random_vec<T>(rng, T(3));
    const T angle = ang(rng);
    const Motor<T> r = rotor(angle, axis);
    EXPECT_NEAR(norm(r), T(1), Tol<T>::value);
    const Point<T> moved = apply(r, point(x));
    EXPECT_NEAR(moved.weight(), T(1), Tol<T>::value);
    expect_near(moved.euclidean(), rodrigues(x, axis, angle), Tol<T>::value);
    // Directions rotate the same way and stay ideal.
    const Point<T> dir = r(direction(x));
    EXPECT_EQ(dir.weight(), T(0));
    expect_near(dir.weighted(), rodrigues(x, axis, angle), Tol<T>::value);
  }
}

TEST(Pga3MotorFixed, QuarterTurnAboutZ) {
  // +90° about z takes x to y (right-handed, docs/conventions.md §7).
  const auto r = rotor(M_PI / 2, Vec3d{0, 0, 1});
  const Vec3d p = apply(r, point(1.0, 0.0, 0.0)).euclidean();
  EXPECT_NEAR(p.x, 0.0, 1e-15);
  EXPECT_NEAR(p.y, 1.0, 1e-15);
  EXPECT_NEAR(p.z, 0.0, 1e-15);
  // Coefficients as in docs/conventions.md §7: cos(θ/2) − sin(θ/2) e12.
  EXPECT_DOUBLE_EQ(r.s, std::cos(M_PI / 4));
  EXPECT_DOUBLE_EQ(r.e12, -std::sin(M_PI / 4));
  EXPECT_EQ(r.e23, 0.0);
  EXPECT_EQ(r.e31, 0.0);
}

TEST(Pga3MotorFixed, TranslatorCoefficientsAndOrigin) {
  const auto t = translator(Vec3d{2, -4, 6});
  EXPECT_EQ(t.s, 1.0);
  EXPECT_EQ(t.e01, -1.0);
  EXPECT_EQ(t.e02, 2.0);
  EXPECT_EQ(t.e03, -3.0);
  // T o T̃ = point(t) (docs/conventions.md §7).
  const auto p = apply(t, origin<double>());
  EXPECT_EQ(p.e123, 1.0);
  EXPECT_EQ(p.euclidean(), (Vec3d{2, -4, 6}));
}

TYPED_TEST(Pga3Motor, TranslatorMovesPointsPlanesLines) {
  using T = TypeParam;
  std::mt19937 rng(11);
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> t = random_vec<T>(rng, T(5)), x = random_vec<T>(rng, T(5));
    const Vec3<T> n = random_vec<T>(rng), dir = random_vec<T>(rng);
    const T d = random_vec<T>(rng).x;
    const Motor<T> tr = translator(t);
    expect_near(apply(tr, point(x)).euclidean(), x + t, Tol<T>::value);
    expect_near(apply(tr, direction(x)).weighted(), x, Tol<T>::value);
    // Plane n·x + d = 0 moved by t is n·x + (d − n·t) = 0.
    const Plane<T> p = apply(tr, plane(n, d));
    expect_near(p.normal(), n, Tol<T>::value);
    EXPECT_NEAR(p.e0, d - dot(n, t), Tol<T>::value * 10);
    // The line through x along dir moves to the line through x + t along dir.
    const Line<T> l = apply(tr, line_through(x, dir));
    const Line<T> want = line_through(x + t, dir);
    expect_near(l.direction(), want.direction(), Tol<T>::value);
    expect_near(l.moment(), want.moment(), Tol<T>::value * 10);
  }
}

// A general rigid motion: the sandwich of points agrees with R then T in closed form, and the
// sandwich of planes and lines agrees with joining the moved points.
TYPED_TEST(Pga3Motor, ScrewMovesJoinsConsistently) {
  using T = TypeParam;
  std::mt19937 rng(13);
  std::uniform_real_distribution<T> ang(T(-3), T(3));
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> axis = random_vec<T>(rng), t = random_vec<T>(rng, T(4));
    const T angle = ang(rng);
    const Motor<T> m = translator(t) * rotor(angle, axis);
    const Vec3<T> a = random_vec<T>(rng, T(2)), b = random_vec<T>(rng, T(2)),
                  c = random_vec<T>(rng, T(2));
    const Point<T> ma = m(point(a)), mb = m(point(b)), mc = m(point(c));
    expect_near(ma.euclidean(), rodrigues(a, axis, angle) + t, Tol<T>::value * 10);
    // Join then move = move then join (motors are automorphisms of the algebra).
    const Line<T> l = apply(m, point(a) & point(b)), l2 = ma & mb;
    expect_near(l.direction(), l2.direction(), Tol<T>::value * 10);
    expect_near(l.moment(), l2.moment(), Tol<T>::value * 50);
    const Plane<T> p = apply(m, point(a) & point(b) & point(c)), p2 = ma & mb & mc;
    expect_near(p.normal(), p2.normal(), Tol<T>::value * 20);
    EXPECT_NEAR(p.e0, p2.e0, Tol<T>::value * 200);
  }
}

TYPED_TEST(Pga3Motor, CompositionAppliesRightFactorFirst) {
  using T = TypeParam;
  std::mt19937 rng(17);
  std::uniform_real_distribution<T> ang(T(-3), T(3));
  for (int i = 0; i < 200; ++i) {
    const Motor<T> a = translator(random_vec<T>(rng)) * rotor(ang(rng), random_vec<T>(rng));
    const Motor<T> b = rotor(ang(rng), random_vec<T>(rng)) * translator(random_vec<T>(rng));
    const Vec3<T> x = random_vec<T>(rng, T(3));
    const Point<T> both = apply(a * b, point(x)), seq = apply(a, apply(b, point(x)));
    expect_near(both.euclidean(), seq.euclidean(), Tol<T>::value * 20);
    // M M̃ = 1 for products of rotors and translators.
    const Motor<T> one = (a * b) * ~(a * b);
    EXPECT_NEAR(one.s, T(1), Tol<T>::value);
    for (T v : {one.e01, one.e02, one.e03, one.e12, one.e31, one.e23, one.e0123})
      EXPECT_NEAR(v, T(0), Tol<T>::value * 10);
  }
}

TYPED_TEST(Pga3Motor, NormalizedAndInverse) {
  using T = TypeParam;
  std::mt19937 rng(19);
  std::uniform_real_distribution<T> coef(T(-1), T(1));
  for (int i = 0; i < 200; ++i) {
    // An arbitrary even element: no Study condition, no unit weight.
    Motor<T> m;
    for (T* x : {&m.s, &m.e01, &m.e02, &m.e03, &m.e12, &m.e31, &m.e23, &m.e0123}) *x = coef(rng);
    if (norm(m) < T(0.2)) continue;
    const Motor<T> n = normalized(m);
    const Motor<T> nn = n * ~n;  // = 1 exactly (also the e0123 part)
    EXPECT_NEAR(nn.s, T(1), Tol<T>::value * 10);
    EXPECT_NEAR(nn.e0123, T(0), Tol<T>::value * 50);
    for (const Motor<T>& one : {m * inverse(m), inverse(m) * m}) {
      EXPECT_NEAR(one.s, T(1), Tol<T>::value * 50);
      for (T v : {one.e01, one.e02, one.e03, one.e12, one.e31, one.e23, one.e0123})
        EXPECT_NEAR(v, T(0), Tol<T>::value * 100);
    }
    // A normalized motor moves points rigidly: distances are kept.
    const Vec3<T> a = random_vec<T>(rng, T(2)), b = random_vec<T>(rng, T(2));
    const T moved = length(n(point(a)).euclidean() - n(point(b)).euclidean());
    EXPECT_NEAR(moved, length(a - b), Tol<T>::value * 50);
  }
}

TEST(Pga3MotorFixed, ZeroAxisRotorIsIdentity) {
  EXPECT_EQ(rotor(1.0, Vec3d{0, 0, 0}), (Motor<double>{.s = 1}));
  EXPECT_EQ(identity_motor<double>(), (Motor<double>{.s = 1}));
  EXPECT_EQ(apply(identity_motor<double>(), point(1.0, 2.0, 3.0)), point(1.0, 2.0, 3.0));
  EXPECT_EQ(normalized(Motor<double>{}), Motor<double>{});
}

TEST(Pga3MotorFixed, LinearOperations) {
  const auto p = plane(1.0, 2.0, 3.0, 4.0), q = plane(-1.0, 0.5, 0.0, 2.0);
  EXPECT_EQ(p + q, plane(0.0, 2.5, 3.0, 6.0));
  EXPECT_EQ(p - q, plane(2.0, 1.5, 3.0, 2.0));
  EXPECT_EQ(2.0 * p, plane(2.0, 4.0, 6.0, 8.0));
  EXPECT_EQ(p / 2.0, plane(0.5, 1.0, 1.5, 2.0));
  EXPECT_EQ(-p, plane(-1.0, -2.0, -3.0, -4.0));
  Point<double> sum{};
  sum += point(1.0, 2.0, 3.0);
  sum += point(3.0, 2.0, 1.0);
  EXPECT_EQ(sum.weight(), 2.0);
  EXPECT_EQ(sum.euclidean(), (Vec3d{2, 2, 2}));
}

}  // namespace
}  // namespace pgamesh::pga3
