// The join (regressive product) A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2) between grade types, as
// `join(a, b)` and `a & b`. Joins of points are carriers: a line (edge), a plane (face), a scalar
// (tetrahedron, 6 × signed volume). Signs: docs/conventions.md §5 (klein and ganja.js differ on
// some, §4).
#pragma once

#include <type_traits>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"
#include "pgamesh/algebra/pga3/simd.hpp"

namespace pgamesh::pga3 {

/// a ∨ b: direction w_a P_b − w_b P_a, moment P_a × P_b (paper eq. 3.10 for unit weights).
template <class T>
constexpr Line<T> join(const Point<T>& a, const Point<T>& b) {
  const Vec3<T> pa = a.weighted(), pb = b.weighted();
  const Vec3<T> d = a.e123 * pb - b.e123 * pa;
  const Vec3<T> m = cross(pa, pb);
  return {m.x, m.y, m.z, d.z, d.y, d.x};
}

/// L ∨ v: normal d × P + w m, e0 coefficient −m·P (docs/conventions.md §5:
/// v0 ∨ v1 ∨ v2 = n − det e0).
template <class T>
constexpr Plane<T> join(const Line<T>& l, const Point<T>& v) {
  const Vec3<T> d = l.direction(), m = l.moment(), p = v.weighted();
  const Vec3<T> n = cross(d, p) + v.e123 * m;
  return {-dot(m, p), n.x, n.y, n.z};
}

/// v ∨ L = L ∨ v (grades 3 and 2: the sign (−1)^((4−3)(4−2)) is +1).
template <class T>
constexpr Plane<T> join(const Point<T>& v, const Line<T>& l) {
  return join(l, v);
}

/// p ∨ v = a x + b y + c z + d for a unit-weight point (paper eq. 4.10); v ∨ p is its negative.
template <class T>
constexpr T join(const Plane<T>& p, const Point<T>& v) {
  return p.e1 * v.e032 + p.e2 * v.e013 + p.e3 * v.e021 + p.e0 * v.e123;
}
/// v ∨ p = −(p ∨ v) (docs/conventions.md §5).
template <class T>
constexpr T join(const Point<T>& v, const Plane<T>& p) {
  return -join(p, v);
}

namespace detail {
#ifdef PGAMESH_PGA3_SIMD
/// join(join(a, b), c) on four-lane vectors, with the same products and sums (the same bits, up
/// to the sign of a zero). The points' lanes (e123, e032, e013, e021) hold (w, x, y, z), and the
/// plane's (e0, e1, e2, e3) take lanes 1, 2, 3 as they come. A cross product takes three shuffles
/// instead of four when its result stays rotated: with next(v) = v's lanes (0, 2, 3, 1),
/// u next(v) − next(u) v holds (u × v)_z, _x, _y in lanes 1, 2, 3, and is rotated back once at the
/// end. The moment is formed negated (the subtraction reversed, an exact negation), so that the
/// e0 coefficient −(m·P_c) is summed without a negation after it.
template <class T>
inline Plane<T> join_simd(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
  V4<T> va, vb, vc;  // (w, x, y, z) each
  load_lanes<T>(a, 0, va), load_lanes<T>(b, 0, vb), load_lanes<T>(c, 0, vc);
  const V4<T> d = PGAMESH_LANES(va, 0, 0, 0, 0) * vb - PGAMESH_LANES(vb, 0, 0, 0, 0) * va;
  // −m = −(P_a × P_b) and d × P_c, rotated: lanes 1, 2, 3 hold their z, x, y coordinates.
  const V4<T> vc_next = PGAMESH_LANES(vc, 0, 2, 3, 1);
  const V4<T> minus_m = PGAMESH_LANES(va, 0, 2, 3, 1) * vb - va * PGAMESH_LANES(vb, 0, 2, 3, 1);
  const V4<T> d_cross_c = d * vc_next - PGAMESH_LANES(d, 0, 2, 3, 1) * vc;
  // The normal d × P_c + w_c m, rotated.
  const V4<T> n = d_cross_c - PGAMESH_LANES(vc, 0, 0, 0, 0) * minus_m;
  // e0 = −((m_x p_x + m_y p_y) + m_z p_z): lanes 2, 3, 1 of −m P_c (rotated alike).
  const V4<T> mp = minus_m * PGAMESH_LANES(vc, 0, 3, 1, 2);
  const V4<T> e0 = (PGAMESH_LANES(mp, 2, 2, 2, 2) + PGAMESH_LANES(mp, 3, 3, 3, 3)) +
                   PGAMESH_LANES(mp, 1, 1, 1, 1);
  // Lane 0 from e0, lanes 1, 2, 3 rotated back to x, y, z.
  const V4<T> out_lanes = PGAMESH_LANES2(n, e0, 4, 1, 2, 3);
  Plane<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES(out_lanes, 0, 2, 3, 1));
  return out;
}
#endif
}  // namespace detail

/// v0 ∨ v1 ∨ v2: the carrier of a triangle, normal (v1 − v0) × (v2 − v0), e0 coefficient −det
/// (paper eq. 3.12, docs/conventions.md §5). float (and double under AVX) take the four-lane
/// form of simd.hpp inline, double on other x86-64 builds out of line, where the processor's
/// AVX2 runs it (pga3/isa.hpp): the same values, a zero possibly with the other sign.
template <class T>
constexpr Plane<T> join(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (detail::kHasSimd<T>)
    if (!std::is_constant_evaluated()) return detail::join_simd(a, b, c);
#endif
  if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
    if (!std::is_constant_evaluated())
      return detail::kRunsAvx2 ? detail::avx2::join(a, b, c) : join(join(a, b), c);
  return join(join(a, b), c);
}

/// L1 ∨ L2: a scalar, zero when the lines meet (coplanar); l1·m2 + l2·m1 in the Plücker
/// coordinates (the dual's ∧ with direction and moment swapped, eq. 2.2). For L1 = a ∨ b and
/// L2 = c ∨ d it equals a ∨ b ∨ c ∨ d.
template <class T>
constexpr T join(const Line<T>& a, const Line<T>& b) {
  return dot(a.direction(), b.moment()) + dot(b.direction(), a.moment());
}

/// v0 ∨ v1 ∨ v2 ∨ v3 = det[v1 − v0, v2 − v0, v3 − v0] (paper eq. 3.14, docs/conventions.md §5).
template <class T>
constexpr T join(const Point<T>& a, const Point<T>& b, const Point<T>& c, const Point<T>& d) {
  return join(join(a, b, c), d);
}

/// a & b = a ∨ b.
template <class T>
constexpr Line<T> operator&(const Point<T>& a, const Point<T>& b) {
  return join(a, b);
}
/// l & v = l ∨ v.
template <class T>
constexpr Plane<T> operator&(const Line<T>& l, const Point<T>& v) {
  return join(l, v);
}
/// v & l = v ∨ l.
template <class T>
constexpr Plane<T> operator&(const Point<T>& v, const Line<T>& l) {
  return join(v, l);
}
/// p & v = p ∨ v.
template <class T>
constexpr T operator&(const Plane<T>& p, const Point<T>& v) {
  return join(p, v);
}
/// v & p = v ∨ p.
template <class T>
constexpr T operator&(const Point<T>& v, const Plane<T>& p) {
  return join(v, p);
}
/// a & b = a ∨ b for two lines.
template <class T>
constexpr T operator&(const Line<T>& a, const Line<T>& b) {
  return join(a, b);
}

}  // namespace pgamesh::pga3
