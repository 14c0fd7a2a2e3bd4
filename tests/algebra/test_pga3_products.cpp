// The general 16-component product (blade table) agrees with every specialised grade product:
// joins, meets, inner products, geometric products, duals, motor composition, reverse, inverse
// and the sandwich on every grade — on random inputs in float, double and (with GMP) exactly in
// rational arithmetic.
#include <gtest/gtest.h>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {
namespace {

using namespace pgamesh::test;

template <class T>
class Pga3Products : public ::testing::Test {};
#ifdef PGAMESH_HAVE_GMP
using ProductScalars = ::testing::Types<float, double, mpq_class>;
#else
using ProductScalars = ::testing::Types<float, double>;
#endif
TYPED_TEST_SUITE(Pga3Products, ProductScalars);

constexpr int kRounds = 100;

template <class X>
auto mv(const X& x) {
  return to_multivector(x);
}

TYPED_TEST(Pga3Products, Joins) {
  using T = TypeParam;
  std::mt19937 r(1);
  for (int i = 0; i < kRounds; ++i) {
    const auto a = random_point<T>(r), b = random_point<T>(r), c = random_point<T>(r),
               d = random_point<T>(r);
    const auto l = random_line<T>(r), l2 = random_line<T>(r);
    const auto p = random_plane<T>(r);
    EXPECT_TRUE(mv_near(mv(a & b), mv(a) & mv(b)));
    EXPECT_TRUE(mv_near(mv(l & a), mv(l) & mv(a)));
    EXPECT_TRUE(mv_near(mv(a & l), mv(a) & mv(l)));
    EXPECT_TRUE(mv_near(mv(join(a, b, c)), mv(a) & mv(b) & mv(c)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(p & a), mv(p) & mv(a)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(a & p), mv(a) & mv(p)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(l & l2), mv(l) & mv(l2)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(join(a, b, c, d)), mv(a) & mv(b) & mv(c) & mv(d)));
  }
}

TYPED_TEST(Pga3Products, Meets) {
  using T = TypeParam;
  std::mt19937 r(2);
  for (int i = 0; i < kRounds; ++i) {
    const auto p = random_plane<T>(r), q = random_plane<T>(r), s = random_plane<T>(r);
    const auto l = random_line<T>(r), l2 = random_line<T>(r);
    const auto v = random_point<T>(r);
    EXPECT_TRUE(mv_near(mv(p ^ q), mv(p) ^ mv(q)));
    EXPECT_TRUE(mv_near(mv(l ^ p), mv(l) ^ mv(p)));
    EXPECT_TRUE(mv_near(mv(p ^ l), mv(p) ^ mv(l)));
    EXPECT_TRUE(mv_near(mv(meet(p, q, s)), mv(p) ^ mv(q) ^ mv(s)));
    EXPECT_TRUE(mv_near(pseudoscalar_mv<T>(p ^ v), mv(p) ^ mv(v)));
    EXPECT_TRUE(mv_near(pseudoscalar_mv<T>(v ^ p), mv(v) ^ mv(p)));
    EXPECT_TRUE(mv_near(pseudoscalar_mv<T>(l ^ l2), mv(l) ^ mv(l2)));
  }
}

TYPED_TEST(Pga3Products, InnerProducts) {
  using T = TypeParam;
  std::mt19937 r(3);
  for (int i = 0; i < kRounds; ++i) {
    const auto p = random_plane<T>(r), q = random_plane<T>(r);
    const auto l = random_line<T>(r), l2 = random_line<T>(r);
    const auto v = random_point<T>(r), v2 = random_point<T>(r);
    EXPECT_TRUE(mv_near(scalar_mv<T>(p | q), mv(p) | mv(q)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(l | l2), mv(l) | mv(l2)));
    EXPECT_TRUE(mv_near(scalar_mv<T>(v | v2), mv(v) | mv(v2)));
    EXPECT_TRUE(mv_near(mv(p | l), mv(p) | mv(l)));
    EXPECT_TRUE(mv_near(mv(l | p), mv(l) | mv(p)));
    EXPECT_TRUE(mv_near(mv(p | v), mv(p) | mv(v)));
    EXPECT_TRUE(mv_near(mv(v | p), mv(v) | mv(p)));
    EXPECT_TRUE(mv_near(mv(l | v), mv(l) | mv(v)));
    EXPECT_TRUE(mv_near(mv(v | l), mv(v) | mv(l)));
  }
}

TYPED_TEST(Pga3Products, GeometricProductsAndDuals) {
  using T = TypeParam;
  std::mt19937 r(4);
  for (int i = 0; i < kRounds; ++i) {
    const auto p = random_plane<T>(r), q = random_plane<T>(r);
    const auto l = random_line<T>(r), l2 = random_line<T>(r);
    const auto v = random_point<T>(r), v2 = random_point<T>(r);
    const auto m = random_motor<T>(r), n = random_motor<T>(r);
    EXPECT_TRUE(mv_near(mv(p * q), mv(p) * mv(q)));
    EXPECT_TRUE(mv_near(mv(l * l2), mv(l) * mv(l2)));
    EXPECT_TRUE(mv_near(mv(v * v2), mv(v) * mv(v2)));
    EXPECT_TRUE(mv_near(mv(m * n), mv(m) * mv(n)));
    EXPECT_TRUE(mv_near(mv(~m), ~mv(m)));
    EXPECT_TRUE(mv_near(mv(!p), !mv(p)));
    EXPECT_TRUE(mv_near(mv(!l), !mv(l)));
    EXPECT_TRUE(mv_near(mv(!v), !mv(v)));
    EXPECT_TRUE(mv_near(mv(undual(p)), undual(mv(p))));
    EXPECT_TRUE(mv_near(mv(undual(l)), undual(mv(l))));
    EXPECT_TRUE(mv_near(mv(undual(v)), undual(mv(v))));
  }
}

// M X M̃ for arbitrary (not normalized) even elements M: the kernels are exact identities.
TYPED_TEST(Pga3Products, SandwichOnEveryGrade) {
  using T = TypeParam;
  std::mt19937 r(5);
  for (int i = 0; i < kRounds; ++i) {
    const auto m = random_motor<T>(r), n = random_motor<T>(r);
    const auto p = random_plane<T>(r);
    const auto l = random_line<T>(r);
    const auto v = random_point<T>(r);
    const auto M = mv(m), Mr = ~mv(m);
    EXPECT_TRUE(mv_near(mv(apply(m, p)), M * mv(p) * Mr));
    EXPECT_TRUE(mv_near(mv(apply(m, l)), M * mv(l) * Mr));
    EXPECT_TRUE(mv_near(mv(apply(m, v)), M * mv(v) * Mr));
    EXPECT_TRUE(mv_near(mv(apply(m, n)), M * mv(n) * Mr));
    EXPECT_TRUE(mv_near(mv(m(v)), M * mv(v) * Mr));
  }
}

TYPED_TEST(Pga3Products, MotorInverse) {
  using T = TypeParam;
  std::mt19937 r(6);
  for (int i = 0; i < kRounds; ++i) {
    const auto m = random_motor<T>(r);
    if (m == Motor<T>{}) continue;
    // M M⁻¹ = 1 in the general algebra, and the general inverse agrees.
    EXPECT_TRUE(mv_near(mv(m) * mv(inverse(m)), scalar_mv<T>(T(1)), 100));
    if constexpr (std::is_floating_point_v<T>) {
      const auto general = inverse(mv(m));
      ASSERT_TRUE(general.has_value());
      EXPECT_TRUE(mv_near(mv(inverse(m)), *general, 1e3));
    }
  }
}

TEST(Pga3ProductsFixed, GeneralInverseRejectsNullElements) {
  using MV = Multivector<double>;
  EXPECT_FALSE(inverse(basis_blade<double>(kE0)).has_value());
  EXPECT_FALSE(inverse(basis_blade<double>(kE01)).has_value());
  EXPECT_FALSE(inverse(scalar(1.0) + basis_blade<double>(kE1)).has_value());  // (1+e1)(1−e1) = 0
  const MV a = scalar(2.0) + basis_blade<double>(kE12) + 3.0 * basis_blade<double>(kE0123);
  const auto inv = inverse(a);
  ASSERT_TRUE(inv.has_value());
  EXPECT_TRUE(mv_near(a * *inv, scalar(1.0)));
  EXPECT_TRUE(mv_near(*inv * a, scalar(1.0)));
}

TEST(Pga3ProductsFixed, GradeSelectionAndSplit) {
  std::mt19937 r(7);
  const auto a = random_multivector<double>(r);
  Multivector<double> sum;
  for (int k = 0; k <= 4; ++k) sum = sum + grade(a, k);
  EXPECT_EQ(sum, a);
  EXPECT_EQ(grade(a, 1), to_multivector(to_plane(a)));
  EXPECT_EQ(grade(a, 2), to_multivector(to_line(a)));
  EXPECT_EQ(grade(a, 3), to_multivector(to_point(a)));
  EXPECT_EQ(grade(a, 0) + grade(a, 2) + grade(a, 4), to_multivector(to_motor(a)));
  // A = A_E + e0 A_I with both parts free of e0 (paper eq. 3.1), and ‖A‖∞ = ‖A_I‖.
  const auto split = euclidean_split(a);
  EXPECT_TRUE(mv_near(split.euclidean + basis_blade<double>(kE0) * split.ideal, a));
  EXPECT_EQ(ideal_norm(split.euclidean), 0.0);
  EXPECT_EQ(ideal_norm(split.ideal), 0.0);
  EXPECT_DOUBLE_EQ(norm(split.ideal), ideal_norm(a));
  EXPECT_DOUBLE_EQ(norm(split.euclidean), norm(a));
  // Commutator: ½(AB − BA), and scalar product = ⟨AB⟩₀.
  const auto b = random_multivector<double>(r);
  EXPECT_TRUE(mv_near(commutator(a, b), 0.5 * (a * b - b * a)));
  EXPECT_DOUBLE_EQ(scalar_product(a, b), (a * b)[kS]);
  // Left and right contraction agree on blades of complementary order: e1 ⌋ e12 = e2,
  // e12 ⌊ e2 = e1.
  EXPECT_EQ(left_contraction(basis_blade<double>(kE1), basis_blade<double>(kE12)),
            basis_blade<double>(kE2));
  EXPECT_EQ(right_contraction(basis_blade<double>(kE12), basis_blade<double>(kE2)),
            basis_blade<double>(kE1));
}

TEST(Pga3ProductsFixed, BladeTableSigns) {
  // The project's blade names (docs/conventions.md §1): e31 = e3 e1, e021 = e0 e2 e1,
  // e032 = e0 e3 e2.
  const auto e = [](int i) { return basis_blade<double>(i); };
  EXPECT_EQ(e(kE3) * e(kE1), e(kE31));
  EXPECT_EQ(e(kE1) * e(kE3), -e(kE31));
  EXPECT_EQ(e(kE0) * e(kE2) * e(kE1), e(kE021));
  EXPECT_EQ(e(kE0) * e(kE1) * e(kE3), e(kE013));
  EXPECT_EQ(e(kE0) * e(kE3) * e(kE2), e(kE032));
  EXPECT_EQ(e(kE1) * e(kE2) * e(kE3), e(kE123));
  EXPECT_EQ(e(kE0) * e(kE1) * e(kE2) * e(kE3), e(kE0123));
  EXPECT_EQ(e(kE0) * e(kE0), Multivector<double>{});
  EXPECT_EQ(e(kE123) * e(kE123), scalar(-1.0));
  EXPECT_EQ(e(kE12) * e(kE12), scalar(-1.0));
}

}  // namespace
}  // namespace pgamesh::pga3
