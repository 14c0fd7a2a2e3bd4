// Reader throughput: an icosphere (sphere-like, 20·4^level triangles, coordinates rounded to 7
// significant digits as exporters print them) is written in every format in memory, then parsed.
// Reports bytes/s (MB/s) and triangles/s per format, and the summing ASCII STL reader of `props
// --no-topology` (the reader's grammar with a summing consumer, no Mesh) on 1 and 2 threads. Level
// from PGAMESH_BENCH_LEVEL (default 7: 327 680 triangles; 8 gives 1.3 million).
//   build/release/bench/bench_readers --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "mesh/mass/stl_ascii_sums.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/primitives.hpp"

using namespace pgamesh;

namespace {

int bench_level() {
  const char* s = std::getenv("PGAMESH_BENCH_LEVEL");
  const int level = s ? std::atoi(s) : 7;
  return level < 1 ? 1 : (level > 9 ? 9 : level);
}

double seven_digits(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6e", x);
  return std::strtod(buf, nullptr);
}

const Mesh& sphere() {
  static const Mesh m = [] {
    Mesh s = icosphere(bench_level(), 10.0);
    for (Vec3d& v : s.vertices) v = {seven_digits(v.x), seven_digits(v.y), seven_digits(v.z)};
    return s;
  }();
  return m;
}

const std::string& file_bytes(MeshFormat f) {
  static std::map<MeshFormat, std::string> cache;
  auto it = cache.find(f);
  if (it == cache.end()) {
    WriteOptions o;
    o.single_precision = true;  // PLY float32, as most PLY files are
    it = cache.emplace(f, write_mesh_bytes(sphere(), f, o)).first;
  }
  return it->second;
}

void read_format(benchmark::State& state, MeshFormat f) {
  const std::string& bytes = file_bytes(f);
  std::size_t faces = 0;
  for (auto _ : state) {
    const Mesh m = read_mesh_bytes({bytes.data(), bytes.size()}, "bench");
    faces = m.face_count();
    benchmark::DoNotOptimize(m.vertices.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["triangles/s"] =
      benchmark::Counter(static_cast<double>(faces) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["file_MB"] = static_cast<double>(bytes.size()) / 1e6;
  state.SetLabel(format_name(f));
}

// The summing ASCII STL reader of `props --no-topology` (the reader's grammar handing the facets of
// each piece to a summing consumer, no Mesh) on state.range(0) threads; CPU time is that of the
// calling thread only, so compare wall times between thread counts.
void summed_stl_ascii(benchmark::State& state) {
  const std::string& bytes = file_bytes(MeshFormat::stl_ascii);
  MassOptions o;
  o.threads = static_cast<unsigned>(state.range(0));
  double volume = 0;
  for (auto _ : state) {
    MeshSource source;
    volume = ascii_stl_mass_properties({bytes.data(), bytes.size()}, "bench", source, o).volume;
    benchmark::DoNotOptimize(volume);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * bytes.size()));
  state.counters["file_MB"] = static_cast<double>(bytes.size()) / 1e6;
}

void write_format(benchmark::State& state, MeshFormat f) {
  std::size_t size = 0;
  for (auto _ : state) {
    const std::string bytes = write_mesh_bytes(sphere(), f);
    size = bytes.size();
    benchmark::DoNotOptimize(bytes.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * size));
  state.SetLabel(format_name(f));
}

}  // namespace

BENCHMARK_CAPTURE(read_format, stl_ascii, MeshFormat::stl_ascii)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, stl_binary, MeshFormat::stl_binary)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, obj, MeshFormat::obj)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, ply_ascii, MeshFormat::ply_ascii)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, ply_binary_le, MeshFormat::ply_binary_le)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, ply_binary_be, MeshFormat::ply_binary_be)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(read_format, off, MeshFormat::off)->Unit(benchmark::kMillisecond);
BENCHMARK(summed_stl_ascii)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(write_format, stl_ascii, MeshFormat::stl_ascii)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(write_format, obj, MeshFormat::obj)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(write_format, stl_binary, MeshFormat::stl_binary)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
