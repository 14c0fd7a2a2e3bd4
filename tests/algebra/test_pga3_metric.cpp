// Meets, the plane side test, projections, distances and angles against vector-algebra closed
// forms (paper eqs. 4.10, 4.11): feet of perpendiculars, point–line and line–line distances,
// angles from normalized dot products, and the parallel line–plane case (an ideal point).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

using namespace pgamesh::test;

template <class T>
class Pga3Metric : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Pga3Metric, Scalars);

template <class T>
void expect_vec_near(Vec3<T> got, Vec3<T> want, T eps) {
  const T s = std::max(T(1), length(want));
  EXPECT_NEAR(got.x, want.x, eps * s);
  EXPECT_NEAR(got.y, want.y, eps * s);
  EXPECT_NEAR(got.z, want.z, eps * s);
}

// Angles from atan2 against acos of a dot product: acos loses digits near 0 and π.
template <class T>
T metric_angle_tol() {
  return std::is_same_v<T, float> ? T(1e-3) : T(1e-7);
}

template <class T>
T clamp_acos(T c) {
  return std::acos(std::max(T(-1), std::min(T(1), c)));
}

TYPED_TEST(Pga3Metric, ProjectionsOfPoints) {
  using T = TypeParam;
  std::mt19937 r(31);
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> n = rvec<T>(r), x = rvec<T>(r, T(3)), q = rvec<T>(r), dir = rvec<T>(r);
    const T d = Num<T>::random(r);
    // Foot on the plane n·x + d = 0: x − (n·x + d) n/|n|².
    const Vec3<T> foot = x - ((dot(n, x) + d) / dot(n, n)) * n;
    const Point<T> f = project(point(x), plane(n, d));
    expect_vec_near(f.euclidean(), foot, 8 * tol<T>());
    EXPECT_NEAR(signed_distance(plane(n, d), point(x)), (dot(n, x) + d) / length(n),
                8 * tol<T>() * std::max(T(1), length(x)));
    // Foot on the line through q along dir: q + ((x − q)·u) u.
    const Vec3<T> u = dir / length(dir);
    const Vec3<T> foot_l = q + dot(x - q, u) * u;
    const Line<T> l = line_through(q, dir);
    expect_vec_near(project(point(x), l).euclidean(), foot_l, 8 * tol<T>());
    EXPECT_NEAR(distance(l, point(x)), length(cross(x - q, u)), 8 * tol<T>());
    EXPECT_NEAR(distance(point(x), point(q)), length(x - q), 4 * tol<T>());
    // Plane through x parallel to p, line through x parallel to l: same orientation.
    const Plane<T> px = project(plane(n, d), point(x));
    EXPECT_NEAR(side(px, point(x)), T(0), 8 * tol<T>());
    expect_vec_near(px.normal(), n, tol<T>());
    const Line<T> lx = project(l, point(x));
    expect_vec_near(lx.direction(), dir, tol<T>());
    EXPECT_NEAR(distance(lx, point(x)), T(0), 8 * tol<T>());
  }
}

TYPED_TEST(Pga3Metric, LineDistancesAndAngles) {
  using T = TypeParam;
  std::mt19937 r(32);
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> q1 = rvec<T>(r), d1 = rvec<T>(r), q2 = rvec<T>(r), d2 = rvec<T>(r);
    const Line<T> a = line_through(q1, d1), b = line_through(q2, d2);
    const Vec3<T> c = cross(d1, d2);
    // Skew lines: |(q2 − q1)·(d1 × d2)| / |d1 × d2|.
    if (length(c) > T(0.1) * length(d1) * length(d2)) {
      EXPECT_NEAR(distance(a, b), std::abs(dot(q2 - q1, c)) / length(c), 16 * tol<T>());
    }
    // Parallel lines: distance of q2 from a.
    const Line<T> b_par = line_through(q2, T(-2) * d1);
    EXPECT_NEAR(distance(a, b_par), length(cross(q2 - q1, d1)) / length(d1), 16 * tol<T>());
    EXPECT_NEAR(angle(a, b), clamp_acos(dot(d1, d2) / (length(d1) * length(d2))),
                metric_angle_tol<T>());
    const Vec3<T> n = rvec<T>(r);
    const Plane<T> p = plane(n, T(0.5)), p2 = plane(d1, T(-1));
    EXPECT_NEAR(angle(p, p2), clamp_acos(dot(n, d1) / (length(n) * length(d1))),
                metric_angle_tol<T>());
    // Line–plane angle = π/2 − angle(direction, normal), folded into [0, π/2].
    const T to_normal = clamp_acos(std::abs(dot(d1, n)) / (length(d1) * length(n)));
    EXPECT_NEAR(angle(a, p), T(M_PI / 2) - to_normal, metric_angle_tol<T>());
    // Projection of a line onto a plane lies in the plane, along d − n (n·d)/|n|².
    const Line<T> pr = project(a, p);
    const Vec3<T> dp = d1 - (dot(n, d1) / dot(n, n)) * n;
    EXPECT_NEAR(length(cross(pr.direction(), dp)), T(0), 32 * tol<T>() * dot(n, n));
    const Point<T> on = project(point(q1), p);
    EXPECT_NEAR(distance(pr, on), T(0), 32 * tol<T>());
  }
}

TEST(Pga3MetricFixed, MeetLineParallelToPlaneIsIdeal) {
  // Paper eq. 4.11 with W = n·l = 0: an ideal point along the line, never a NaN.
  const Line<double> l = point(0.0, 0.0, 1.0) & point(1.0, 2.0, 1.0);
  const Plane<double> p = plane(0.0, 0.0, 1.0, -3.0);
  const Point<double> x = l ^ p;
  EXPECT_EQ(x.weight(), 0.0);
  EXPECT_GT(ideal_norm(x), 0.0);
  const Vec3d dir = x.weighted() / ideal_norm(x);
  EXPECT_NEAR(std::abs(dot(dir, Vec3d{1, 2, 0})) / std::sqrt(5.0), 1.0, 1e-15);
  EXPECT_EQ(angle(l, p), 0.0);
}

TEST(Pga3MetricFixed, SideTest) {
  // Eq. 4.10: p ∨ v = a x + b y + c z + d; positive on the normal's side.
  const Plane<double> p = plane(1.0, 2.0, 3.0, 4.0);
  EXPECT_EQ(side(p, point(1.0, 1.0, 1.0)), 10.0);
  EXPECT_EQ(side(p, point(-4.0, 0.0, 0.0)), 0.0);
  EXPECT_LT(side(p, point(-5.0, 0.0, 0.0)), 0.0);
}

}  // namespace
}  // namespace pgamesh::pga3
