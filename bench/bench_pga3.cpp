// Core PGA3 operations (ns per operation): motor × motor, the motor sandwich of a point, a plane
// and a line, the join of three points (a triangle carrier), exp of a bivector, log of a motor,
// and the general 16-component geometric product for comparison. Each benchmark walks a ring of
// 1024 random inputs so the compiler cannot fold them.
//   build/release/bench/bench_pga3 --benchmark_min_time=0.2s
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"

namespace {

using namespace pgamesh;
using namespace pgamesh::pga3;

constexpr std::size_t kRing = 1024;

template <class T>
struct Inputs {
  std::vector<Motor<T>> motors;
  std::vector<Point<T>> points;
  std::vector<Plane<T>> planes;
  std::vector<Line<T>> lines;
  std::vector<Multivector<T>> multivectors;

  Inputs() {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<T> u(-1, 1);
    for (std::size_t i = 0; i < kRing; ++i) {
      const Line<T> b{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)};
      motors.push_back(exp(b));
      points.push_back(point(u(rng), u(rng), u(rng)));
      planes.push_back(plane(u(rng), u(rng), u(rng), u(rng)));
      lines.push_back(b);
      Multivector<T> m;
      for (T& c : m.c) c = u(rng);
      multivectors.push_back(m);
    }
  }
};

template <class T>
const Inputs<T>& inputs() {
  static const Inputs<T> in;
  return in;
}

template <class T>
void BM_MotorTimesMotor(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.motors[i] * in.motors[(i + 1) % kRing]);
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_SandwichPoint(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(apply(in.motors[i], in.points[i]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_SandwichPlane(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(apply(in.motors[i], in.planes[i]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_SandwichLine(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(apply(in.motors[i], in.lines[i]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_JoinThreePoints(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        join(in.points[i], in.points[(i + 1) % kRing], in.points[(i + 2) % kRing]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_Exp(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(exp(in.lines[i]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_Log(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(log(in.motors[i]));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_GeneralGeometricProduct(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.multivectors[i] * in.multivectors[(i + 1) % kRing]);
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

template <class T>
void BM_GeneralSandwichPoint(benchmark::State& state) {
  const auto& in = inputs<T>();
  std::size_t i = 0;
  for (auto _ : state) {
    const Multivector<T> m = to_multivector(in.motors[i]);
    benchmark::DoNotOptimize(m * to_multivector(in.points[i]) * reverse(m));
    i = (i + 1) % kRing;
  }
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_MotorTimesMotor<double>);
BENCHMARK(BM_MotorTimesMotor<float>);
BENCHMARK(BM_SandwichPoint<double>);
BENCHMARK(BM_SandwichPoint<float>);
BENCHMARK(BM_SandwichPlane<double>);
BENCHMARK(BM_SandwichPlane<float>);
BENCHMARK(BM_SandwichLine<double>);
BENCHMARK(BM_JoinThreePoints<double>);
BENCHMARK(BM_JoinThreePoints<float>);
BENCHMARK(BM_Exp<double>);
BENCHMARK(BM_Exp<float>);
BENCHMARK(BM_Log<double>);
BENCHMARK(BM_Log<float>);
BENCHMARK(BM_GeneralGeometricProduct<double>);
BENCHMARK(BM_GeneralSandwichPoint<double>);

}  // namespace

BENCHMARK_MAIN();
