// The straight-line kernels of docs/pga3.md "Speed": the lane forms (simd.hpp) of the motor
// product and of the point and plane sandwiches equal the quaternion-order (generic) formulas,
// which the exact tests (test_pga3_products.cpp, mpq_class) check against the 16-component
// product — exactly where every operation is exact (integer coefficients), to rounding otherwise;
// the four-lane join gives the generic bits up to the sign of a zero; and the batch forms
// apply_to_points / apply_to_planes equal apply() — exactly in rational arithmetic, to rounding in
// float and double.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

using test::random_motor;
using test::random_plane;
using test::random_point;

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
// Coefficient by coefficient equal: the same bits, except that a zero may carry the other sign
// (−(x + y) and (−x) + (−y) differ only for x = −y).
template <class Element>
bool same_values(const Element& a, const Element& b) {
  using T = typename Element::scalar_type;
  static_assert(sizeof(Element) % sizeof(T) == 0);
  T x[sizeof(Element) / sizeof(T)], y[sizeof(Element) / sizeof(T)];
  std::memcpy(x, &a, sizeof a), std::memcpy(y, &b, sizeof b);
  for (std::size_t k = 0; k < sizeof(Element) / sizeof(T); ++k)
    if (!(x[k] == y[k]) || (x[k] != T(0) && std::memcmp(&x[k], &y[k], sizeof(T)) != 0))
      return false;
  return true;
}

#ifdef PGAMESH_PGA3_SIMD
// Whether the double operators run the lane forms: inline in builds with AVX, through the AVX2
// variant of pga3/isa.hpp on x86-64 processors with AVX2; the quaternion order otherwise.
bool double_runs_lanes() {
  return detail::kHasSimd<double> || (detail::kDoubleOutOfLine && detail::runs(detail::Isa::avx2));
}

// The lane forms on integer coefficients in [−8, 8]: every product and sum is exact in float and
// double, so they must equal the quaternion-order formulas exactly, whatever the summation order
// (a zero may carry the other sign). This checks each term's sign pattern and lane order; half the
// motors are rotors (zero ideal part) and half the planes pass through the origin.
template <class T>
void expect_lane_forms_exact_on_integers() {
  std::mt19937 rng(41);
  std::uniform_int_distribution<int> coef(-8, 8);
  const auto motor = [&] {
    Motor<T> m;
    for (T* x : {&m.s, &m.e01, &m.e02, &m.e03, &m.e12, &m.e31, &m.e23, &m.e0123}) *x = T(coef(rng));
    return m;
  };
  for (int i = 0; i < 20000; ++i) {
    Motor<T> a = motor(), b = motor();
    Plane<T> v = plane(T(coef(rng)), T(coef(rng)), T(coef(rng)), T(coef(rng)));
    const Point<T> x = point(T(coef(rng)), T(coef(rng)), T(coef(rng)));
    if (i % 2 == 0) a.e01 = a.e02 = a.e03 = a.e0123 = v.e0 = T(0);
    if (i % 4 == 0) b.e01 = b.e02 = b.e03 = b.e0123 = T(0);
    ASSERT_TRUE(same_values(detail::geometric_product_lanes(a, b),
                            quaternion_order::geometric_product(a, b)))
        << i;
    ASSERT_TRUE(same_values(detail::apply_lanes(a, x), quaternion_order::apply(a, x))) << i;
    ASSERT_TRUE(same_values(detail::apply_lanes(a, v), quaternion_order::apply(a, v))) << i;
  }
}
TEST(Pga3Kernels, LaneFormsAreExactOnIntegers) {
  expect_lane_forms_exact_on_integers<float>();
  expect_lane_forms_exact_on_integers<double>();
}

// The four-lane join (double takes it inline under AVX and through the AVX2 variant of
// pga3/isa.hpp; float always) gives the generic values, a zero possibly with the other sign.
template <class T>
void expect_join_matches_generic() {
  std::mt19937 rng(43);
  for (int i = 0; i < 20000; ++i) {
    const Point<T> x = random_point<T>(rng), y = random_point<T>(rng), z = random_point<T>(rng);
    ASSERT_TRUE(same_values(detail::join_simd(x, y, z), join(join(x, y), z))) << i;
  }
}
TEST(Pga3Kernels, FourLaneJoinGivesTheGenericValues) {
  expect_join_matches_generic<float>();
  expect_join_matches_generic<double>();
}

// The motor product sums lane-uniformly (geometric_product_lanes): the quaternion-order product
// to rounding, on random coefficients in [−1, 1).
template <class T>
void expect_lane_product_matches_generic(double tolerance) {
  std::mt19937 rng(47);
  for (int i = 0; i < 20000; ++i) {
    const Motor<T> a = random_motor<T>(rng), b = random_motor<T>(rng);
    const Motor<T> got = detail::geometric_product_lanes(a, b);
    const Motor<T> want = quaternion_order::geometric_product(a, b);
    const T* g = &got.s;
    const T* w = &want.s;
    for (int k = 0; k < 8; ++k) ASSERT_NEAR(double(g[k]), double(w[k]), tolerance) << i;
  }
}

TEST(Pga3Kernels, LaneProductMatchesGeneric) {
  expect_lane_product_matches_generic<float>(2e-6);
  expect_lane_product_matches_generic<double>(4e-15);
  // The operator runs it in float, and in double where AVX2 runs.
  std::mt19937 rng(53);
  const Motor<float> a = random_motor<float>(rng), b = random_motor<float>(rng);
  EXPECT_TRUE(same_bits(a * b, detail::geometric_product_lanes(a, b)));
  const Motor<double> c = random_motor<double>(rng), d = random_motor<double>(rng);
  EXPECT_TRUE(same_bits(c * d, double_runs_lanes() ? detail::geometric_product_lanes(c, d)
                                                   : quaternion_order::geometric_product(c, d)));
}

// The sandwiches sum lane-uniformly (apply_lanes): the quaternion-order point and plane to
// rounding; rotors included (zero ideal part).
template <class T>
void expect_lane_sandwiches_match_generic(double tolerance) {
  std::mt19937 rng(59);
  for (int i = 0; i < 20000; ++i) {
    Motor<T> m = random_motor<T>(rng);
    if (i % 2 == 0) m.e01 = m.e02 = m.e03 = m.e0123 = T(0);
    const Point<T> x = random_point<T>(rng);
    const Plane<T> v = random_plane<T>(rng);
    const Point<T> got_x = detail::apply_lanes(m, x), want_x = quaternion_order::apply(m, x);
    const Plane<T> got_v = detail::apply_lanes(m, v), want_v = quaternion_order::apply(m, v);
    const T *gx = &got_x.e123, *wx = &want_x.e123, *gv = &got_v.e0, *wv = &want_v.e0;
    for (int k = 0; k < 4; ++k) {
      ASSERT_NEAR(double(gx[k]), double(wx[k]), tolerance) << i << " point " << k;
      ASSERT_NEAR(double(gv[k]), double(wv[k]), tolerance) << i << " plane " << k;
    }
  }
}

TEST(Pga3Kernels, LaneSandwichesMatchGeneric) {
  expect_lane_sandwiches_match_generic<float>(4e-6);
  expect_lane_sandwiches_match_generic<double>(8e-15);
  std::mt19937 rng(61);
  const Motor<float> m = random_motor<float>(rng);
  const Point<float> x = random_point<float>(rng);
  const Plane<float> v = random_plane<float>(rng);
  EXPECT_TRUE(same_bits(apply(m, x), detail::apply_lanes(m, x)));
  EXPECT_TRUE(same_bits(apply(m, v), detail::apply_lanes(m, v)));
  const Motor<double> n = random_motor<double>(rng);
  const Point<double> y = random_point<double>(rng);
  const Plane<double> u = random_plane<double>(rng);
  const bool lanes = double_runs_lanes();
  EXPECT_TRUE(
      same_bits(apply(n, y), lanes ? detail::apply_lanes(n, y) : quaternion_order::apply(n, y)));
  EXPECT_TRUE(
      same_bits(apply(n, u), lanes ? detail::apply_lanes(n, u) : quaternion_order::apply(n, u)));
}
#endif

// apply_to_points / apply_to_planes against apply() on each element, for 37 elements (the
// four-lane loop and its scalar tail), out of place and in place.
template <class T>
void expect_batch_matches_apply(T tolerance) {
  std::mt19937 rng(43);
  const Motor<T> m = random_motor<T>(rng);
  constexpr std::size_t n = 37;
  std::vector<T> x(n), y(n), z(n), a(n), b(n), c(n), d(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point<T> p = random_point<T>(rng);
    x[i] = p.e032, y[i] = p.e013, z[i] = p.e021;
    const Plane<T> v = random_plane<T>(rng);
    a[i] = v.e1, b[i] = v.e2, c[i] = v.e3, d[i] = v.e0;
  }
  std::vector<T> ox(n), oy(n), oz(n), oa(n), ob(n), oc(n), od(n);
  apply_to_points(m, x, y, z, ox, oy, oz);
  apply_to_planes(m, a, b, c, d, oa, ob, oc, od);
  const auto close = [&](const T& got, const T& want) {
    if constexpr (std::is_floating_point_v<T>)
      return std::abs(got - want) <= tolerance * std::max(T(1), std::abs(want));
    else
      return got == want;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Point<T> p = apply(m, point(x[i], y[i], z[i]));
    EXPECT_TRUE(close(ox[i], p.e032) && close(oy[i], p.e013) && close(oz[i], p.e021)) << i;
    const Plane<T> v = apply(m, plane(a[i], b[i], c[i], d[i]));
    EXPECT_TRUE(close(oa[i], v.e1) && close(ob[i], v.e2) && close(oc[i], v.e3) &&
                close(od[i], v.e0))
        << i;
  }
  // In place: the same numbers.
  apply_to_points(m, x, y, z, x, y, z);
  apply_to_planes(m, a, b, c, d, a, b, c, d);
  EXPECT_TRUE(x == ox && y == oy && z == oz && a == oa && b == ob && c == oc && d == od);
}

TEST(Pga3Kernels, BatchMatchesApplyFloat) {
  expect_batch_matches_apply<float>(2e-5f);
}
TEST(Pga3Kernels, BatchMatchesApplyDouble) {
  expect_batch_matches_apply<double>(1e-13);
}
#ifdef PGAMESH_HAVE_GMP
TEST(Pga3Kernels, BatchMatchesApplyExactly) {
  expect_batch_matches_apply<mpq_class>(0);
}
#endif

TEST(Pga3Kernels, BatchRejectsArraysOfDifferentLengths) {
  const std::vector<double> three(3), two(2);
  std::vector<double> out3(3), out2(2);
  EXPECT_THROW(apply_to_points(identity_motor<double>(), three, three, two, out3, out3, out3),
               std::length_error);
  EXPECT_THROW(
      apply_to_planes(identity_motor<double>(), three, three, three, three, out3, out3, out3, out2),
      std::length_error);
}

}  // namespace
}  // namespace pgamesh::pga3
