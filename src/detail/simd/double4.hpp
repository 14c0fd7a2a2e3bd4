// Four doubles operated on lane by lane: the number type that lets the scalar formulas of
// body_moments.hpp sum four faces at once (chunked_sums.hpp's lanes). Every operation is the IEEE
// operation of each lane on its own (no fused multiply–add, no reassociation), so lane j holds
// bit for bit what the same formula gives in double for the face of lane j.
//
// Stored as two 2-lane vectors (GCC/Clang vector extension), the width every x86-64 processor has
// (SSE2); targets without vector registers get the same arithmetic lane by lane.
#pragma once

#include <cmath>

#include "pgamesh/core/vec3.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pgamesh {

struct Double4 {
  using Pair = double __attribute__((vector_size(16)));
  Pair lo{}, hi{};  // lanes 0, 1 and 2, 3

  constexpr Double4() = default;
  constexpr Double4(Pair l, Pair h) : lo(l), hi(h) {}
  // Every lane s (a scalar in the formulas, such as a constant or the reference point).
  constexpr Double4(double s) : lo{s, s}, hi{s, s} {}  // NOLINT: implicit, as a double converts
  constexpr Double4(double l0, double l1, double l2, double l3) : lo{l0, l1}, hi{l2, l3} {}

  double lane(int j) const { return j < 2 ? lo[j] : hi[j - 2]; }

  friend constexpr Double4 operator+(Double4 a, Double4 b) { return {a.lo + b.lo, a.hi + b.hi}; }
  friend constexpr Double4 operator-(Double4 a, Double4 b) { return {a.lo - b.lo, a.hi - b.hi}; }
  friend constexpr Double4 operator*(Double4 a, Double4 b) { return {a.lo * b.lo, a.hi * b.hi}; }
  friend constexpr Double4 operator/(Double4 a, Double4 b) { return {a.lo / b.lo, a.hi / b.hi}; }
  friend constexpr Double4 operator-(Double4 a) { return {-a.lo, -a.hi}; }
  constexpr Double4& operator+=(Double4 b) { return *this = *this + b; }
  constexpr Double4& operator-=(Double4 b) { return *this = *this - b; }

  // The correctly rounded square root of each lane (found by argument-dependent lookup, so
  // generic code calls `using std::sqrt; sqrt(x)`).
  friend Double4 sqrt(Double4 a) {
#if defined(__SSE2__)
    return {_mm_sqrt_pd(a.lo), _mm_sqrt_pd(a.hi)};
#else
    return {std::sqrt(a.lo[0]), std::sqrt(a.lo[1]), std::sqrt(a.hi[0]), std::sqrt(a.hi[1])};
#endif
  }
};

// Four points side by side: lane j of each coordinate is v_j's.
inline Vec3<Double4> lanes(Vec3<double> v0, Vec3<double> v1, Vec3<double> v2, Vec3<double> v3) {
  return {Double4(v0.x, v1.x, v2.x, v3.x), Double4(v0.y, v1.y, v2.y, v3.y),
          Double4(v0.z, v1.z, v2.z, v3.z)};
}

}  // namespace pgamesh
