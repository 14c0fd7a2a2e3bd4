// Algebraic identities on random inputs, float and double: associativity of the geometric
// product, reverse as an anti-automorphism, the join/meet duality (A ∨ B)* = A* ∧ B* (paper
// eq. 2.2), (A*)^(−*) = A, motors preserving distances and angles, and the norms of joins giving
// lengths, areas and volumes (paper Tables 3 and 4) against Heron's formula and triple products.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

using namespace pgamesh::test;

template <class T>
class Pga3Identities : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Pga3Identities, Scalars);

// Angles from atan2 against acos of a dot product: acos loses digits near 0 and π.
template <class T>
T angle_tol() {
  return std::is_same_v<T, float> ? T(1e-3) : T(1e-9);
}

TYPED_TEST(Pga3Identities, GeometricProductIsAssociative) {
  using T = TypeParam;
  std::mt19937 r(41);
  for (int i = 0; i < 100; ++i) {
    const auto a = random_multivector<T>(r), b = random_multivector<T>(r),
               c = random_multivector<T>(r);
    EXPECT_TRUE(mv_near((a * b) * c, a * (b * c), 8));
    EXPECT_TRUE(mv_near((a ^ b) ^ c, a ^ (b ^ c), 8));
    EXPECT_TRUE(mv_near((a & b) & c, a & (b & c), 8));
    EXPECT_TRUE(mv_near(~(a * b), ~b * ~a, 4));
    EXPECT_TRUE(mv_near(grade_involution(a * b), grade_involution(a) * grade_involution(b), 4));
  }
}

TYPED_TEST(Pga3Identities, JoinMeetDuality) {
  using T = TypeParam;
  std::mt19937 r(42);
  for (int i = 0; i < 100; ++i) {
    const auto a = random_multivector<T>(r), b = random_multivector<T>(r);
    EXPECT_TRUE(mv_near(dual(a & b), dual(a) ^ dual(b), 4));
    EXPECT_TRUE(mv_near(undual(dual(a)), a));
    EXPECT_TRUE(mv_near(dual(undual(a)), a));
    // The grade types: the dual of a join of points is the meet of their dual planes.
    const auto u = random_point<T>(r), v = random_point<T>(r), w = random_point<T>(r);
    EXPECT_TRUE(mv_near(to_multivector(dual(u & v)), to_multivector(dual(u) ^ dual(v))));
    EXPECT_TRUE(mv_near(to_multivector(dual(join(u, v, w))),
                        to_multivector(meet(dual(u), dual(v), dual(w))), 4));
    const auto p = random_plane<T>(r);
    const auto l = random_line<T>(r);
    EXPECT_EQ(undual(dual(p)), p);
    EXPECT_EQ(undual(dual(l)), l);
    EXPECT_EQ(undual(dual(u)), u);
  }
}

TYPED_TEST(Pga3Identities, MotorsPreserveDistancesAndAngles) {
  using T = TypeParam;
  std::mt19937 r(43);
  for (int i = 0; i < 200; ++i) {
    const Motor<T> m =
        exp(line_from_plucker(rvec<T>(r, T(1.5)), rvec<T>(r, T(3))));  // a general screw
    const Vec3<T> a = rvec<T>(r), b = rvec<T>(r), c = rvec<T>(r);
    const Point<T> pa = point(a), pb = point(b), pc = point(c);
    EXPECT_NEAR(distance(m(pa), m(pb)), distance(pa, pb), 16 * tol<T>());
    const Plane<T> p = pa & pb & pc, q = plane(rvec<T>(r), Num<T>::random(r));
    EXPECT_NEAR(angle(m(p), m(q)), angle(p, q), angle_tol<T>());
    EXPECT_NEAR(signed_distance(m(q), m(pa)), signed_distance(q, pa), 32 * tol<T>());
    const Line<T> l = pa & pb, k = pc & point(rvec<T>(r));
    EXPECT_NEAR(angle(m(l), m(k)), angle(l, k), angle_tol<T>());
    EXPECT_NEAR(distance(m(l), m(k)), distance(l, k), 64 * tol<T>());
    EXPECT_NEAR(distance(m(l), m(pc)), distance(l, pc), 32 * tol<T>());
  }
}

// Heron's formula, with the sides sorted for accuracy (Kahan).
template <class T>
T heron(Vec3<T> a, Vec3<T> b, Vec3<T> c) {
  T x = length(b - c), y = length(c - a), z = length(a - b);
  if (x < y) std::swap(x, y);
  if (y < z) std::swap(y, z);
  if (x < y) std::swap(x, y);
  return std::sqrt((x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z))) / 4;
}

TYPED_TEST(Pga3Identities, NormsOfJoinsAreMagnitudes) {
  using T = TypeParam;
  std::mt19937 r(44);
  const Vec3<T> o{};
  for (int i = 0; i < 200; ++i) {
    const Vec3<T> a = rvec<T>(r), b = rvec<T>(r), c = rvec<T>(r), d = rvec<T>(r);
    const Point<T> pa = point(a), pb = point(b), pc = point(c), pd = point(d);
    // Table 3: ‖edge‖ = length, ‖face‖ = 2 area, tetrahedron = 6 signed volume.
    EXPECT_NEAR(norm(pa & pb), length(b - a), 4 * tol<T>());
    EXPECT_NEAR(norm(pa & pb & pc), 2 * heron(a, b, c), 16 * tol<T>());
    const T triple = dot(b - a, cross(c - a, d - a));
    EXPECT_NEAR(join(pa, pb, pc, pd), triple, 64 * tol<T>());
    // Table 4: the ideal norms are the magnitudes of the extensions to the origin.
    EXPECT_NEAR(ideal_norm(pa & pb), 2 * heron(o, a, b), 16 * tol<T>());
    EXPECT_NEAR(ideal_norm(pa & pb & pc), std::abs(dot(a, cross(b, c))), 64 * tol<T>());
    // o ∨ F = +det(a, b, c) (docs/conventions.md §5: o on the left gives +6V).
    EXPECT_NEAR(origin<T>() & (pa & pb & pc), dot(a, cross(b, c)), 64 * tol<T>());
    // The same with the general Multivector.
    EXPECT_NEAR(norm(to_multivector(pa) & to_multivector(pb) & to_multivector(pc)),
                2 * heron(a, b, c), 16 * tol<T>());
  }
}

}  // namespace
}  // namespace pgamesh::pga3
