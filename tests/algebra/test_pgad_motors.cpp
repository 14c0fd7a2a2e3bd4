// exp and log of motors of PGA R(d,0,1), d = 4 … 7, in closed form without choosing planes
// (pgad::exp, pgad::log; docs/clifford.md): against the scaled-and-squared Taylor series
// (pgad::exp_series), for random bivectors, for exactly and nearly isoclinic ones (relative gaps
// 1e-3 … 1e-12 between two or three planes), for zero planes with a translation; log(exp B) = B
// in the principal range; exp(log M) = M for products of motors; known angles; the invariant
// split for d = 6, 7; the general engine in R(6,0,1) and R(7,0,1).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "pgad_engine_check.hpp"
#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/pgad.hpp"

using namespace pgamesh;
using pgamesh::test::max_diff;

namespace {

// e_(2j+1) e_(2j+2): the j-th coordinate plane (blade masks: bit 0 = e0, bit i = e_i).
constexpr clifford::BladeMask plane_blade(int j) {
  return clifford::BladeMask{0b110} << (2 * j);
}

template <int D>
pgad::Multivector<D> random_grade2(std::mt19937_64& rng, bool euclidean, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  pgad::Multivector<D> b{};
  for (clifford::BladeMask m = 0; m < b.size; ++m)
    if (clifford::grade_of(m) == 2 && ((m & 1u) == 0) == euclidean) b.c[m] = u(rng);
  return b;
}

// R (Σ_j angle[j] e_(2j+1)(2j+2)) R̃ + e0 t with a random Euclidean rotor R and random t: rotation
// angles exactly as given about planes in general position, centres moved, and a translation
// along the directions the planes leave free (d odd, or fewer than d/2 planes).
template <int D>
pgad::Multivector<D> bivector_with_angles(std::mt19937_64& rng, const std::vector<double>& angle) {
  pgad::Multivector<D> f{};
  for (std::size_t j = 0; j < angle.size(); ++j) f.c[plane_blade(static_cast<int>(j))] = angle[j];
  const auto r = pgad::exp_series(random_grade2<D>(rng, true, 1.0));
  return pgad::grade(pgad::sandwich(r, f), 2) + random_grade2<D>(rng, false, 1.0);
}

// A random bivector in the principal range of log: Σ ψ_j² = Σ (Euclidean coefficients)², and
// |ψ1| + |ψ2| + |ψ3| ≤ √3 √(Σ ψ_j²) < π when the Euclidean coefficients have norm ≤ 1.75.
template <int D>
pgad::Multivector<D> random_principal_bivector(std::mt19937_64& rng) {
  auto b = random_grade2<D>(rng, true, 1.0);
  const double scale = std::uniform_real_distribution<double>(0.1, 1.75)(rng) / pgad::norm(b);
  return scale * b + random_grade2<D>(rng, false, 1.0);
}

template <int D>
void check_round_trip(const pgad::Multivector<D>& b, double exp_tolerance, double log_tolerance,
                      const std::string& what) {
  const auto m = pgad::exp(b);
  EXPECT_LT(max_diff(m, pgad::exp_series(b)), exp_tolerance) << what;
  EXPECT_LT(max_diff(pgad::geometric(m, pgad::reverse(m)), pgad::scalar<D>(1)), 1e-13) << what;
  EXPECT_LT(max_diff(pgad::log(m), b), log_tolerance) << what;
}

template <int D>
void check_random(std::uint64_t seed, int trials) {
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < trials; ++trial) {
    const auto b = random_principal_bivector<D>(rng);
    check_round_trip(b, 1e-12, 1e-10,
                     "d = " + std::to_string(D) + ", trial " + std::to_string(trial));
    // exp(log M) = M for a product of motors (out of the principal range too: log picks the
    // principal one, whose exp is M)
    const auto m =
        pgad::geometric(pgad::exp_series(b), pgad::exp_series(random_principal_bivector<D>(rng)));
    EXPECT_LT(max_diff(pgad::exp(pgad::log(m)), m), 1e-8) << "d = " << D << ", trial " << trial;
  }
}

TEST(PgadMotors, RandomBivectorsD4) {
  check_random<4>(401, 100);
}
TEST(PgadMotors, RandomBivectorsD5) {
  check_random<5>(501, 100);
}
TEST(PgadMotors, RandomBivectorsD6) {
  check_random<6>(601, 60);
}
TEST(PgadMotors, RandomBivectorsD7) {
  check_random<7>(701, 30);
}

// Angles ψ, ψ (1 − gap) [, ψ (1 − 2 gap)] for gaps from 0.3 down to 0 (exactly isoclinic): the
// closed forms stay as accurate as away from the isoclinic case, with no switch to fall over.
template <int D>
void check_isoclinic(std::uint64_t seed, int planes) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.05, 2.9 / planes);
  for (double gap : {0.3, 1e-3, 1e-6, 1e-9, 1e-12, 0.0}) {
    for (int trial = 0; trial < 6; ++trial) {
      const double psi = angle(rng);
      std::vector<double> a = {psi, psi * (1 - gap)};
      if (planes == 3) a.push_back(psi * (1 - 2 * gap));
      const auto b = bivector_with_angles<D>(rng, a);
      check_round_trip(b, 1e-12, 1e-10,
                       "d = " + std::to_string(D) + ", " + std::to_string(planes) +
                           " planes, gap " + std::to_string(gap));
    }
  }
}

TEST(PgadMotors, NearlyIsoclinicPairs) {
  check_isoclinic<4>(41, 2);
  check_isoclinic<5>(51, 2);
  check_isoclinic<6>(61, 2);
  check_isoclinic<7>(71, 2);
}

TEST(PgadMotors, NearlyIsoclinicTriples) {
  check_isoclinic<6>(62, 3);
  check_isoclinic<7>(72, 3);
}

TEST(PgadMotors, ThreePlanesWithOneIsoclinicPair) {
  std::mt19937_64 rng(63);
  for (double gap : {1e-4, 1e-8, 0.0}) {
    check_round_trip(bivector_with_angles<6>(rng, {0.3, 1.1, 1.1 * (1 - gap)}), 1e-12, 1e-11,
                     "d = 6");
    check_round_trip(bivector_with_angles<7>(rng, {1.2, 0.7 * (1 - gap), 0.7}), 1e-12, 1e-11,
                     "d = 7");
  }
}

TEST(PgadMotors, ZeroPlanesAndTranslations) {
  // fewer planes than fit: one rotation with a translation along free directions, two in d = 7
  std::mt19937_64 rng(73);
  check_round_trip(bivector_with_angles<4>(rng, {0.8}), 1e-12, 1e-12, "d = 4, one plane");
  check_round_trip(bivector_with_angles<6>(rng, {0.8}), 1e-12, 1e-12, "d = 6, one plane");
  check_round_trip(bivector_with_angles<7>(rng, {0.8, 0.0, 0.0}), 1e-12, 1e-12, "d = 7, one");
  check_round_trip(bivector_with_angles<7>(rng, {0.8, 1.3}), 1e-12, 1e-12, "d = 7, two planes");
  check_round_trip(bivector_with_angles<7>(rng, {0.8, 0.8}), 1e-12, 1e-12, "d = 7, isoclinic");
}

TEST(PgadMotors, KnownAnglesInSixDimensions) {
  // exp(θ (e12 + e34 + e56)) = Π (cos θ + sin θ e_(2j−1)(2j)) with commuting factors:
  // cos³θ + cos²θ sin θ (e12 + e34 + e56) + cos θ sin²θ (e1234 + e1256 + e3456) + sin³θ e123456.
  const double theta = 0.7, c = std::cos(theta), s = std::sin(theta);
  pgad::Multivector<6> b{}, expected = pgad::scalar<6>(c * c * c);
  for (int j = 0; j < 3; ++j) {
    b.c[plane_blade(j)] = theta;
    expected.c[plane_blade(j)] = c * c * s;
    for (int k = j + 1; k < 3; ++k) expected.c[plane_blade(j) | plane_blade(k)] = c * s * s;
  }
  expected.c[plane_blade(0) | plane_blade(1) | plane_blade(2)] = s * s * s;
  const auto m = pgad::exp(b);
  EXPECT_LT(max_diff(m, expected), 1e-15);
  EXPECT_LT(max_diff(pgad::log(m), b), 1e-14);
  // distinct angles 0.4, −1.1, 0.9 and a translation 0.5 e07: the product of the factors
  pgad::Multivector<7> b7 = pgad::blade<7>(plane_blade(0), 0.4) +
                            pgad::blade<7>(plane_blade(1), -1.1) +
                            pgad::blade<7>(plane_blade(2), 0.9) + pgad::blade<7>(0b10000001, 0.5);
  pgad::Multivector<7> product = pgad::scalar<7>(1) + pgad::blade<7>(0b10000001, 0.5);
  for (int j = 0; j < 3; ++j) {
    const double a = b7.c[plane_blade(j)];
    product = pgad::geometric(
        product, pgad::scalar<7>(std::cos(a)) + pgad::blade<7>(plane_blade(j), std::sin(a)));
  }
  EXPECT_LT(max_diff(pgad::exp(b7), product), 1e-15);
  EXPECT_LT(max_diff(pgad::log(product), b7), 1e-14);
}

template <int D>
void check_motor_split(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.1, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<double> a = {angle(rng), 1.0 + angle(rng), 2.0 + angle(rng)};
    const auto b = bivector_with_angles<D>(rng, a);
    const pgad::BivectorSplit<D> s = pgad::invariant_split(b);
    ASSERT_EQ(s.rotations, 3);
    std::vector<pgad::Multivector<D>> parts = {s.rotation[0], s.rotation[1], s.rotation[2],
                                               s.translation};
    EXPECT_LT(max_diff(parts[0] + parts[1] + parts[2] + parts[3], b), 1e-12);
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const double lambda = i < 3 ? s.square[i] : 0.0;
      EXPECT_LT(max_diff(pgad::geometric(parts[i], parts[i]), pgad::scalar<D>(lambda)), 1e-12);
      for (std::size_t j = i + 1; j < parts.size(); ++j)
        EXPECT_LT(
            max_diff(pgad::geometric(parts[i], parts[j]), pgad::geometric(parts[j], parts[i])),
            1e-12);
    }
    // the squares are −ψ_j², largest rotation first
    EXPECT_NEAR(s.square[0], -a[2] * a[2], 1e-12);
    EXPECT_NEAR(s.square[1], -a[1] * a[1], 1e-12);
    EXPECT_NEAR(s.square[2], -a[0] * a[0], 1e-12);
    EXPECT_LT(max_diff(pgad::exp_of_split(s), pgad::exp(b)), 1e-12);
    if (D == 6) {
      EXPECT_LT(pgad::ideal_norm(s.translation), 1e-12);
    }
  }
}

TEST(PgadMotors, InvariantSplitOfThreePlanes) {
  check_motor_split<6>(606);
  check_motor_split<7>(707);
}

TEST(PgadMotors, LogRefusesWhatIsNotAMotor) {
  const auto m =
      pgad::exp(pgad::blade<6>(plane_blade(0), 0.3) + pgad::blade<6>(plane_blade(1), 0.4));
  EXPECT_THROW(pgad::log(2.0 * m), std::domain_error);                        // not normalised
  EXPECT_THROW(pgad::log(m + pgad::blade<6>(0b10, 0.1)), std::domain_error);  // odd grade
  try {
    pgad::log(2.0 * m);
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a normalised motor"), std::string::npos);
  }
}

template <int D>
void check_motor_general(const char* name, std::uint64_t seed) {
  const auto alg = *clifford::make_algebra(name);
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 5; ++trial) {
    const auto b = trial == 0 ? bivector_with_angles<D>(rng, {0.6, 0.6, 0.6})
                              : random_principal_bivector<D>(rng);
    test::expect_engine_exp_log_match_pgad(alg, b, 1e-11, name);
  }
}

TEST(PgadMotors, GeneralEngineUsesTheSameClosedForms) {
  check_motor_general<6>("pga6", 66);
  check_motor_general<7>("7,0,1", 77);
}

}  // namespace
