// Compile-time graded multivectors against the general engine (pgamesh::clifford) on random
// inputs in R(4,1), R(3,0,1), R(2,0,2), R(3,1) and R(4,4): every product and operation to 1e-12
// relative; the result grade sets (static_assert); identities (associativity, reverse of a
// product, rotors preserve the square of a vector).
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "pgamesh/algebra/graded.hpp"
#include "test_clifford_util.hpp"

using namespace pgamesh;
using graded::GradeMask;
using test::mv_near;

namespace {

using R41 = graded::Algebra<4, 1>;
using R301 = graded::Algebra<3, 0, 1>;
using R202 = graded::Algebra<2, 0, 2>;
using R31 = graded::Algebra<3, 1>;
using R44 = graded::Algebra<4, 4>;

// ---- grade sets and storage, at compile time ----------------------------------------------------

static_assert(graded::Vector<R41>::size == 5 && graded::Bivector<R41>::size == 10);
static_assert(graded::Even<R41>::size == 16 && graded::Odd<R41>::size == 16);
static_assert(graded::Full<R41>::size == 32 && graded::Full<R44>::size == 256);
static_assert(graded::Even<R41>::grades == 0b010101u && graded::Odd<R41>::grades == 0b101010u);
static_assert(graded::Bivector<R41>::blades[0] == 0b00011 &&
              graded::Bivector<R41>::blades[9] == 0b11000);  // ascending masks
// vector × vector = scalar + bivector; rotor × rotor stays even; three vectors span a trivector.
static_assert(decltype(graded::Vector<R41>{} * graded::Vector<R41>{})::grades == 0b101u);
static_assert(decltype(graded::Even<R41>{} * graded::Even<R41>{})::grades == R41::even_grades);
static_assert(decltype(graded::Even<R41>{} * graded::Odd<R41>{})::grades == R41::odd_grades);
static_assert(decltype(graded::Vector<R41>{} ^ graded::Vector<R41>{} ^
                       graded::Vector<R41>{})::grades == 0b1000u);
static_assert(decltype(graded::Vector<R41>{} | graded::Bivector<R41>{})::grades == 0b10u);
static_assert(decltype(graded::left_contraction(graded::Bivector<R41>{},
                                                graded::Vector<R41>{}))::grades == 0u);
// PGA3: join of two points (trivectors) is a line, of a line and a point a plane.
static_assert(decltype(graded::KVector<R301, 3>{} & graded::KVector<R301, 3>{})::grades == 0b100u);
static_assert(decltype(graded::Bivector<R301>{} & graded::KVector<R301, 3>{})::grades == 0b10u);
static_assert(decltype(graded::dual(graded::Vector<R41>{}))::grades == 0b10000u);
// Degenerate generators drop terms: e0 e0 = 0 (15 of 16 vector pairs in PGA3), and in R(0,0,2)
// the product of two vectors has no scalar part.
static_assert(graded::ProductTable<R301, graded::Product::geometric, 2u, 2u, ~0u>::count == 15);
static_assert(decltype(graded::Vector<graded::Algebra<0, 0, 2>>{} *
                       graded::Vector<graded::Algebra<0, 0, 2>>{})::grades == 0b100u);
// Sandwiches keep the operand's grades; the rotor × vector term list is 16 × 5 = 80 terms.
static_assert(decltype(graded::sandwich(graded::Even<R41>{}, graded::Vector<R41>{}))::grades ==
              0b10u);
static_assert(
    graded::ProductTable<R41, graded::Product::geometric, R41::even_grades, 2u, ~0u>::count == 80);
// Even × even in R(4,4) has all 128 × 128 pairs, past the unroll limit: the looped path.
static_assert(graded::ProductTable<R44, graded::Product::geometric, R44::even_grades,
                                   R44::even_grades, ~0u>::count == 16384 &&
              16384 > graded::unroll_limit);

// ---- random inputs against the general engine ---------------------------------------------------

template <class M>
M random_graded(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  M out;
  for (double& c : out.c) c = u(rng);
  return out;
}

// Sum of the grades of x in G (the engine's result projected to a graded result's grades).
clifford::Multivector grades_of(const clifford::Multivector& x, GradeMask g) {
  clifford::Multivector out;
  for (const auto& t : x.terms)
    if (g >> clifford::grade_of(t.mask) & 1u) out.terms.push_back(t);
  return out;
}

::testing::AssertionResult scalar_near(double a, double b) {
  if (std::abs(a - b) <= 1e-12 * std::max({std::abs(a), std::abs(b), 1.0}))
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b;
}

template <class A, GradeMask GA, GradeMask GB>
void check_products(std::mt19937_64& rng, int trials) {
  using MA = graded::Multivector<A, GA>;
  using MB = graded::Multivector<A, GB>;
  const clifford::Algebra alg = graded::runtime_algebra<A>();
  SCOPED_TRACE(::testing::Message()
               << "R(" << A::p << "," << A::q << "," << A::r << ") grades " << GA << " x " << GB);
  for (int t = 0; t < trials; ++t) {
    const MA a = random_graded<MA>(rng);
    const MB b = random_graded<MB>(rng);
    const auto ca = graded::to_clifford(a), cb = graded::to_clifford(b);
    EXPECT_TRUE(mv_near(graded::to_clifford(a * b), clifford::geometric(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(a ^ b), clifford::outer(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::left_contraction(a, b)),
                        clifford::left_contraction(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(a | b), clifford::inner(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(a & b), clifford::regressive(alg, ca, cb)));
    EXPECT_TRUE(scalar_near(graded::scalar_product(a, b), clifford::scalar_product(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(a + b), ca + cb));
    EXPECT_TRUE(mv_near(graded::to_clifford(a - b), ca - cb));
    // The sandwich A B Ã projected to B's grades.
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::sandwich(a, b)),
                        grades_of(clifford::sandwich(alg, ca, cb), GB)));
  }
}

template <class A, GradeMask G>
void check_unary(std::mt19937_64& rng, int trials) {
  using M = graded::Multivector<A, G>;
  const clifford::Algebra alg = graded::runtime_algebra<A>();
  SCOPED_TRACE(::testing::Message()
               << "R(" << A::p << "," << A::q << "," << A::r << ") grades " << G);
  for (int t = 0; t < trials; ++t) {
    const M a = random_graded<M>(rng);
    const auto ca = graded::to_clifford(a);
    EXPECT_TRUE(mv_near(graded::to_clifford(~a), clifford::reverse(ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::involution(a)), clifford::involution(ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::conjugate(a)), clifford::conjugate(ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::dual(a)), clifford::dual(alg, ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::undual(a)), clifford::undual(alg, ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::undual(graded::dual(a))), ca));
    EXPECT_TRUE(mv_near(graded::to_clifford(-2.5 * a), -2.5 * ca));
    EXPECT_TRUE(mv_near(graded::to_clifford(a / 4.0), ca / 4.0));
    EXPECT_TRUE(mv_near(graded::to_clifford(-a), -ca));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::grade<2>(a)), clifford::grade(ca, 2)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::grade<1>(a)), clifford::grade(ca, 1)));
    EXPECT_TRUE(scalar_near(graded::scalar_part(a), clifford::scalar_part(ca)));
    EXPECT_TRUE(scalar_near(graded::norm_squared(a), clifford::norm_squared(alg, ca)));
    EXPECT_TRUE(scalar_near(graded::norm(a), clifford::norm(alg, ca)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::from_clifford<M>(ca)), ca));
  }
}

// Associativity and the reverse of a product on random inputs.
template <class A, GradeMask G1, GradeMask G2, GradeMask G3>
void check_identities(std::mt19937_64& rng, int trials) {
  for (int t = 0; t < trials; ++t) {
    const auto a = random_graded<graded::Multivector<A, G1>>(rng);
    const auto b = random_graded<graded::Multivector<A, G2>>(rng);
    const auto c = random_graded<graded::Multivector<A, G3>>(rng);
    EXPECT_TRUE(mv_near(graded::to_clifford((a * b) * c), graded::to_clifford(a * (b * c))));
    EXPECT_TRUE(mv_near(graded::to_clifford((a ^ b) ^ c), graded::to_clifford(a ^ (b ^ c))));
    EXPECT_TRUE(mv_near(graded::to_clifford((a & b) & c), graded::to_clifford(a & (b & c))));
    EXPECT_TRUE(mv_near(graded::to_clifford(~(a * b)), graded::to_clifford(~b * ~a)));
  }
}

// Rotors R = exp(B) (the engine's exp of a random bivector): R X R̃ keeps X² and agrees with the
// engine's full sandwich (no other grades); R R̃ = 1 and the versor inverse is R̃.
template <class A>
void check_rotors(std::mt19937_64& rng, int trials) {
  const clifford::Algebra alg = graded::runtime_algebra<A>();
  for (int t = 0; t < trials; ++t) {
    const auto b = 0.7 * random_graded<graded::Bivector<A>>(rng);
    const auto r = graded::from_clifford<graded::Even<A>>(
        clifford::pruned(clifford::exp(alg, graded::to_clifford(b)), 0.0));
    const auto x = random_graded<graded::Vector<A>>(rng);
    const auto y = graded::sandwich(r, x);
    EXPECT_TRUE(scalar_near(graded::scalar_product(y, y), graded::scalar_product(x, x)));
    EXPECT_TRUE(scalar_near(graded::norm_squared(r), 1.0));
    EXPECT_TRUE(mv_near(graded::to_clifford(y),
                        clifford::sandwich(alg, graded::to_clifford(r), graded::to_clifford(x)),
                        1e-11));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::inverse(r)), graded::to_clifford(~r), 1e-11));
  }
}

TEST(Graded, R41ProductsAgreeWithEngine) {
  std::mt19937_64 rng(41);
  check_products<R41, 2u, 2u>(rng, 20);
  check_products<R41, 4u, 2u>(rng, 20);
  check_products<R41, 2u, 4u>(rng, 20);
  check_products<R41, R41::even_grades, R41::even_grades>(rng, 20);
  check_products<R41, R41::even_grades, 2u>(rng, 20);
  check_products<R41, R41::odd_grades, R41::even_grades>(rng, 20);
  check_products<R41, 0b1000u, 0b110u>(rng, 20);
  check_products<R41, R41::all_grades, R41::all_grades>(rng, 10);
}

TEST(Graded, R301ProductsAgreeWithEngine) {
  std::mt19937_64 rng(301);
  check_products<R301, 2u, 2u>(rng, 20);
  check_products<R301, 0b1000u, 0b1000u>(rng, 20);  // join of points
  check_products<R301, 4u, 0b1000u>(rng, 20);
  check_products<R301, R301::even_grades, 0b1000u>(rng, 20);  // motor on a point
  check_products<R301, R301::even_grades, R301::even_grades>(rng, 20);
  check_products<R301, R301::all_grades, R301::all_grades>(rng, 10);
}

TEST(Graded, R202AndR31ProductsAgreeWithEngine) {
  std::mt19937_64 rng(202);
  check_products<R202, 2u, 2u>(rng, 20);
  check_products<R202, R202::even_grades, R202::odd_grades>(rng, 20);
  check_products<R202, R202::all_grades, R202::all_grades>(rng, 10);
  check_products<R31, 2u, 4u>(rng, 20);
  check_products<R31, R31::even_grades, R31::even_grades>(rng, 20);
  check_products<R31, R31::all_grades, R31::all_grades>(rng, 10);
}

TEST(Graded, R44ProductsAgreeWithEngine) {
  std::mt19937_64 rng(44);
  check_products<R44, 2u, 2u>(rng, 10);
  check_products<R44, 4u, 2u>(rng, 10);
  check_products<R44, 4u, 4u>(rng, 10);
  check_products<R44, R44::even_grades, 2u>(rng, 5);
  // Even × even is 16384 terms: the looped path. Only the geometric product and the sandwich
  // here (each 128 × 128 table costs seconds of compile time); the other products of even
  // elements are covered by even × vector above.
  const clifford::Algebra alg = graded::runtime_algebra<R44>();
  for (int t = 0; t < 3; ++t) {
    const auto a = random_graded<graded::Even<R44>>(rng);
    const auto b = random_graded<graded::Even<R44>>(rng);
    const auto ca = graded::to_clifford(a), cb = graded::to_clifford(b);
    EXPECT_TRUE(mv_near(graded::to_clifford(a * b), clifford::geometric(alg, ca, cb)));
    EXPECT_TRUE(mv_near(graded::to_clifford(graded::sandwich(a, b)),
                        grades_of(clifford::sandwich(alg, ca, cb), R44::even_grades)));
  }
}

TEST(Graded, UnaryOperationsAgreeWithEngine) {
  std::mt19937_64 rng(7);
  check_unary<R41, R41::all_grades>(rng, 10);
  check_unary<R41, R41::even_grades>(rng, 10);
  check_unary<R301, R301::all_grades>(rng, 10);
  check_unary<R202, R202::all_grades>(rng, 10);
  check_unary<R31, R31::odd_grades>(rng, 10);
  check_unary<R44, R44::even_grades>(rng, 5);
}

TEST(Graded, Identities) {
  std::mt19937_64 rng(8);
  check_identities<R41, 2u, 2u, 2u>(rng, 10);
  check_identities<R41, R41::even_grades, 2u, R41::all_grades>(rng, 10);
  check_identities<R301, R301::all_grades, 0b1000u, R301::even_grades>(rng, 10);
  check_identities<R31, 4u, R31::odd_grades, 2u>(rng, 10);
  check_identities<R44, 2u, 4u, 2u>(rng, 5);
}

TEST(Graded, RotorsPreserveSquaresAndInvert) {
  std::mt19937_64 rng(9);
  check_rotors<R41>(rng, 20);
  check_rotors<R31>(rng, 20);
  check_rotors<R301>(rng, 20);
}

TEST(Graded, VersorInverse) {
  std::mt19937_64 rng(10);
  const clifford::Algebra alg = graded::runtime_algebra<R41>();
  for (int t = 0; t < 20; ++t) {
    const auto a = random_graded<graded::Vector<R41>>(rng);
    const auto b = random_graded<graded::Vector<R41>>(rng);
    const auto c = random_graded<graded::Vector<R41>>(rng);
    const auto v = a * b * c;  // an odd versor
    const auto inv = graded::inverse(v);
    EXPECT_TRUE(
        mv_near(graded::to_clifford(inv), clifford::inverse(alg, graded::to_clifford(v)), 1e-10));
    EXPECT_TRUE(mv_near(graded::to_clifford(v * inv), clifford::scalar(1.0), 1e-10));
  }
  // 1 + e12 + e34: V Ṽ has a grade-4 part, so V is not a versor.
  const auto bad =
      graded::basis<R41, 0>() + graded::basis<R41, 0b0011>() + graded::basis<R41, 0b1100>();
  EXPECT_THROW(graded::inverse(bad), std::domain_error);
  EXPECT_THROW(graded::inverse(graded::Vector<R41>{}), std::domain_error);
}

TEST(Graded, ConversionsAndPrinting) {
  graded::Vector<R41> v;
  v.c = {1.0, -2.0, 0.0, 0.0, 0.5};
  EXPECT_EQ(graded::to_string(v), "1 e1 - 2 e2 + 0.5 e5");
  EXPECT_EQ(graded::to_string(graded::Even<R41>{}), "0");
  EXPECT_EQ(graded::to_string(graded::basis<R301, 0b0011>(-3.0)), "-3 e01");
  EXPECT_EQ(v[0b10000], 0.5);
  EXPECT_EQ(v[0b00011], 0.0);  // a bivector blade: not stored, zero
  // A bivector does not fit a vector: refused rather than dropped.
  EXPECT_THROW(graded::from_clifford<graded::Vector<R41>>(clifford::basis_blade(0b11, 1.0)),
               std::invalid_argument);
  EXPECT_NO_THROW(graded::from_clifford<graded::Full<R41>>(clifford::basis_blade(0b11, 1.0)));
}

}  // namespace
