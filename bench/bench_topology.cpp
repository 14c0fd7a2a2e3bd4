// Topology speed: the exact weld of an STL-like vertex soup (three fresh vertices per triangle),
// the weld of binary STL records, the topology pass on welded triangles, the whole
// analyze_topology pass (weld, edges, components, loops, defects, sums) and the same pass walking
// the triangles as polygons, on icospheres of 81 920 to 5 242 880 triangles. Not a test: nothing
// here asserts a time.
//   build/release/bench/bench_topology --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstring>
#include <vector>

#include "mesh/topology/welded_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

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

// The same soup as binary STL bytes (float32 records, little-endian hosts).
const std::vector<char>& stl_bytes(int level) {
  static std::vector<std::vector<char>> cache(11);
  std::vector<char>& out = cache[level];
  if (out.empty()) {
    const Mesh& m = soup(level);
    const std::size_t n = m.face_count();
    out.assign(stl_header_bytes + stl_record_bytes * n, 0);
    const auto count = static_cast<std::uint32_t>(n);
    std::memcpy(out.data() + 80, &count, 4);
    for (std::size_t t = 0; t < n; ++t)
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) {
          const auto f = static_cast<float>(m.vertices[3 * t + k][j]);
          std::memcpy(out.data() + stl_header_bytes + stl_record_bytes * t + 12 + 12 * k + 4 * j,
                      &f, 4);
        }
  }
  return out;
}

void set_counters(benchmark::State& state, double triangles) {
  state.counters["triangles"] = triangles;
  state.counters["triangles/s"] =
      benchmark::Counter(triangles, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_WeldExact(benchmark::State& state) {
  const Mesh& m = soup(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    WeldMap w = weld_map(m.vertices);
    benchmark::DoNotOptimize(w.representative.data());
  }
  set_counters(state, static_cast<double>(m.face_count()));
}
BENCHMARK(BM_WeldExact)->Arg(6)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();

// weld_binary_stl on bytes in memory (two threads above 65 536 records).
void BM_WeldBinaryStl(benchmark::State& state) {
  const std::vector<char>& bytes = stl_bytes(static_cast<int>(state.range(0)));
  const BinaryStlView view = *binary_stl_view(bytes, "soup.stl");
  for (auto _ : state) {
    WeldedTriangles w = weld_binary_stl(view, "soup.stl");
    benchmark::DoNotOptimize(w.corners.data());
  }
  set_counters(state, static_cast<double>(view.count));
}
BENCHMARK(BM_WeldBinaryStl)->Arg(6)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();

// The pass alone on welded triangles (edge pass and face tally on two threads).
void BM_AnalyzeWeldedTriangles(benchmark::State& state) {
  const std::vector<char>& bytes = stl_bytes(static_cast<int>(state.range(0)));
  const WeldedTriangles w = weld_binary_stl(*binary_stl_view(bytes, "soup.stl"), "soup.stl");
  const Vec3d ref = bounding_box(w.positions).centre();
  for (auto _ : state) {
    TopologyReport r = analyze_welded_triangles(w, ref);
    benchmark::DoNotOptimize(r.edges);
  }
  set_counters(state, static_cast<double>(w.triangle_count()));
}
BENCHMARK(BM_AnalyzeWeldedTriangles)
    ->Arg(6)
    ->Arg(8)
    ->Arg(9)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// analyze_topology on a Mesh soup: weld_triangles, then the pass on welded triangles.
void BM_AnalyzeTopology(benchmark::State& state) {
  const Mesh& m = soup(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    TopologyReport r = analyze_topology(m);
    benchmark::DoNotOptimize(r.edges);
  }
  set_counters(state, static_cast<double>(m.face_count()));
}
BENCHMARK(BM_AnalyzeTopology)->Arg(6)->Arg(8)->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same soup welded as a polygon mesh and walked through the polygon layout of the pass
// (face_layout.hpp), for comparison with the triangle layout above.
void BM_AnalyzeWeldedMesh(benchmark::State& state) {
  const Mesh& m = soup(static_cast<int>(state.range(0)));
  const Vec3d ref = bounding_box(m.vertices).centre();
  for (auto _ : state) {
    TopologyReport r = analyze_welded_mesh(weld(m), ref);
    benchmark::DoNotOptimize(r.edges);
  }
  set_counters(state, static_cast<double>(m.face_count()));
}
BENCHMARK(BM_AnalyzeWeldedMesh)
    ->Arg(6)
    ->Arg(8)
    ->Arg(9)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
