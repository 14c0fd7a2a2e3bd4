// One motor applied to many points or planes stored as separate coordinate arrays (structure of
// arrays). The sandwich M X M̃ of motor.hpp is linear in X, so it is formed once as a 3 × 4
// matrix [R | t] (R = |q|² × the rotation, t the translation part) and then costs 9
// multiplications and 9 additions per element, in a loop the compiler vectorises across
// elements (four at a time as simd.hpp vectors for float and double: with six separate arrays
// GCC gives up vectorising the plain loop over its alias checks). The results equal apply(m, x)
// (motor.hpp) in exact arithmetic; in floating point they may differ from it in the last bits (the
// sums are grouped differently).
#pragma once

#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"
#include "pgamesh/algebra/pga3/quaternion.hpp"
#include "pgamesh/algebra/pga3/simd.hpp"

namespace pgamesh::pga3 {

namespace detail {
/// The sandwich of M = q + ε c on points as a 3 × 4 matrix: rows r[i] = (R_i0, R_i1, R_i2, t_i),
/// with R x = q x q* = (w² − v·v) x + 2 (v·x) v + 2 w (v × x) (quaternion.hpp rotate) and
/// t = 2 (c_w q_v − q_w c_v + c_v × q_v) (motor.hpp apply to a point): the action X ↦ M X M̃ of
/// docs/conventions.md §7 with M = T R, q the rotor's quaternion as §7 maps it.
template <class T>
struct SandwichMatrix {
  T r[3][4];
  T weight;  // |q|², the weight of M X M̃ for a point of weight 1
};

template <class T>
constexpr SandwichMatrix<T> sandwich_matrix(const Motor<T>& m) {
  const T w = m.s, x = -m.e23, y = -m.e31, z = -m.e12;  // q = (w, (x, y, z))
  const T cw = m.e0123, cx = m.e01, cy = m.e02, cz = m.e03;
  const T s = w * w - (x * x + y * y + z * z);
  const T x2 = T(2) * x, y2 = T(2) * y, z2 = T(2) * z;
  const T tx = T(2) * (cw * x - w * cx + (cy * z - cz * y));
  const T ty = T(2) * (cw * y - w * cy + (cz * x - cx * z));
  const T tz = T(2) * (cw * z - w * cz + (cx * y - cy * x));
  return {{{s + x2 * x, x2 * y - w * z2, x2 * z + w * y2, tx},
           {y2 * x + w * z2, s + y2 * y, y2 * z - w * x2, ty},
           {z2 * x - w * y2, z2 * y + w * x2, s + z2 * z, tz}},
          w * w + (x * x + y * y + z * z)};
}

/// (ox, oy, oz)[i] = r (x, y, z, 1)[i] for i < n: the loop of apply_to_points, four elements at a
/// time as simd.hpp vectors, then one at a time. Every element gets the same operations in the same
/// order whatever the vector width, so the bits do not depend on the instruction set it is compiled
/// for (src/algebra/pga3_kernels.cpp compiles it for SSE2 and AVX2). The out arrays are the in
/// arrays or do not overlap them.
template <class T>
[[gnu::always_inline]] inline void transform_points_loop(const T (&r)[3][4], const T* x, const T* y,
                                                         const T* z, T* ox, T* oy, T* oz,
                                                         std::size_t n) {
  const T r00 = r[0][0], r01 = r[0][1], r02 = r[0][2], r03 = r[0][3];  // in registers: the
  const T r10 = r[1][0], r11 = r[1][1], r12 = r[1][2], r13 = r[1][3];  // stores below may alias
  const T r20 = r[2][0], r21 = r[2][1], r22 = r[2][2], r23 = r[2][3];  // r as far as C++ knows
  std::size_t i = 0;
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (kHasSimdArithmetic<T>) {
    using V = V4<T>;
    for (; i + 4 <= n; i += 4) {
      V px, py, pz;
      std::memcpy(&px, x + i, sizeof px), std::memcpy(&py, y + i, sizeof py);
      std::memcpy(&pz, z + i, sizeof pz);
      const V qx = r00 * px + r01 * py + r02 * pz + r03;
      const V qy = r10 * px + r11 * py + r12 * pz + r13;
      const V qz = r20 * px + r21 * py + r22 * pz + r23;
      std::memcpy(ox + i, &qx, sizeof qx), std::memcpy(oy + i, &qy, sizeof qy);
      std::memcpy(oz + i, &qz, sizeof qz);
    }
  }
#endif
  for (; i < n; ++i) {
    const T px = x[i], py = y[i], pz = z[i];
    ox[i] = r00 * px + r01 * py + r02 * pz + r03;
    oy[i] = r10 * px + r11 * py + r12 * pz + r13;
    oz[i] = r20 * px + r21 * py + r22 * pz + r23;
  }
}

/// The loop of apply_to_planes: normal R n, offset u_w d + (u_x a + u_y b + u_z c), with the
/// rotation part R of r and u = (u_x, u_y, u_z, |q|²). Same rules as transform_points_loop.
template <class T>
[[gnu::always_inline]] inline void transform_planes_loop(const T (&r)[3][4], const T (&u)[4],
                                                         const T* a, const T* b, const T* c,
                                                         const T* d, T* oa, T* ob, T* oc, T* od,
                                                         std::size_t n) {
  const T ux = u[0], uy = u[1], uz = u[2], weight = u[3];  // in registers (as above)
  const T r00 = r[0][0], r01 = r[0][1], r02 = r[0][2];
  const T r10 = r[1][0], r11 = r[1][1], r12 = r[1][2];
  const T r20 = r[2][0], r21 = r[2][1], r22 = r[2][2];
  std::size_t i = 0;
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (kHasSimdArithmetic<T>) {
    using V = V4<T>;
    for (; i + 4 <= n; i += 4) {
      V na, nb, nc, nd;
      std::memcpy(&na, a + i, sizeof na), std::memcpy(&nb, b + i, sizeof nb);
      std::memcpy(&nc, c + i, sizeof nc), std::memcpy(&nd, d + i, sizeof nd);
      const V qa = r00 * na + r01 * nb + r02 * nc;
      const V qb = r10 * na + r11 * nb + r12 * nc;
      const V qc = r20 * na + r21 * nb + r22 * nc;
      const V qd = weight * nd + (ux * na + uy * nb + uz * nc);
      std::memcpy(oa + i, &qa, sizeof qa), std::memcpy(ob + i, &qb, sizeof qb);
      std::memcpy(oc + i, &qc, sizeof qc), std::memcpy(od + i, &qd, sizeof qd);
    }
  }
#endif
  for (; i < n; ++i) {
    const T na = a[i], nb = b[i], nc = c[i], nd = d[i];
    oa[i] = r00 * na + r01 * nb + r02 * nc;
    ob[i] = r10 * na + r11 * nb + r12 * nc;
    oc[i] = r20 * na + r21 * nb + r22 * nc;
    od[i] = weight * nd + (ux * na + uy * nb + uz * nc);
  }
}

inline void check_lengths(std::size_t n, std::initializer_list<std::size_t> sizes) {
  for (std::size_t k : sizes)
    if (k != n) throw std::length_error("pga3::apply_to_*: coordinate arrays of different lengths");
}
/// Spans whose element type follows the motor's scalar (not deduced: std::vector converts).
template <class T>
using In = std::type_identity_t<std::span<const T>>;
template <class T>
using Out = std::type_identity_t<std::span<T>>;
}  // namespace detail

/// Moves the points (x[i], y[i], z[i]) (weight 1) by the motor m: (ox[i], oy[i], oz[i]) is the
/// weighted position of apply(m, point(x[i], y[i], z[i])) — the moved point when m is normalized.
/// All arrays have the same length (else std::length_error); the out arrays are either the in
/// arrays (in place) or do not overlap them.
template <class T>
void apply_to_points(const Motor<T>& m, detail::In<T> x, detail::In<T> y, detail::In<T> z,
                     detail::Out<T> ox, detail::Out<T> oy, detail::Out<T> oz) {
  const std::size_t n = x.size();
  detail::check_lengths(n, {y.size(), z.size(), ox.size(), oy.size(), oz.size()});
  const detail::SandwichMatrix<T> mat = detail::sandwich_matrix(m);
  const auto& r = mat.r;
  if constexpr (std::is_same_v<T, double>)  // compiled in the library for each x86-64 level
    detail::transform_points(detail::Isa::avx2, r, x.data(), y.data(), z.data(), ox.data(),
                             oy.data(), oz.data(), n);
  else
    detail::transform_points_loop(r, x.data(), y.data(), z.data(), ox.data(), oy.data(), oz.data(),
                                  n);
}

/// Moves the planes a[i] x + b[i] y + c[i] z + d[i] = 0 by the motor m: the coefficients of
/// apply(m, plane(a[i], b[i], c[i], d[i])). Normal R n; offset |q|² d + n·u with
/// u = 2 (q_w c_v − c_w q_v + c_v × q_v) (motor.hpp apply to a plane, with (q_v × n)·c_v =
/// n·(c_v × q_v)). Same length rules as apply_to_points.
template <class T>
void apply_to_planes(const Motor<T>& m, detail::In<T> a, detail::In<T> b, detail::In<T> c,
                     detail::In<T> d, detail::Out<T> oa, detail::Out<T> ob, detail::Out<T> oc,
                     detail::Out<T> od) {
  const std::size_t n = a.size();
  detail::check_lengths(n,
                        {b.size(), c.size(), d.size(), oa.size(), ob.size(), oc.size(), od.size()});
  const auto [r, weight] = detail::sandwich_matrix(m);
  const T w = m.s, x = -m.e23, y = -m.e31, z = -m.e12;
  const T cw = m.e0123, cx = m.e01, cy = m.e02, cz = m.e03;
  const T ux = T(2) * (w * cx - cw * x + (cy * z - cz * y));
  const T uy = T(2) * (w * cy - cw * y + (cz * x - cx * z));
  const T uz = T(2) * (w * cz - cw * z + (cx * y - cy * x));
  const T u[4] = {ux, uy, uz, weight};
  if constexpr (std::is_same_v<T, double>)
    detail::transform_planes(detail::Isa::avx2, r, u, a.data(), b.data(), c.data(), d.data(),
                             oa.data(), ob.data(), oc.data(), od.data(), n);
  else
    detail::transform_planes_loop(r, u, a.data(), b.data(), c.data(), d.data(), oa.data(),
                                  ob.data(), oc.data(), od.data(), n);
}

}  // namespace pgamesh::pga3
