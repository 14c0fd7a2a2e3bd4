// The double kernels of pga3/isa.hpp, compiled for baseline x86-64 (SSE2) and again for AVX2, one
// chosen per call from a flag read once at start-up (docs/pga3.md "Speed"). The batch loops and
// the join are the header's code compiled under another target attribute: the same operations in
// the same order, so the same bits. The motor product and the sandwiches run the quaternion-order
// formulas in the baseline variant and the lane forms in the AVX2 variant (with four doubles split
// over two SSE2 registers, the lane shuffles would cost three times the generic formula). "avx2"
// does not enable FMA, and the library is compiled with -ffp-contract=off, so no multiply-add is
// fused in either variant.
#include "pgamesh/algebra/pga3/batch.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"
#include "pgamesh/algebra/pga3/join.hpp"
#include "pgamesh/algebra/pga3/motor.hpp"

#ifdef PGAMESH_PGA3_AVX2_VARIANT
#include <cpuid.h>
#endif

namespace pgamesh::pga3::detail {

namespace {

// The attribute of the AVX2 variants: code for AVX2 on x86-64. Elsewhere the variants compile to
// the plain code and are never called (kRunsAvx2 is false), so each dispatch below is one test.
#ifdef PGAMESH_PGA3_AVX2_VARIANT
#define PGAMESH_TARGET_AVX2 gnu::target("avx2")
// Whether the processor has AVX2 and the OS saves the YMM registers: CPUID leaf 1 (OSXSAVE, AVX),
// XCR0 bits 1 and 2 (SSE and AVX state), CPUID leaf 7 (AVX2). Three reads, not libgcc's
// __builtin_cpu_init, which reads every leaf it knows: in a virtual machine each CPUID traps to
// the hypervisor, and that cost 0.2 ms of every start of the command-line tool.
bool detect_avx2() noexcept {
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & bit_OSXSAVE) || !(c & bit_AVX)) return false;
  unsigned xcr0 = 0, xcr0_high = 0;
  __asm__("xgetbv" : "=a"(xcr0), "=d"(xcr0_high) : "c"(0));
  if ((xcr0 & 6u) != 6u) return false;
  return __get_cpuid_count(7, 0, &a, &b, &c, &d) && (b & bit_AVX2);
}
#else
#define PGAMESH_TARGET_AVX2
bool detect_avx2() noexcept {
  return false;
}
#endif

[[PGAMESH_TARGET_AVX2]] void transform_points_avx2(const double (&r)[3][4], const double* x,
                                                   const double* y, const double* z, double* ox,
                                                   double* oy, double* oz, std::size_t n) {
  transform_points_loop(r, x, y, z, ox, oy, oz, n);
}
[[PGAMESH_TARGET_AVX2]] void transform_planes_avx2(const double (&r)[3][4], const double (&u)[4],
                                                   const double* a, const double* b,
                                                   const double* c, const double* d, double* oa,
                                                   double* ob, double* oc, double* od,
                                                   std::size_t n) {
  transform_planes_loop(r, u, a, b, c, d, oa, ob, oc, od, n);
}
}  // namespace

// Zero (false, the baseline) until dynamic initialisation has run, so an early call is safe.
const bool kRunsAvx2 = detect_avx2();

namespace avx2 {
[[PGAMESH_TARGET_AVX2, gnu::flatten]] Motor<double> geometric_product(
    const Motor<double>& a, const Motor<double>& b) noexcept {
  return geometric_product_lanes(a, b);
}
[[PGAMESH_TARGET_AVX2, gnu::flatten]] Point<double> apply(const Motor<double>& m,
                                                          const Point<double>& x) noexcept {
  return apply_lanes(m, x);
}
[[PGAMESH_TARGET_AVX2, gnu::flatten]] Plane<double> apply(const Motor<double>& m,
                                                          const Plane<double>& p) noexcept {
  return apply_lanes(m, p);
}
[[PGAMESH_TARGET_AVX2, gnu::flatten]] Plane<double> join(const Point<double>& a,
                                                         const Point<double>& b,
                                                         const Point<double>& c) noexcept {
  return join_simd(a, b, c);
}
}  // namespace avx2
#undef PGAMESH_TARGET_AVX2

namespace {

bool use_avx2(Isa isa) noexcept {
  return isa == Isa::avx2 && kRunsAvx2;
}

}  // namespace

bool runs(Isa isa) noexcept {
  return isa == Isa::baseline || kRunsAvx2;
}

void transform_points(Isa isa, const double (&r)[3][4], const double* x, const double* y,
                      const double* z, double* ox, double* oy, double* oz, std::size_t n) noexcept {
  if (use_avx2(isa)) return transform_points_avx2(r, x, y, z, ox, oy, oz, n);
  transform_points_loop(r, x, y, z, ox, oy, oz, n);
}
void transform_planes(Isa isa, const double (&r)[3][4], const double (&u)[4], const double* a,
                      const double* b, const double* c, const double* d, double* oa, double* ob,
                      double* oc, double* od, std::size_t n) noexcept {
  if (use_avx2(isa)) return transform_planes_avx2(r, u, a, b, c, d, oa, ob, oc, od, n);
  transform_planes_loop(r, u, a, b, c, d, oa, ob, oc, od, n);
}
Motor<double> geometric_product(Isa isa, const Motor<double>& a, const Motor<double>& b) noexcept {
  return use_avx2(isa) ? avx2::geometric_product(a, b) : quaternion_order::geometric_product(a, b);
}
Point<double> apply(Isa isa, const Motor<double>& m, const Point<double>& x) noexcept {
  return use_avx2(isa) ? avx2::apply(m, x) : quaternion_order::apply(m, x);
}
Plane<double> apply(Isa isa, const Motor<double>& m, const Plane<double>& p) noexcept {
  return use_avx2(isa) ? avx2::apply(m, p) : quaternion_order::apply(m, p);
}

Plane<double> join(Isa isa, const Point<double>& a, const Point<double>& b,
                   const Point<double>& c) noexcept {
  return use_avx2(isa) ? avx2::join(a, b, c) : pga3::join(pga3::join(a, b), c);
}

}  // namespace pgamesh::pga3::detail
