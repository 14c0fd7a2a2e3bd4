// Internal: the double kernels compiled into the algebra library (src/algebra/pga3_kernels.cpp)
// once for baseline x86-64 (SSE2) and once more for AVX2 (four doubles per register), the variant
// chosen at run time; on other processors (aarch64) only the plain code is compiled. Plain
// declarations: the instruction-set attributes stay in the .cpp. Every variant gives the bits of
// the header formulas it is named after (docs/pga3.md "Speed"); tests/algebra/test_pga3_isa.cpp
// checks each variant against them.
#pragma once

#include <cstddef>

#include "pgamesh/algebra/pga3/grades.hpp"

// x86-64 with GCC or clang: an AVX2 variant is compiled beside the baseline one.
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define PGAMESH_PGA3_AVX2_VARIANT 1
#endif

namespace pgamesh::pga3::detail {

/// Whether motor.hpp and join.hpp call the double motor product, point and plane sandwiches and
/// join of three points out of line (below), so that they run AVX2 where the processor has it: on
/// x86-64 builds without AVX. Builds with AVX inline the four-lane forms themselves; elsewhere
/// (aarch64) the generic formulas stay inline.
inline constexpr bool kDoubleOutOfLine =
#if defined(PGAMESH_PGA3_AVX2_VARIANT) && !defined(__AVX__)
    true;
#else
    false;
#endif

/// The instruction sets the kernels below are compiled for. A kernel called with `avx2` runs the
/// AVX2 code when this processor has AVX2 and the baseline code otherwise.
enum class Isa { baseline, avx2 };

/// Whether the kernels run `isa` itself on this processor (baseline: always; avx2: an x86-64
/// processor with AVX2, and an OS that saves its registers).
bool runs(Isa isa) noexcept;

/// runs(Isa::avx2), read once at start-up (false before: an earlier call takes the baseline). The
/// operators of motor.hpp and join.hpp test it inline and call the AVX2 kernel below directly: one
/// test and one call, where a call to a dispatching function cost a second call and its frame.
extern const bool kRunsAvx2;

/// The AVX2 variants of the kernels below, to be called only where kRunsAvx2 holds.
namespace avx2 {
Motor<double> geometric_product(const Motor<double>& a, const Motor<double>& b) noexcept;
Point<double> apply(const Motor<double>& m, const Point<double>& x) noexcept;
Plane<double> apply(const Motor<double>& m, const Plane<double>& p) noexcept;
Plane<double> join(const Point<double>& a, const Point<double>& b, const Point<double>& c) noexcept;
}  // namespace avx2

/// transform_points_loop<double> (batch.hpp): (ox, oy, oz)[i] = r (x, y, z, 1)[i], i < n.
void transform_points(Isa isa, const double (&r)[3][4], const double* x, const double* y,
                      const double* z, double* ox, double* oy, double* oz, std::size_t n) noexcept;
/// transform_planes_loop<double> (batch.hpp).
void transform_planes(Isa isa, const double (&r)[3][4], const double (&u)[4], const double* a,
                      const double* b, const double* c, const double* d, double* oa, double* ob,
                      double* oc, double* od, std::size_t n) noexcept;

/// The motor product: quaternion_order::geometric_product (motor.hpp) in the baseline
/// variant, geometric_product_lanes in the AVX2 variant (equal to rounding).
Motor<double> geometric_product(Isa isa, const Motor<double>& a, const Motor<double>& b) noexcept;
/// The point sandwich: quaternion_order::apply, or apply_lanes (motor.hpp).
Point<double> apply(Isa isa, const Motor<double>& m, const Point<double>& x) noexcept;
/// The plane sandwich: quaternion_order::apply, or apply_lanes (motor.hpp).
Plane<double> apply(Isa isa, const Motor<double>& m, const Plane<double>& p) noexcept;
/// The join of three points: join(join(a, b), c) of join.hpp, or join_simd (the same values up to
/// the sign of a zero).
Plane<double> join(Isa isa, const Point<double>& a, const Point<double>& b,
                   const Point<double>& c) noexcept;

}  // namespace pgamesh::pga3::detail
