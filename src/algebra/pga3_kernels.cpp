// The double kernels of pga3/isa.hpp, compiled for baseline x86-64 (SSE2) and again for AVX2, one
// chosen per call from a flag read once at start-up (docs/pga3.md "Speed"). Each variant is the
// header's always-inline loop or formula compiled under another target attribute: the same source
// and the same operations in the same order, so the same bits. "avx2" does not enable FMA, and the
// library is compiled with -ffp-contract=off, so no multiply-add is fused in either variant.
#include "pgamesh/algebra/pga3/batch.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"
#include "pgamesh/algebra/pga3/motor.hpp"

namespace pgamesh::pga3::detail {

namespace {

#ifdef PGAMESH_PGA3_AVX2_VARIANT
bool detect_avx2() noexcept {
  __builtin_cpu_init();  // needed before static initialisation has run libgcc's own
  return __builtin_cpu_supports("avx2");
}
// Zero (false, the baseline) until dynamic initialisation has run, so an early call is safe.
const bool kRunsAvx2 = detect_avx2();

[[gnu::target("avx2")]] void transform_points_avx2(const double (&r)[3][4], const double* x,
                                                   const double* y, const double* z, double* ox,
                                                   double* oy, double* oz, std::size_t n) {
  transform_points_loop(r, x, y, z, ox, oy, oz, n);
}
[[gnu::target("avx2")]] void transform_planes_avx2(const double (&r)[3][4], const double (&u)[4],
                                                   const double* a, const double* b,
                                                   const double* c, const double* d, double* oa,
                                                   double* ob, double* oc, double* od,
                                                   std::size_t n) {
  transform_planes_loop(r, u, a, b, c, d, oa, ob, oc, od, n);
}

[[gnu::target("avx2"), gnu::flatten]] Motor<double> geometric_product_avx2(const Motor<double>& a,
                                                                           const Motor<double>& b) {
  return geometric_product_simd(a, b);
}
[[gnu::target("avx2"), gnu::flatten]] Point<double> apply_avx2(const Motor<double>& m,
                                                               const Point<double>& x) {
  return apply_simd(m, x);
}
[[gnu::target("avx2"), gnu::flatten]] Plane<double> apply_avx2(const Motor<double>& m,
                                                               const Plane<double>& p) {
  return apply_simd(m, p);
}

bool use_avx2(Isa isa) noexcept {
  return isa == Isa::avx2 && kRunsAvx2;
}
#else
constexpr bool kRunsAvx2 = false;
#endif

}  // namespace

bool runs(Isa isa) noexcept {
  return isa == Isa::baseline || kRunsAvx2;
}

void transform_points(Isa isa, const double (&r)[3][4], const double* x, const double* y,
                      const double* z, double* ox, double* oy, double* oz, std::size_t n) noexcept {
#ifdef PGAMESH_PGA3_AVX2_VARIANT
  if (use_avx2(isa)) return transform_points_avx2(r, x, y, z, ox, oy, oz, n);
#endif
  (void)isa;
  transform_points_loop(r, x, y, z, ox, oy, oz, n);
}

void transform_planes(Isa isa, const double (&r)[3][4], const double (&u)[4], const double* a,
                      const double* b, const double* c, const double* d, double* oa, double* ob,
                      double* oc, double* od, std::size_t n) noexcept {
#ifdef PGAMESH_PGA3_AVX2_VARIANT
  if (use_avx2(isa)) return transform_planes_avx2(r, u, a, b, c, d, oa, ob, oc, od, n);
#endif
  (void)isa;
  transform_planes_loop(r, u, a, b, c, d, oa, ob, oc, od, n);
}

Motor<double> geometric_product(Isa isa, const Motor<double>& a, const Motor<double>& b) noexcept {
#ifdef PGAMESH_PGA3_AVX2_VARIANT
  if (use_avx2(isa)) return geometric_product_avx2(a, b);
#endif
  (void)isa;
  return geometric_product_generic(a, b);
}
Point<double> apply(Isa isa, const Motor<double>& m, const Point<double>& x) noexcept {
#ifdef PGAMESH_PGA3_AVX2_VARIANT
  if (use_avx2(isa)) return apply_avx2(m, x);
#endif
  (void)isa;
  return apply_generic(m, x);
}
Plane<double> apply(Isa isa, const Motor<double>& m, const Plane<double>& p) noexcept {
#ifdef PGAMESH_PGA3_AVX2_VARIANT
  if (use_avx2(isa)) return apply_avx2(m, p);
#endif
  (void)isa;
  return apply_generic(m, p);
}

}  // namespace pgamesh::pga3::detail
