// Google Benchmark: QCGA point test, line–quadric intersection, 10⁶-point quadric fit
// (docs/models-quadrics.md §8).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "pgamesh/algebra/clifford/products.hpp"
#include "pgamesh/models/quadric_convert.hpp"

using namespace pgamesh;

namespace {

std::vector<Vec3d> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Vec3d> out(n);
  for (auto& p : out) p = {u(rng), u(rng), u(rng)};
  return out;
}

const quadric::Quadric& ellipsoid() {
  static const quadric::Quadric q =
      quadric::translate(quadric::rotate(quadric::ellipsoid({0, 0, 0}, {3, 2, 1}),
                                         quadric::axis_rotation({1, 2, 3}, 0.4)),
                         {0.5, -1, 2});
  return q;
}

void BM_QcgaPointTest(benchmark::State& state) {
  const qcga::Vector qs = qcga::dual_quadric(ellipsoid());
  const auto pts = random_points(1024, 1);
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(qcga::value(qs, pts[k++ & 1023]));
  }
}
BENCHMARK(BM_QcgaPointTest);

void BM_QcgaPointTestEmbedded(benchmark::State& state) {  // x = point(p), then x·q*
  const qcga::Vector qs = qcga::dual_quadric(ellipsoid());
  const auto pts = random_points(1024, 1);
  std::size_t k = 0;
  for (auto _ : state) {
    const qcga::Vector x = qcga::point(pts[k++ & 1023]);
    benchmark::DoNotOptimize(qcga::inner(x, qs));
  }
}
BENCHMARK(BM_QcgaPointTestEmbedded);

void BM_QcgaPointTestEngine(benchmark::State& state) {  // the full R(9,6) scalar product
  const auto qs = qcga::to_clifford(qcga::dual_quadric(ellipsoid()));
  const auto pts = random_points(1024, 1);
  std::size_t k = 0;
  for (auto _ : state) {
    const auto x = qcga::to_clifford(qcga::point(pts[k++ & 1023]));
    benchmark::DoNotOptimize(clifford::scalar_product(qcga::algebra(), x, qs));
  }
}
BENCHMARK(BM_QcgaPointTestEngine);

void BM_LineQuadricIntersection(benchmark::State& state) {
  const qcga::Vector qs = qcga::dual_quadric(ellipsoid());
  const auto o = random_points(1024, 2), d = random_points(1024, 3);
  std::size_t k = 0;
  for (auto _ : state) {
    const std::size_t n = k++ & 1023;
    benchmark::DoNotOptimize(qcga::intersect_line(qs, o[n], d[n]));
  }
}
BENCHMARK(BM_LineQuadricIntersection);

void BM_DpgaPointTestGraded(benchmark::State& state) {
  const auto q = dpga::quadric(ellipsoid());
  const auto pts = random_points(1024, 1);
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(dpga::value(q, pts[k++ & 1023]));
}
BENCHMARK(BM_DpgaPointTestGraded);

void BM_Fit1e6(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> noise(0, 1e-3);
  std::vector<Vec3d> pts(n);
  for (auto& p : pts) {
    const double th = std::acos(2 * u(rng) - 1), ph = 2 * M_PI * u(rng);
    p = {0.5 + 3 * std::sin(th) * std::cos(ph) + noise(rng),
         -1 + 2 * std::sin(th) * std::sin(ph) + noise(rng), 2 + std::cos(th) + noise(rng)};
  }
  for (auto _ : state) benchmark::DoNotOptimize(quadric::fit(pts));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_Fit1e6)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_NinePointsClosedForm(benchmark::State& state) {
  std::array<Vec3d, 9> pts;
  for (int n = 0; n < 9; ++n)
    pts[static_cast<std::size_t>(n)] = {0.5 + 3 * std::sin(0.3 + 0.31 * n) * std::cos(0.7 * n * n),
                                        -1 + 2 * std::sin(0.3 + 0.31 * n) * std::sin(0.7 * n * n),
                                        2 + std::cos(0.3 + 0.31 * n)};
  for (auto _ : state) benchmark::DoNotOptimize(qcga::quadric_from_points(pts));
}
BENCHMARK(BM_NinePointsClosedForm);

}  // namespace

BENCHMARK_MAIN();
