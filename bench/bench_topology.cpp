// Topology speed: the exact weld of an STL-like vertex soup (three fresh vertices per triangle)
// and the whole analyze_topology pass (weld, edges, components, loops, defects, sums), on
// icospheres of 81 920 to 5 242 880 triangles. Not a test: nothing here asserts a time.
//   build/release/bench/bench_topology --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <vector>

#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/mesh/topology.hpp"
#include "pgamesh/mesh/weld.hpp"

using namespace pgamesh;

namespace {

// The icosphere of `level` with every triangle given its own vertex copies, as read from an STL
// (level 6: 81 920 triangles, 8: 1 310 720, 9: 5 242 880).
const Mesh& soup(int level) {
  static std::vector<Mesh> cache(11);
  if (cache[level].vertices.empty()) {
    const Mesh m = icosphere(level, 1.0);
    Mesh& s = cache[level];
    s.vertices.reserve(m.corners.size());
    for (std::uint32_t c : m.corners) {
      s.corners.push_back(static_cast<std::uint32_t>(s.vertices.size()));
      s.vertices.push_back(m.vertices[c]);
    }
    s.face_offsets = m.face_offsets;
  }
  return cache[level];
}

void BM_WeldExact(benchmark::State& state) {
  const Mesh& m = soup(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    WeldMap w = weld_map(m.vertices);
    benchmark::DoNotOptimize(w.representative.data());
  }
  state.counters["corners"] = static_cast<double>(m.vertices.size());
  state.counters["corners/s"] = benchmark::Counter(static_cast<double>(m.vertices.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_WeldExact)->Arg(6)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond);

void BM_AnalyzeTopology(benchmark::State& state) {
  const Mesh& m = soup(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    TopologyReport r = analyze_topology(m);
    benchmark::DoNotOptimize(r.edges);
  }
  state.counters["triangles"] = static_cast<double>(m.face_count());
  state.counters["triangles/s"] = benchmark::Counter(static_cast<double>(m.face_count()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AnalyzeTopology)->Arg(6)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
