// Fuel queries on a 10⁶-triangle capsule tank, each accelerated path against the naive full
// pass per query, in one run:
//   table    1000 levels, one up vector: sorted sweep vs 1000 full passes
//   attitude 1000 random planes: hierarchy with accumulated sums vs full passes
//   inverse  level for a volume: Newton over the hierarchy vs Newton over full passes
// Each benchmark reports the time per query (or per solve) as the counter `per_item`; the
// naive inverse runs 100 solves (each costs ~10 full passes) to keep the run short.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"

using namespace pgamesh;
using namespace pgamesh::tank;

namespace {

const Tank& big_tank() {
  // 1000 segments × 500 latitude rings: 1 000 000 triangles.
  static const Tank t = make_tank(capsule(0.6, 2.0, 1000, 250));
  return t;
}

const FuelIndex& big_index() {
  static const FuelIndex index(big_tank());
  return index;
}

struct Query {
  Vec3d up;
  double level;
  double volume;
};

// 1000 random attitudes (up within 60° of +z and any heading) and levels within the tank.
const std::vector<Query>& random_queries() {
  static const std::vector<Query> q = [] {
    std::vector<Query> out;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> uni(0, 1);
    const Tank& t = big_tank();
    for (int i = 0; i < 1000; ++i) {
      const double polar = 1.05 * uni(rng), azimuth = 6.283185307179586 * uni(rng);
      const Vec3d up{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                     std::cos(polar)};
      const LevelRange r = level_range(t, up);
      out.push_back({up, r.lowest + (0.02 + 0.96 * uni(rng)) * (r.highest - r.lowest),
                     (0.01 + 0.98 * uni(rng)) * t.volume});
    }
    return out;
  }();
  return q;
}

void per_item(benchmark::State& state, double items) {
  state.counters["per_item"] = benchmark::Counter(
      items, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_PrepareTank(benchmark::State& state) {
  const Mesh m = capsule(0.6, 2.0, 1000, 250);
  for (auto _ : state) benchmark::DoNotOptimize(make_tank(m).volume);
  state.counters["triangles"] = static_cast<double>(m.face_count());
}

void BM_BuildIndex(benchmark::State& state) {
  for (auto _ : state) {
    const FuelIndex index(big_tank());
    benchmark::DoNotOptimize(index.node_count());
  }
}

void BM_Table1000_Sweep(benchmark::State& state) {
  const Tank& t = big_tank();
  const Vec3d up{0.1, -0.2, 1};
  const auto levels = even_levels(level_range(t, unit_up(up)), 999);
  for (auto _ : state) benchmark::DoNotOptimize(fuel_sweep(t, up, levels).back().volume);
  per_item(state, 1000);
}

void BM_Table1000_Naive(benchmark::State& state) {
  const Tank& t = big_tank();
  const Vec3d up = unit_up({0.1, -0.2, 1});
  const auto levels = even_levels(level_range(t, up), 999);
  for (auto _ : state)
    for (double level : levels) benchmark::DoNotOptimize(fuel_naive(t, {up, level}).volume);
  per_item(state, 1000);
}

void BM_RandomAttitude1000_Index(benchmark::State& state) {
  const FuelIndex& index = big_index();
  for (auto _ : state)
    for (const Query& q : random_queries())
      benchmark::DoNotOptimize(index.query({q.up, q.level}).volume);
  per_item(state, 1000);
}

void BM_RandomAttitude1000_Naive(benchmark::State& state) {
  const Tank& t = big_tank();
  for (auto _ : state)
    for (const Query& q : random_queries())
      benchmark::DoNotOptimize(fuel_naive(t, {q.up, q.level}).volume);
  per_item(state, 1000);
}

void BM_Inverse1000_Index(benchmark::State& state) {
  const FuelIndex& index = big_index();
  for (auto _ : state)
    for (const Query& q : random_queries())
      benchmark::DoNotOptimize(level_for_volume(index, q.up, q.volume).level);
  per_item(state, 1000);
}

void BM_Inverse100_Naive(benchmark::State& state) {
  const Tank& t = big_tank();
  const auto& qs = random_queries();
  for (auto _ : state)
    for (std::size_t i = 0; i < 100; ++i) {
      const Query& q = qs[i];
      const auto naive = [&](const FuelPlane& p) { return fuel_naive(t, p); };
      benchmark::DoNotOptimize(
          level_for_volume(naive, q.up, level_range(t, q.up), t.volume, q.volume).level);
    }
  per_item(state, 100);
}

}  // namespace

BENCHMARK(BM_PrepareTank)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_BuildIndex)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Table1000_Sweep)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Table1000_Naive)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_RandomAttitude1000_Index)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_RandomAttitude1000_Naive)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Inverse1000_Index)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_Inverse100_Naive)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();
