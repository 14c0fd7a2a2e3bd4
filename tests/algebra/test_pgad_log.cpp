// exp and log of non-simple bivectors in PGA R(d,0,1), d = 4, 5 (the invariant decomposition,
// Roelfs & De Keninck 2021; d = 6, 7 and isoclinic planes: test_pgad_motors.cpp): the closed-form
// exp agrees with the scaled-and-squared Taylor series,
// log inverts exp within the principal range, the parts of the split commute and are simple, and
// the general engine gives the same exp and log in R(4,0,1) and R(5,0,1).
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "pgad_engine_check.hpp"
#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/pgad.hpp"

using namespace pgamesh;
using pgamesh::test::max_diff;

namespace {

// A random bivector whose rotation angles satisfy |θ1| + |θ2| < π (the principal range of log):
// |θ1| + |θ2| ≤ sqrt(2 (θ1² + θ2²)) and θ1² + θ2² = Σ (Euclidean coefficients)², kept ≤ 4.
// Ideal (e0i) coefficients are any size: they move centres and translate.
template <int D>
pgad::Multivector<D> random_bivector(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  pgad::Multivector<D> b{};
  double euclidean = 0;
  for (clifford::BladeMask m = 0; m < b.size; ++m)
    if (clifford::grade_of(m) == 2) {
      b.c[m] = u(rng);
      if (!(m & 1u)) euclidean += b.c[m] * b.c[m];
    }
  const double scale = std::uniform_real_distribution<double>(0.2, 2.0)(rng) / std::sqrt(euclidean);
  for (clifford::BladeMask m = 0; m < b.size; ++m)
    if (!(m & 1u)) b.c[m] *= scale;
  return b;
}

template <int D>
void check_exp_log(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 200; ++trial) {
    const auto b = random_bivector<D>(rng);
    const auto b2 = pgad::geometric(b, b);
    ASSERT_GT(pgad::norm(pgad::grade(b2, 4)) + pgad::ideal_norm(pgad::grade(b2, 4)), 1e-6)
        << "the test wants non-simple bivectors";
    // exp: closed form (invariant split) against the series
    const auto m = pgad::exp(b);
    EXPECT_LT(max_diff(m, pgad::exp_series(b)), 1e-12) << "d = " << D << ", trial " << trial;
    // a motor: M M̃ = 1
    EXPECT_LT(max_diff(pgad::geometric(m, pgad::reverse(m)), pgad::scalar<D>(1)), 1e-12);
    // log(exp B) = B in the principal range
    EXPECT_LT(max_diff(pgad::log(m), b), 1e-9) << "d = " << D << ", trial " << trial;
    // exp(log M) = M for a product of two random motors (the series makes M independently)
    const auto m2 = pgad::geometric(m, pgad::exp_series(random_bivector<D>(rng)));
    EXPECT_LT(max_diff(pgad::exp_series(pgad::log(m2)), m2), 1e-9) << "d = " << D;
  }
}

TEST(PgadLog, NonSimpleExpLogRoundTripD4) {
  check_exp_log<4>(41);
}

TEST(PgadLog, NonSimpleExpLogRoundTripD5) {
  check_exp_log<5>(51);
}

template <int D>
void check_split(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 50; ++trial) {
    const auto b = random_bivector<D>(rng);
    const pgad::BivectorSplit<D> s = pgad::invariant_split(b);
    ASSERT_EQ(s.rotations, 2);
    std::array<pgad::Multivector<D>, 3> parts = {s.rotation[0], s.rotation[1], s.translation};
    auto sum = parts[0] + parts[1] + parts[2];
    EXPECT_LT(max_diff(sum, b), 1e-12);
    for (std::size_t i = 0; i < 3; ++i) {
      // simple: the square is a scalar, λ_j for the rotations and 0 for the translation
      const auto sq = pgad::geometric(parts[i], parts[i]);
      const double lambda = i < 2 ? s.square[i] : 0.0;
      EXPECT_LT(max_diff(sq, pgad::scalar<D>(lambda)), 1e-12) << "part " << i;
      if (i < 2) {
        EXPECT_LT(lambda, 0.0);
      }
      for (std::size_t j = i + 1; j < 3; ++j)  // commuting
        EXPECT_LT(
            max_diff(pgad::geometric(parts[i], parts[j]), pgad::geometric(parts[j], parts[i])),
            1e-12);
    }
    if (D == 4) {
      EXPECT_LT(max_diff(s.translation, pgad::Multivector<D>{}), 1e-12);
    }
  }
}

TEST(PgadLog, InvariantSplitIsCommutingAndSimple) {
  check_split<4>(7);
  check_split<5>(8);
}

TEST(PgadLog, DoubleRotationWithKnownAngles) {
  // B = 0.4 e12 − 1.1 e34 + 0.7 e05: exp(B) = exp(0.4 e12) exp(−1.1 e34) exp(0.7 e05).
  const auto b12 = pgad::blade<5>(0b000110, 0.4), b34 = pgad::blade<5>(0b011000, -1.1),
             b05 = pgad::blade<5>(0b100001, 0.7);
  const auto m = pgad::exp(b12 + b34 + b05);
  const auto expected =
      pgad::geometric(pgad::geometric(pgad::exp(b12), pgad::exp(b34)), pgad::exp(b05));
  EXPECT_LT(max_diff(m, expected), 1e-15);
  EXPECT_NEAR(m.c[0], std::cos(0.4) * std::cos(1.1), 1e-15);
  const auto l = pgad::log(m);
  EXPECT_LT(max_diff(l, b12 + b34 + b05), 1e-14);
  // a rotation by π/2 in one plane hides the other plane from ⟨M⟩₂; log still finds it
  const auto quarter =
      pgad::exp(pgad::blade<4>(0b00110, std::numbers::pi / 2) + pgad::blade<4>(0b11000, 0.3));
  EXPECT_LT(max_diff(pgad::log(quarter),
                     pgad::blade<4>(0b00110, std::numbers::pi / 2) + pgad::blade<4>(0b11000, 0.3)),
            1e-12);
}

TEST(PgadLog, IsoclinicRotationsHaveAClosedFormExpAndLog) {
  // exp(θ (e12 + e34)) rotates every direction by θ: the planes are not unique, but exp and log
  // are: exp = cos²θ + cos θ sin θ (e12 + e34) + sin²θ e1234 (the factors commute), and log
  // returns θ (e12 + e34). The split itself refuses, naming the reason.
  const double theta = 0.5;
  const auto b = pgad::blade<4>(0b00110, theta) + pgad::blade<4>(0b11000, theta);
  const auto m = pgad::exp(b);
  const double c = std::cos(theta), s = std::sin(theta);
  const auto expected = pgad::scalar<4>(c * c) + pgad::blade<4>(0b00110, c * s) +
                        pgad::blade<4>(0b11000, c * s) + pgad::blade<4>(0b11110, s * s);
  EXPECT_LT(max_diff(m, expected), 1e-15);
  EXPECT_LT(max_diff(pgad::log(m), b), 1e-15);
  EXPECT_THROW(pgad::invariant_split(b), std::domain_error);
}

template <int D>
void check_general(const char* name, std::uint64_t seed) {
  const auto alg = *clifford::make_algebra(name);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 20; ++trial) {
    test::expect_engine_exp_log_match_pgad(alg, random_bivector<D>(rng), 1e-9, name);
  }
}

TEST(PgadLog, GeneralEngineUsesTheSameClosedForms) {
  check_general<4>("pga4", 3);
  check_general<5>("pga5", 4);
}

}  // namespace
