// pgamesh::cga (conformal R(4,1) in the null basis e_o, e1, e2, e3, e_∞): the vector × vector
// product, versor sandwiches of a point, objects from points, and the sphere fit of 10⁶ points.
// Compare with the ~6–30 ns per product that compile-time C++ GA libraries report for 3-D CGA.
// Run: build/release/bench/bench_cga   (figures: docs/models-cga.md §9)
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "pgamesh/models/cga.hpp"

using namespace pgamesh;
using namespace pgamesh::cga;

namespace {

constexpr std::size_t lanes = 64;  // inputs cycled through, so nothing is constant-folded

std::array<Vec3d, lanes> random_points(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-2, 2);
  std::array<Vec3d, lanes> out{};
  for (auto& p : out) p = {u(rng), u(rng), u(rng)};
  return out;
}

void BM_CgaGeometricVectorVector(benchmark::State& s) {
  const auto a = random_points(1), b = random_points(2);
  std::array<Vector, lanes> x{}, y{};
  for (std::size_t i = 0; i < lanes; ++i) {
    x[i] = up(a[i]);
    y[i] = up(b[i]) + einf(0.25);  // a dual sphere: all five coefficients non-zero
  }
  std::size_t i = 0;
  for (auto _ : s) {
    auto p = x[i] * y[i];
    benchmark::DoNotOptimize(p);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaGeometricVectorVector);

void BM_CgaRotorSandwichPoint(benchmark::State& s) {
  const auto p = random_points(3);
  std::array<Rotor, lanes> r{};
  std::array<Vector, lanes> x{};
  for (std::size_t i = 0; i < lanes; ++i) {
    r[i] = rotor(p[(i + 7) % lanes], 0.1 * static_cast<double>(i));
    x[i] = up(p[i]);
  }
  std::size_t i = 0;
  for (auto _ : s) {
    auto y = sandwich(r[i], x[i]);
    benchmark::DoNotOptimize(y);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaRotorSandwichPoint);

void BM_CgaMotorSandwichPoint(benchmark::State& s) {
  const auto p = random_points(4);
  std::array<Versor, lanes> m{};
  std::array<Vector, lanes> x{};
  for (std::size_t i = 0; i < lanes; ++i) {
    m[i] = motor(rotor(p[(i + 7) % lanes], 0.1 * static_cast<double>(i)), p[(i + 3) % lanes]);
    x[i] = up(p[i]);
  }
  std::size_t i = 0;
  for (auto _ : s) {
    auto y = sandwich(m[i], x[i]);
    benchmark::DoNotOptimize(y);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaMotorSandwichPoint);

void BM_CgaOuterFourPoints(benchmark::State& s) {
  const auto p = random_points(5);
  std::array<Vector, lanes> x{};
  for (std::size_t i = 0; i < lanes; ++i) x[i] = up(p[i]);
  std::size_t i = 0;
  for (auto _ : s) {
    auto v4 = x[i] ^ x[(i + 1) % lanes] ^ x[(i + 2) % lanes] ^ x[(i + 3) % lanes];
    benchmark::DoNotOptimize(v4);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaOuterFourPoints);

void BM_CgaSphereFromPoints(benchmark::State& s) {  // checked, about the first point
  const auto p = random_points(6);
  std::size_t i = 0;
  for (auto _ : s) {
    auto v4 = sphere(p[i], p[(i + 1) % lanes], p[(i + 2) % lanes], p[(i + 3) % lanes]);
    benchmark::DoNotOptimize(v4);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaSphereFromPoints);

void BM_CgaSphereParams(benchmark::State& s) {
  const auto p = random_points(7);
  std::array<Quadvector, lanes> v{};
  for (std::size_t i = 0; i < lanes; ++i)
    v[i] = sphere(p[i], p[(i + 1) % lanes], p[(i + 2) % lanes], p[(i + 3) % lanes]);
  std::size_t i = 0;
  for (auto _ : s) {
    auto r = sphere_params(v[i]);
    benchmark::DoNotOptimize(r);
    i = (i + 1) % lanes;
  }
}
BENCHMARK(BM_CgaSphereParams);

void BM_CgaFitSphere(benchmark::State& s) {
  const auto n = static_cast<std::size_t>(s.range(0));
  std::mt19937_64 rng(8);
  std::normal_distribution<double> g(0, 1), noise(0, 0.01);
  std::vector<Vec3d> pts(n);
  for (auto& q : pts) {
    Vec3d d{g(rng), g(rng), g(rng)};
    d = d / length(d);
    q = Vec3d{1, 2, 3} + (5 + noise(rng)) * d;
  }
  for (auto _ : s) {
    auto f = fit_sphere(pts);
    benchmark::DoNotOptimize(f);
  }
  s.SetItemsProcessed(static_cast<std::int64_t>(s.iterations() * n));
}
BENCHMARK(BM_CgaFitSphere)->Arg(1000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
