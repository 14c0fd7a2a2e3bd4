// The general Clifford engine, the compile-time PGA R(d,0,1) and the PGA3 fast path, side by side.
// Compare the R(4,1) products with the ~6–30 ns per product that compile-time C++ GA libraries
// report for 3-D CGA; the R(9,6) outer product of nine vectors shows the sparse engine at 32768
// blades. Run: build/release/bench/bench_clifford
#include <benchmark/benchmark.h>

#include <random>

#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/graded.hpp"
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

// ---- R(4,1) with compile-time graded multivectors (pgamesh::graded)
// ------------------------------ Inputs cycle through 64 random values so that no product can be
// hoisted out of the loop, and every result goes through DoNotOptimize.

using R41 = graded::Algebra<4, 1>;
constexpr std::size_t graded_inputs = 64;

template <class M>
std::vector<M> random_inputs(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<M> out(graded_inputs);
  for (M& m : out)
    for (double& c : m.c) c = u(rng);
  return out;
}

// Rotors exp(B) of random bivectors (the engine's exp), as graded even multivectors.
std::vector<graded::Even<R41>> random_rotors(std::mt19937_64& rng) {
  const auto alg = graded::runtime_algebra<R41>();
  std::vector<graded::Even<R41>> out;
  for (const auto& b : random_inputs<graded::Bivector<R41>>(rng))
    out.push_back(
        graded::from_clifford<graded::Even<R41>>(clifford::exp(alg, 0.3 * graded::to_clifford(b))));
  return out;
}

// Conformal points X = x + ½x² e∞ + e_o with e∞ = e4 + e5, e_o = ½(e5 − e4) (docs/conventions.md
// §15).
graded::Vector<R41> conformal_point(double x, double y, double z) {
  const double h = 0.5 * (x * x + y * y + z * z);
  return {{x, y, z, h - 0.5, h + 0.5}};
}

template <class M1, class M2, class F>
void run_graded(benchmark::State& s, std::uint64_t seed, F f) {
  std::mt19937_64 rng(seed);
  const auto a = random_inputs<M1>(rng);
  const auto b = random_inputs<M2>(rng);
  std::size_t i = 0;
  for (auto _ : s) {
    benchmark::DoNotOptimize(f(a[i], b[i]));
    i = (i + 1) % graded_inputs;
  }
}

void BM_Graded_R41_GeometricVectorVector(benchmark::State& s) {
  run_graded<graded::Vector<R41>, graded::Vector<R41>>(
      s, 21, [](const auto& a, const auto& b) { return a * b; });
}
BENCHMARK(BM_Graded_R41_GeometricVectorVector);

void BM_Graded_R41_GeometricEvenEven(benchmark::State& s) {
  run_graded<graded::Even<R41>, graded::Even<R41>>(
      s, 22, [](const auto& a, const auto& b) { return a * b; });
}
BENCHMARK(BM_Graded_R41_GeometricEvenEven);

void BM_Graded_R41_GeometricFullFull(benchmark::State& s) {
  run_graded<graded::Full<R41>, graded::Full<R41>>(
      s, 23, [](const auto& a, const auto& b) { return a * b; });
}
BENCHMARK(BM_Graded_R41_GeometricFullFull);

void BM_Graded_R41_SandwichRotorOnVector(benchmark::State& s) {
  std::mt19937_64 rng(24);
  const auto r = random_rotors(rng);
  const auto x = random_inputs<graded::Vector<R41>>(rng);
  std::size_t i = 0;
  for (auto _ : s) {
    benchmark::DoNotOptimize(graded::sandwich(r[i], x[i]));
    i = (i + 1) % graded_inputs;
  }
}
BENCHMARK(BM_Graded_R41_SandwichRotorOnVector);

std::vector<graded::Vector<R41>> random_conformal_points(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<graded::Vector<R41>> out;
  for (std::size_t i = 0; i < graded_inputs + 2; ++i)
    out.push_back(conformal_point(u(rng), u(rng), u(rng)));
  return out;
}

void BM_Graded_R41_OuterOfThreeConformalPoints(benchmark::State& s) {
  std::mt19937_64 rng(25);
  const auto p = random_conformal_points(rng);
  std::size_t i = 0;
  for (auto _ : s) {
    benchmark::DoNotOptimize(p[i] ^ p[i + 1] ^ p[i + 2]);  // the circle through three points
    i = (i + 1) % graded_inputs;
  }
}
BENCHMARK(BM_Graded_R41_OuterOfThreeConformalPoints);

void BM_R41_OuterOfThreeConformalPoints(benchmark::State& s) {  // the general engine, same input
  const auto alg = graded::runtime_algebra<R41>();
  std::mt19937_64 rng(25);
  std::vector<Multivector> p;
  for (const auto& x : random_conformal_points(rng)) p.push_back(graded::to_clifford(x));
  std::size_t i = 0;
  for (auto _ : s) {
    benchmark::DoNotOptimize(clifford::outer(alg, clifford::outer(alg, p[i], p[i + 1]), p[i + 2]));
    i = (i + 1) % graded_inputs;
  }
}
BENCHMARK(BM_R41_OuterOfThreeConformalPoints);

void BM_Graded_Pga3JoinThreePoints(benchmark::State& s) {
  using R301 = graded::Algebra<3, 0, 1>;
  std::mt19937_64 rng(26);
  const auto p = random_inputs<graded::KVector<R301, 3>>(rng);
  std::size_t i = 0;
  for (auto _ : s) {
    benchmark::DoNotOptimize(p[i] & p[(i + 1) % graded_inputs] & p[(i + 2) % graded_inputs]);
    i = (i + 1) % graded_inputs;
  }
}
BENCHMARK(BM_Graded_Pga3JoinThreePoints);

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
