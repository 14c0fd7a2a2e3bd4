// The general Clifford engine, the compile-time PGA R(d,0,1) and the PGA3 fast path, side by side.
// Compare the R(4,1) products with the ~6–30 ns per product that compile-time C++ GA libraries
// report for 3-D CGA; the R(9,6) outer product of nine vectors shows the sparse engine at 32768
// blades. Run: build/release/bench/bench_clifford
#include <benchmark/benchmark.h>

#include <random>

#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/algebra/pgad.hpp"

using namespace pgamesh;
using clifford::Multivector;

namespace {

Multivector random_grades(const clifford::Algebra& alg, std::mt19937_64& rng, unsigned grades) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<clifford::Term> t;
  for (clifford::BladeMask m = 0; m <= alg.pseudoscalar_mask(); ++m)
    if (grades >> clifford::grade_of(m) & 1) t.push_back({m, u(rng)});
  return clifford::from_terms(t);
}

// ---- R(4,1) (orthonormal e1..e4, e5² = −1) and CGA's null basis ---------------------------------

void BM_R41_GeometricVectorVector(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("4,1,0");
  std::mt19937_64 rng(1);
  const auto a = random_grades(alg, rng, 1u << 1), b = random_grades(alg, rng, 1u << 1);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::geometric(alg, a, b));
}
BENCHMARK(BM_R41_GeometricVectorVector);

void BM_R41_GeometricFullFull(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("4,1,0");
  std::mt19937_64 rng(2);
  const auto a = random_grades(alg, rng, 0x3f), b = random_grades(alg, rng, 0x3f);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::geometric(alg, a, b));
}
BENCHMARK(BM_R41_GeometricFullFull);

void BM_R41_SandwichRotorOnVector(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("4,1,0");
  std::mt19937_64 rng(3);
  const auto r = clifford::exp(alg, 0.3 * random_grades(alg, rng, 1u << 2));
  const auto x = random_grades(alg, rng, 1u << 1);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::sandwich(alg, r, x));
}
BENCHMARK(BM_R41_SandwichRotorOnVector);

void BM_Cga3NullBasis_GeometricVectorVector(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("cga3");  // change of basis on every product
  std::mt19937_64 rng(4);
  const auto a = random_grades(alg, rng, 1u << 1), b = random_grades(alg, rng, 1u << 1);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::geometric(alg, a, b));
}
BENCHMARK(BM_Cga3NullBasis_GeometricVectorVector);

void BM_Cga3NullBasis_OuterOfFourPoints(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("cga3");  // metric-free: no change of basis
  std::mt19937_64 rng(5);
  std::vector<Multivector> p;
  for (int i = 0; i < 4; ++i) p.push_back(random_grades(alg, rng, 1u << 1));
  for (auto _ : s) {
    Multivector w = clifford::outer(alg, clifford::outer(alg, p[0], p[1]), p[2]);
    benchmark::DoNotOptimize(clifford::outer(alg, w, p[3]));
  }
}
BENCHMARK(BM_Cga3NullBasis_OuterOfFourPoints);

// ---- R(9,6): QCGA, 32768 blades
// -------------------------------------------------------------------

void BM_R96_OuterOfNineVectors(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("qcga");
  std::mt19937_64 rng(6);
  std::vector<Multivector> v;
  for (int i = 0; i < 9; ++i) v.push_back(random_grades(alg, rng, 1u << 1));
  for (auto _ : s) {
    Multivector w = v[0];
    for (int i = 1; i < 9; ++i) w = clifford::outer(alg, w, v[static_cast<std::size_t>(i)]);
    benchmark::DoNotOptimize(w);
  }
}
BENCHMARK(BM_R96_OuterOfNineVectors)->Unit(benchmark::kMicrosecond);

void BM_R96_GeometricVectorByNineBlade(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("qcga");
  std::mt19937_64 rng(7);
  Multivector w = random_grades(alg, rng, 1u << 1);
  for (int i = 1; i < 9; ++i) w = clifford::outer(alg, w, random_grades(alg, rng, 1u << 1));
  const auto x = random_grades(alg, rng, 1u << 1);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::geometric(alg, x, w));
}
BENCHMARK(BM_R96_GeometricVectorByNineBlade)->Unit(benchmark::kMicrosecond);

// ---- PGA3: fast path vs compile-time R(3,0,1) vs general engine ---------------------------------

void BM_Pga3Fast_JoinThreePoints(benchmark::State& s) {
  const auto a = pga3::point(0.3, 1.2, -0.7), b = pga3::point(-1.1, 0.4, 2.0),
             c = pga3::point(0.9, -0.8, 0.5);
  for (auto _ : s) {
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(pga3::join(a, b, c));
  }
}
BENCHMARK(BM_Pga3Fast_JoinThreePoints);

void BM_Pgad3_JoinThreePoints(benchmark::State& s) {
  const auto a = pgad::point<3>({0.3, 1.2, -0.7}), b = pgad::point<3>({-1.1, 0.4, 2.0}),
             c = pgad::point<3>({0.9, -0.8, 0.5});
  for (auto _ : s) {
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(pgad::join(a, b, c));
  }
}
BENCHMARK(BM_Pgad3_JoinThreePoints);

void BM_General_Pga3JoinThreePoints(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("pga3");
  auto pt = [&](double x, double y, double z) {
    return clifford::dual(alg, clifford::from_terms({{1, 1.0}, {2, x}, {4, y}, {8, z}}));
  };
  const auto a = pt(0.3, 1.2, -0.7), b = pt(-1.1, 0.4, 2.0), c = pt(0.9, -0.8, 0.5);
  for (auto _ : s)
    benchmark::DoNotOptimize(clifford::regressive(alg, clifford::regressive(alg, a, b), c));
}
BENCHMARK(BM_General_Pga3JoinThreePoints);

void BM_Pga3Fast_MotorOnPoint(benchmark::State& s) {
  const auto m = pga3::translator(Vec3d{1, 2, 3}) * pga3::rotor(0.7, Vec3d{0, 0.6, 0.8});
  const auto p = pga3::point(0.3, 1.2, -0.7);
  for (auto _ : s) {
    benchmark::DoNotOptimize(m);
    benchmark::DoNotOptimize(pga3::apply(m, p));
  }
}
BENCHMARK(BM_Pga3Fast_MotorOnPoint);

void BM_Pgad3_MotorOnPoint(benchmark::State& s) {
  const auto l = pgad::join(pgad::point<3>({0.1, 0.2, 0.3}), pgad::point<3>({1.0, -0.5, 0.7}));
  const auto m = pgad::exp(0.4 * l);
  const auto p = pgad::point<3>({0.3, 1.2, -0.7});
  for (auto _ : s) {
    benchmark::DoNotOptimize(m);
    benchmark::DoNotOptimize(pgad::sandwich(m, p));
  }
}
BENCHMARK(BM_Pgad3_MotorOnPoint);

void BM_General_Pga3MotorOnPoint(benchmark::State& s) {
  const auto alg = *clifford::make_algebra("pga3");
  std::mt19937_64 rng(8);
  const auto m = clifford::exp(alg, 0.4 * random_grades(alg, rng, 1u << 2));
  const auto p = random_grades(alg, rng, 1u << 3);
  for (auto _ : s) benchmark::DoNotOptimize(clifford::sandwich(alg, m, p));
}
BENCHMARK(BM_General_Pga3MotorOnPoint);

void BM_Pgad4_GeometricFullFull(benchmark::State& s) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  pgad::Multivector<4> a, b;
  for (double& x : a.c) x = u(rng);
  for (double& x : b.c) x = u(rng);
  for (auto _ : s) {
    benchmark::DoNotOptimize(a);
    benchmark::DoNotOptimize(pgad::geometric(a, b));
  }
}
BENCHMARK(BM_Pgad4_GeometricFullFull);

// ---- exp and log of PGA R(d,0,1) motors: the closed forms in the angle sums against the series --

template <int D>
pgad::Multivector<D> random_pgad_bivector(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  pgad::Multivector<D> b{};
  for (clifford::BladeMask m = 0; m < b.size; ++m)
    if (clifford::grade_of(m) == 2) b.c[m] = u(rng);
  return b;
}

template <int D>
void BM_PgadExpClosedForm(benchmark::State& s) {
  const auto b = random_pgad_bivector<D>(10);
  for (auto _ : s) {
    benchmark::DoNotOptimize(b);
    benchmark::DoNotOptimize(pgad::exp(b));
  }
}
BENCHMARK_TEMPLATE(BM_PgadExpClosedForm, 4);
BENCHMARK_TEMPLATE(BM_PgadExpClosedForm, 7);

template <int D>
void BM_PgadExpSeries(benchmark::State& s) {
  const auto b = random_pgad_bivector<D>(10);
  for (auto _ : s) {
    benchmark::DoNotOptimize(b);
    benchmark::DoNotOptimize(pgad::exp_series(b));
  }
}
BENCHMARK_TEMPLATE(BM_PgadExpSeries, 4);
BENCHMARK_TEMPLATE(BM_PgadExpSeries, 7);

template <int D>
void BM_PgadLogClosedForm(benchmark::State& s) {
  const auto m = pgad::exp(random_pgad_bivector<D>(11));
  for (auto _ : s) {
    benchmark::DoNotOptimize(m);
    benchmark::DoNotOptimize(pgad::log(m));
  }
}
BENCHMARK_TEMPLATE(BM_PgadLogClosedForm, 4);
BENCHMARK_TEMPLATE(BM_PgadLogClosedForm, 7);

}  // namespace

BENCHMARK_MAIN();
