// Mass-property accumulation speed: per-triangle cost of the boundary sums (paper Table 1,
// eqs. 5.3–5.6), whole mass_properties() on a Mesh, and the streamed binary STL path in MB/s.
//   build/release/bench/bench_mass_properties --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <cstring>
#include <vector>

#include "mesh/mass/stl_mass_properties.hpp"
#include "mesh/topology/welded_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/primitives.hpp"

using namespace pgamesh;

namespace {

// icosphere level 6: 81 920 triangles; level 8: 1 310 720.
const Mesh& sphere(int level) {
  static std::vector<Mesh> cache(11);
  if (cache[level].vertices.empty()) cache[level] = icosphere(level, 1.0);
  return cache[level];
}

std::vector<char> stl_of(const Mesh& m) {
  std::vector<char> out(84 + 50 * m.face_count(), 0);
  const auto count = static_cast<std::uint32_t>(m.face_count());
  std::memcpy(out.data() + 80, &count, 4);
  char* r = out.data() + 84;
  for (std::size_t f = 0; f < m.face_count(); ++f, r += 50)
    for (int k = 0; k < 3; ++k) {
      const Vec3d v = m.vertices[m.face(f)[k]];
      const float xyz[3] = {static_cast<float>(v.x), static_cast<float>(v.y),
                            static_cast<float>(v.z)};
      std::memcpy(r + 12 + 12 * k, xyz, 12);
    }
  return out;
}

// The wall or CPU time per triangle, of `triangles` per iteration, as the counter ns_per_triangle.
void set_ns_per_triangle(benchmark::State& state, std::size_t triangles) {
  state.counters["ns_per_triangle"] =
      benchmark::Counter(static_cast<double>(state.iterations() * triangles),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The binary STL of sphere(8), made once.
const std::vector<char>& sphere_stl() {
  static const std::vector<char> bytes = stl_of(sphere(8));
  return bytes;
}

// The bare per-triangle sums, one thread, vertices already relative to the reference point.
void BM_AddTriangle(benchmark::State& state) {
  const Mesh& m = sphere(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    BoundarySums s;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      const std::uint32_t* c = m.face(f);
      add_triangle(s, m.vertices[c[0]], m.vertices[c[1]], m.vertices[c[2]]);
    }
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.face_count()));
  set_ns_per_triangle(state, m.face_count());
}
BENCHMARK(BM_AddTriangle)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);

// mass_properties(Mesh): reference point, sums, Jacobi; threads = range(1).
void BM_MassPropertiesMesh(benchmark::State& state) {
  const Mesh& m = sphere(static_cast<int>(state.range(0)));
  MassOptions opt;
  opt.threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(mass_properties(m, opt));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(m.face_count()));
  set_ns_per_triangle(state, m.face_count());
}
BENCHMARK(BM_MassPropertiesMesh)
    ->Args({8, 1})
    ->Args({8, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The streamed binary STL path from bytes in memory: MB/s of STL; threads = range(1).
void BM_StreamedStl(benchmark::State& state) {
  const std::vector<char>& bytes = sphere_stl();
  const auto view = binary_stl_view(bytes, "bench.stl");
  MassOptions opt;
  opt.threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(binary_stl_mass_properties(*view, "bench.stl", opt));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes.size()));
  set_ns_per_triangle(state, view->count);
}
BENCHMARK(BM_StreamedStl)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The exact weld of the binary STL records (welded_triangles.hpp), both cores: ns per triangle.
void BM_WeldBinaryStl(benchmark::State& state) {
  const std::vector<char>& bytes = sphere_stl();
  const auto view = binary_stl_view(bytes, "bench.stl");
  for (auto _ : state) benchmark::DoNotOptimize(weld_binary_stl(*view, "bench.stl"));
  set_ns_per_triangle(state, view->count);
}
BENCHMARK(BM_WeldBinaryStl)->Unit(benchmark::kMillisecond)->UseRealTime();

// The topology and mass pass on the welded triangles (welded_topology.hpp) that `pgamesh props`
// runs after the weld: face sums, edges, loops, orientation, components.
void BM_WeldedTriangleProps(benchmark::State& state) {
  const std::vector<char>& bytes = sphere_stl();
  const auto view = binary_stl_view(bytes, "bench.stl");
  const WeldedTriangles welded = weld_binary_stl(*view, "bench.stl");
  for (auto _ : state)
    benchmark::DoNotOptimize(
        analyze_welded_triangles(welded, Vec3d{0, 0, 0}, MassOptions{}, TopologyOptions{}, true));
  set_ns_per_triangle(state, view->count);
}
BENCHMARK(BM_WeldedTriangleProps)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
