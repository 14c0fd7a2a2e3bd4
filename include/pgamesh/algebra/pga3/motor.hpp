// Motors (even elements: rotations, translations, screws) — composition, reverse, normalisation,
// inverse, the rotor and translator constructors of docs/conventions.md §7 and the sandwich
// X ↦ M X M̃ on every grade. The kernels use the dual-quaternion form M = q + ε c of quaternion.hpp.
#pragma once

#include <cmath>
#include <type_traits>

#include "pgamesh/algebra/pga3/grades.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"
#include "pgamesh/algebra/pga3/quaternion.hpp"
#include "pgamesh/algebra/pga3/simd.hpp"

namespace pgamesh::pga3 {

namespace detail {
/// q of M = q + ε c: (s, −(e23, e31, e12)).
template <class T>
constexpr Quat<T> real_part(const Motor<T>& m) {
  return {m.s, {-m.e23, -m.e31, -m.e12}};
}
/// c of M = q + ε c: (e0123, (e01, e02, e03)).
template <class T>
constexpr Quat<T> dual_part(const Motor<T>& m) {
  return {m.e0123, {m.e01, m.e02, m.e03}};
}
/// The motor q + ε c.
template <class T>
constexpr Motor<T> motor_from(const Quat<T>& q, const Quat<T>& c) {
  return {q.w, c.v.x, c.v.y, c.v.z, -q.v.z, -q.v.y, -q.v.x, c.w};
}
}  // namespace detail

namespace detail {
/// The geometric product A B of two motors, (q_a + ε c_a)(q_b + ε c_b) =
/// q_a q_b + ε (q_a c_b + c_a q_b), for any scalar type.
template <class T>
constexpr Motor<T> geometric_product_generic(const Motor<T>& a, const Motor<T>& b) {
  const auto qa = real_part(a), qb = real_part(b), ca = dual_part(a), cb = dual_part(b);
  return motor_from(qa * qb, qa * cb + ca * qb);
}

#ifdef PGAMESH_PGA3_SIMD
/// A motor's eight coefficients in two four-lane vectors, in its storage order: lo = (s, e01, e02,
/// e03) and hi = (e12, e31, e23, e0123).
template <class T>
[[gnu::always_inline]] inline void load_motor_lanes(const Motor<T>& m, V4<T>& lo, V4<T>& hi) {
  load_lanes<T>(m, 0, lo), load_lanes<T>(m, 4, hi);
}

/// geometric_product_generic on four-lane vectors, bit for bit (zeros' signs included): each lane
/// does the generic formula's operations in its order, on the same negated inputs. With
/// Q = q_v = −(e23, e31, e12) and m = c_v = (e01, e02, e03), lane i of the vector parts is
///   q_a q_b → (a_w Q_b + b_w Q_a) + (Q_a,j Q_b,k − Q_a,k Q_b,j)   (i, j, k cyclic),
///   q_a c_b → (a_w m_b + b_p Q_a) + (Q_a,j m_b,k − Q_a,k m_b,j),
///   c_a q_b → (a_p Q_b + b_w m_a) + (m_a,j Q_b,k − m_a,k Q_b,j),
/// and the three scalar parts share one vector (a_w b_w, a_w b_p, a_p b_w) − the three dot
/// products ((x + y) + z each).
template <class T>
inline Motor<T> geometric_product_simd(const Motor<T>& a, const Motor<T>& b) {
  V4<T> alo, ahi, blo, bhi;  // (s, e01, e02, e03) and (e12, e31, e23, e0123)
  load_motor_lanes<T>(a, alo, ahi), load_motor_lanes<T>(b, blo, bhi);
  const V4<T> aQ = -PGAMESH_LANES(ahi, 2, 1, 0, 3), bQ = -PGAMESH_LANES(bhi, 2, 1, 0, 3);
  const V4<T> am = PGAMESH_LANES(alo, 1, 2, 3, 0), bm = PGAMESH_LANES(blo, 1, 2, 3, 0);
  const V4<T> aw = PGAMESH_LANES(alo, 0, 0, 0, 0), bw = PGAMESH_LANES(blo, 0, 0, 0, 0);
  const V4<T> ap = PGAMESH_LANES(ahi, 3, 3, 3, 3), bp = PGAMESH_LANES(bhi, 3, 3, 3, 3);
  // (x, y, z) → (y, z, x) and (z, x, y): the j and k of lane i.
  const V4<T> aQj = PGAMESH_LANES(aQ, 1, 2, 0, 3), aQk = PGAMESH_LANES(aQ, 2, 0, 1, 3);
  const V4<T> bQj = PGAMESH_LANES(bQ, 1, 2, 0, 3), bQk = PGAMESH_LANES(bQ, 2, 0, 1, 3);
  const V4<T> bmj = PGAMESH_LANES(bm, 1, 2, 0, 3), bmk = PGAMESH_LANES(bm, 2, 0, 1, 3);
  const V4<T> amj = PGAMESH_LANES(am, 1, 2, 0, 3), amk = PGAMESH_LANES(am, 2, 0, 1, 3);
  const V4<T> qv = (aw * bQ + bw * aQ) + (aQj * bQk - aQk * bQj);
  const V4<T> x = (aw * bm + bp * aQ) + (aQj * bmk - aQk * bmj);
  const V4<T> y = (ap * bQ + bw * am) + (amj * bQk - amk * bQj);
  const V4<T> m = x + y;  // (e01, e02, e03)
  const V4<T> e = -qv;    // (e23, e31, e12)
  // Scalar parts: lanes (q_a q_b, q_a c_b, c_a q_b) of (a_w, a_w, a_p)(b_w, b_p, b_w) − dots.
  const V4<T> p1 = aQ * bQ, p2 = aQ * bm, p3 = am * bQ;
  const V4<T> u = PGAMESH_LANES2(p1, p2, 0, 4, 1, 5), z = PGAMESH_LANES2(p1, p2, 2, 6, 2, 6);
  const V4<T> tx = PGAMESH_LANES2(u, p3, 0, 1, 4, 4), ty = PGAMESH_LANES2(u, p3, 2, 3, 5, 5);
  const V4<T> tz = PGAMESH_LANES2(z, p3, 0, 1, 6, 6);
  const V4<T> w = PGAMESH_LANES2(alo, ahi, 0, 0, 7, 7) * PGAMESH_LANES2(blo, bhi, 0, 7, 0, 0) -
                  ((tx + ty) + tz);
  const V4<T> pseudo = PGAMESH_LANES(w, 1, 1, 1, 1) + PGAMESH_LANES(w, 2, 2, 2, 2);
  Motor<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(w, m, 0, 4, 5, 6));
  store_lanes<T>(out, 4, PGAMESH_LANES2(e, pseudo, 2, 1, 0, 4));
  return out;
}

/// Flips the sign bit of each lane of v where `signs` holds −0 (+0: unchanged): an exact
/// negation by one bitwise operation. (By reference: a function returning four doubles by value
/// would have an ABI that depends on AVX.)
template <class T>
[[gnu::always_inline]] inline void flip_signs(V4<T>& v, const V4<T>& signs) {
  using Bits [[gnu::vector_size(sizeof(V4<T>))]] =
      std::conditional_t<sizeof(T) == 4, unsigned int, unsigned long long>;
  v = reinterpret_cast<V4<T>>(reinterpret_cast<Bits>(v) ^ reinterpret_cast<Bits>(signs));
}

/// The motor product with lane-uniform sums, as klein sums it. With A = (s, e23, e31, e12) and
/// C = (e0123, e01, e02, e03) in four lanes each, q = (A_0, −A_1, −A_2, −A_3) and c = C, each of
/// the Hamilton products q_a q_b, q_a c_b and c_a q_b is x_0 y + x_1 y1 + x_2 y2 + x_3 y3, summed
/// left to right, where y1, y2, y3 are y's lanes in the orders (1, 0, 3, 2), (2, 3, 0, 1),
/// (3, 2, 1, 0) with signs. Every sign (the Hamilton product's, q's, and the output's
/// (e23, e31, e12) = −vec(q_a q_b)) is folded into one pattern per term and applied by
/// flip_signs, as klein folds them into its shuffles. Other rounding than
/// geometric_product_generic (a few ulps); float only — double keeps the generic summation order,
/// whose bits the mesh results depend on (docs/pga3.md "Speed").
template <class T>
inline Motor<T> geometric_product_lanes(const Motor<T>& a, const Motor<T>& b) {
  V4<T> alo, ahi, blo, bhi;  // (s, e01, e02, e03), (e12, e31, e23, e0123)
  load_motor_lanes<T>(a, alo, ahi), load_motor_lanes<T>(b, blo, bhi);
  constexpr T P = T(0), N = -T(0);  // keep, flip
  // b's A = (s, e23, e31, e12) and C = (e0123, e01, e02, e03) (two-register shuffles, once), then
  // in the orders of the four terms, (0, 1, 2, 3), (1, 0, 3, 2), (2, 3, 0, 1), (3, 2, 1, 0).
  const V4<T> bA0 = PGAMESH_LANES2(blo, bhi, 0, 6, 5, 4),
              bC0 = PGAMESH_LANES2(blo, bhi, 7, 1, 2, 3);
  const V4<T> bA1 = PGAMESH_LANES(bA0, 1, 0, 3, 2), bC1 = PGAMESH_LANES(bC0, 1, 0, 3, 2);
  const V4<T> bA2 = PGAMESH_LANES(bA0, 2, 3, 0, 1), bC2 = PGAMESH_LANES(bC0, 2, 3, 0, 1);
  const V4<T> bA3 = PGAMESH_LANES(bA0, 3, 2, 1, 0), bC3 = PGAMESH_LANES(bC0, 3, 2, 1, 0);
  // a's coefficients, each in every lane: A_0 … A_3 and C_0 … C_3.
  const V4<T> aA0 = PGAMESH_LANES(alo, 0, 0, 0, 0), aA1 = PGAMESH_LANES(ahi, 2, 2, 2, 2);
  const V4<T> aA2 = PGAMESH_LANES(ahi, 1, 1, 1, 1), aA3 = PGAMESH_LANES(ahi, 0, 0, 0, 0);
  const V4<T> aC0 = PGAMESH_LANES(ahi, 3, 3, 3, 3), aC1 = PGAMESH_LANES(alo, 1, 1, 1, 1);
  const V4<T> aC2 = PGAMESH_LANES(alo, 2, 2, 2, 2), aC3 = PGAMESH_LANES(alo, 3, 3, 3, 3);
  // The signed b lanes of each term: q_a q_b (output signs folded in), q_a c_b, c_a q_b.
  V4<T> q1 = bA1, q2 = bA2, q3 = bA3, x1 = bC1, x2 = bC2, x3 = bC3;
  V4<T> y0 = bA0, y1 = bA1, y2 = bA2, y3 = bA3;
  flip_signs<T>(q1, V4<T>{N, P, P, N}), flip_signs<T>(q2, V4<T>{N, N, P, P}),
      flip_signs<T>(q3, V4<T>{N, P, N, P});
  flip_signs<T>(x1, V4<T>{P, N, P, N}), flip_signs<T>(x2, V4<T>{P, N, N, P}),
      flip_signs<T>(x3, V4<T>{P, P, N, N});
  flip_signs<T>(y0, V4<T>{P, N, N, N}), flip_signs<T>(y1, V4<T>{P, P, P, N});
  flip_signs<T>(y2, V4<T>{P, N, P, P}), flip_signs<T>(y3, V4<T>{P, P, N, P});
  const V4<T> q = ((aA0 * bA0 + aA1 * q1) + aA2 * q2) + aA3 * q3;  // (s, e23, e31, e12)
  const V4<T> x = ((aA0 * bC0 + aA1 * x1) + aA2 * x2) + aA3 * x3;  // q_a c_b
  const V4<T> y = ((aC0 * y0 + aC1 * y1) + aC2 * y2) + aC3 * y3;   // c_a q_b
  const V4<T> c = x + y;                                           // (e0123, e01, e02, e03)
  Motor<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(q, c, 0, 5, 6, 7));
  store_lanes<T>(out, 4, PGAMESH_LANES2(q, c, 3, 2, 1, 4));
  return out;
}
#endif
}  // namespace detail

/// The geometric product A B of two motors, (q_a + ε c_a)(q_b + ε c_b) =
/// q_a q_b + ε (q_a c_b + c_a q_b). As a motion, B acts first: (A B) X (A B)~ = A (B X B̃) Ã.
/// float runs geometric_product_lanes, double the four-lane form under AVX (same values as the
/// generic formula) and the generic formula otherwise (docs/pga3.md "Speed").
template <class T>
constexpr Motor<T> geometric_product(const Motor<T>& a, const Motor<T>& b) {
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (std::is_same_v<T, float>) {
    if (!std::is_constant_evaluated()) return detail::geometric_product_lanes(a, b);
  } else if constexpr (detail::kHasSimd<T>) {
    if (!std::is_constant_evaluated()) return detail::geometric_product_simd(a, b);
  }
#endif
  if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
    if (!std::is_constant_evaluated()) return detail::geometric_product(detail::Isa::avx2, a, b);
  return detail::geometric_product_generic(a, b);
}
/// A * B = geometric_product(A, B): the motion B followed by A.
template <class T>
constexpr Motor<T> operator*(const Motor<T>& a, const Motor<T>& b) {
  return geometric_product(a, b);
}
/// A *= B: A ← A B.
template <class T>
constexpr Motor<T>& operator*=(Motor<T>& a, const Motor<T>& b) {
  return a = a * b;
}

/// The reverse M̃: the bivector part changes sign (grade k picks up (−1)^(k(k−1)/2)).
template <class T>
constexpr Motor<T> reverse(const Motor<T>& m) {
  return {m.s, -m.e01, -m.e02, -m.e03, -m.e12, -m.e31, -m.e23, m.e0123};
}
/// ~M = reverse(M).
template <class T>
constexpr Motor<T> operator~(const Motor<T>& m) {
  return reverse(m);
}

/// M / sqrt(M M̃), with M M̃ = |q|² + 2 ε (q·c) a dual number: the result has M M̃ = 1 exactly
/// (unit q and q·c = 0, the Study condition), so its sandwich is a rigid motion. The zero motor
/// is returned unchanged.
template <class T>
Motor<T> normalized(const Motor<T>& m) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const T r2 = dot4(q, q);
  if (r2 == T(0)) return m;
  const T inv_r = T(1) / std::sqrt(r2);
  // (a + ε b)^(−1/2) = a^(−1/2) − ε b / (2 a^(3/2)), a = |q|², b = 2 q·c.
  const T dual = -dot4(q, c) * inv_r * inv_r * inv_r;
  return detail::motor_from(inv_r * q, inv_r * c + dual * q);
}

/// M⁻¹ = M̃ (M M̃)⁻¹, (a + ε b)⁻¹ = 1/a − ε b/a² (a = |q|², b = 2 q·c). Defined when q ≠ 0;
/// equals M̃ for a normalized motor.
template <class T>
constexpr Motor<T> inverse(const Motor<T>& m) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(m), c = dual_part(m);
  const T a = dot4(q, q);
  const T alpha = T(1) / a, beta = T(-2) * dot4(q, c) / (a * a);
  return detail::motor_from(alpha * conj(q), alpha * conj(c) + beta * conj(q));
}

/// The rotor turning by +angle (radians, right-handed) about the axis through the origin with
/// direction `axis`: R = cos(θ/2) − sin(θ/2) (a_x e23 + a_y e31 + a_z e12), a = axis/|axis|
/// (docs/conventions.md §7) = exp(−θ/2 (a_x e23 + a_y e31 + a_z e12)). A zero axis gives the
/// identity.
template <class T>
Motor<T> rotor(T angle, Vec3<T> axis) {
  const T len = length(axis);
  if (len == T(0)) return identity_motor<T>();
  const T c = std::cos(angle / 2), s = std::sin(angle / 2) / len;
  return {c, T(0), T(0), T(0), -s * axis.z, -s * axis.y, -s * axis.x, T(0)};
}

/// The translator by t: T = 1 − ½ (t_x e01 + t_y e02 + t_z e03) (docs/conventions.md §7)
/// = exp(−½ t·e0i).
template <class T>
constexpr Motor<T> translator(Vec3<T> t) {
  return {T(1), -t.x / 2, -t.y / 2, -t.z / 2, T(0), T(0), T(0), T(0)};
}

namespace detail {
/// M X M̃ for a point, any scalar type (apply below).
template <class T>
constexpr Point<T> apply_generic(const Motor<T>& m, const Point<T>& x) {
  const auto q = real_part(m), c = dual_part(m);
  const T w = x.e123;
  const Vec3<T> t = T(2) * (c.w * q.v - q.w * c.v + cross(c.v, q.v));
  const Vec3<T> p = rotate(q, x.weighted()) + w * t;
  return {p.z, p.y, p.x, dot4(q, q) * w};
}
/// M p M̃ for a plane, any scalar type (apply below).
template <class T>
constexpr Plane<T> apply_generic(const Motor<T>& m, const Plane<T>& p) {
  const auto q = real_part(m), c = dual_part(m);
  const Vec3<T> n = p.normal();
  const Vec3<T> rn = rotate(q, n);
  const T d =
      dot4(q, q) * p.e0 + T(2) * (-c.w * dot(q.v, n) + q.w * dot(n, c.v) + dot(cross(q.v, n), c.v));
  return {d, rn.x, rn.y, rn.z};
}

#ifdef PGAMESH_PGA3_SIMD
/// apply_generic for points on four-lane vectors (x, y, z, ·), bit for bit (zeros' signs
/// included): each lane does the generic formula's operations in its order. With Q = q_v =
/// −(e23, e31, e12) and m = c_v: t = 2 ((c_w Q − q_w m) + m × Q) and
/// q P q* = ((s P + 2 (Q·P) Q) + 2 q_w (Q × P)), s = q_w² − Q·Q.
template <class T>
inline Point<T> apply_simd(const Motor<T>& mo, const Point<T>& x) {
  V4<T> lo, hi, pt;  // (s, e01, e02, e03), (e12, e31, e23, e0123), (e021, e013, e032, e123)
  load_motor_lanes<T>(mo, lo, hi), load_lanes<T>(x, 0, pt);
  const V4<T> q = -PGAMESH_LANES(hi, 2, 1, 0, 3), m = PGAMESH_LANES(lo, 1, 2, 3, 0);
  const V4<T> p = PGAMESH_LANES(pt, 2, 1, 0, 3), w = PGAMESH_LANES(pt, 3, 3, 3, 3);
  const V4<T> qw = PGAMESH_LANES(lo, 0, 0, 0, 0), cw = PGAMESH_LANES(hi, 3, 3, 3, 3);
  const V4<T> qj = PGAMESH_LANES(q, 1, 2, 0, 3), qk = PGAMESH_LANES(q, 2, 0, 1, 3);
  const V4<T> mj = PGAMESH_LANES(m, 1, 2, 0, 3), mk = PGAMESH_LANES(m, 2, 0, 1, 3);
  const V4<T> pj = PGAMESH_LANES(p, 1, 2, 0, 3), pk = PGAMESH_LANES(p, 2, 0, 1, 3);
  // Lanes (Q·Q, Q·P, Q·Q, Q·P), each summed (x + y) + z.
  const V4<T> qq = q * q, qp = q * p;
  const V4<T> dots = (PGAMESH_LANES2(qq, qp, 0, 4, 0, 4) + PGAMESH_LANES2(qq, qp, 1, 5, 1, 5)) +
                     PGAMESH_LANES2(qq, qp, 2, 6, 2, 6);
  const V4<T> qw2 = qw * qw;
  const V4<T> s = qw2 - PGAMESH_LANES(dots, 0, 0, 0, 0);
  const V4<T> two = {T(2), T(2), T(2), T(2)};
  const V4<T> t = two * ((cw * q - qw * m) + (mj * qk - mk * qj));
  const V4<T> r =
      ((s * p + (two * PGAMESH_LANES(dots, 1, 1, 1, 1)) * q) + (two * qw) * (qj * pk - qk * pj)) +
      w * t;
  const V4<T> weight = (qw2 + dots) * w;  // lane 0: |q|² w
  Point<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(r, weight, 2, 1, 0, 4));
  return out;
}

/// apply_generic for planes on four-lane vectors, summed in the same order (the same bits, up to
/// the sign of a zero): normal
/// ((s n + 2 (B·n) B) − 2 q_w (B × n)), offset (q_w² + B·B) d + 2 ((c_w (B·n) + q_w (n·m))
/// − (B × n)·m).
template <class T>
inline Plane<T> apply_simd(const Motor<T>& mo, const Plane<T>& pl) {
  V4<T> lo, hi, v;  // (s, e01, e02, e03), (e12, e31, e23, e0123), (e0, e1, e2, e3)
  load_motor_lanes<T>(mo, lo, hi), load_lanes<T>(pl, 0, v);
  const V4<T> b = PGAMESH_LANES(hi, 2, 1, 0, 3), m = PGAMESH_LANES(lo, 1, 2, 3, 0);
  const V4<T> n = PGAMESH_LANES(v, 1, 2, 3, 0);
  const V4<T> qw = PGAMESH_LANES(lo, 0, 0, 0, 0), cw = PGAMESH_LANES(hi, 3, 3, 3, 3);
  const V4<T> bj = PGAMESH_LANES(b, 1, 2, 0, 3), bk = PGAMESH_LANES(b, 2, 0, 1, 3);
  const V4<T> nj = PGAMESH_LANES(n, 1, 2, 0, 3), nk = PGAMESH_LANES(n, 2, 0, 1, 3);
  const V4<T> bxn = bj * nk - bk * nj;
  // Lanes (B·B, B·n, n·m, (B × n)·m), each summed (x + y) + z.
  const V4<T> p1 = b * b, p2 = b * n, p3 = n * m, p4 = bxn * m;
  const V4<T> lo12 = PGAMESH_LANES2(p1, p2, 0, 4, 1, 5), lo34 = PGAMESH_LANES2(p3, p4, 0, 4, 1, 5);
  const V4<T> hi12 = PGAMESH_LANES2(p1, p2, 2, 6, 2, 6), hi34 = PGAMESH_LANES2(p3, p4, 2, 6, 2, 6);
  const V4<T> dots =
      (PGAMESH_LANES2(lo12, lo34, 0, 1, 4, 5) + PGAMESH_LANES2(lo12, lo34, 2, 3, 6, 7)) +
      PGAMESH_LANES2(hi12, hi34, 0, 1, 4, 5);
  const V4<T> qw2 = qw * qw;
  const V4<T> two = {T(2), T(2), T(2), T(2)};
  const V4<T> r =
      ((qw2 - PGAMESH_LANES(dots, 0, 0, 0, 0)) * n + (two * PGAMESH_LANES(dots, 1, 1, 1, 1)) * b) -
      (two * qw) * bxn;
  // Lane 0: (q_w² + B·B) d + 2 ((c_w (B·n) + q_w (n·m)) − (B × n)·m).
  const V4<T> d =
      (qw2 + dots) * v +
      two * ((cw * PGAMESH_LANES(dots, 1, 1, 1, 1) + qw * PGAMESH_LANES(dots, 2, 2, 2, 2)) -
             PGAMESH_LANES(dots, 3, 3, 3, 3));
  Plane<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(d, r, 0, 4, 5, 6));
  return out;
}

/// The point sandwich with lane-uniform sums, for float (to rounding; apply_generic's sums are
/// grouped otherwise): the same M X M̃ (motors as in docs/conventions.md §7, points §2, in the
/// dual-quaternion form of quaternion.hpp). With q_v = v, c_v = c and lane i's next and previous
/// coordinates n, p (x → y → z → x), rotate(q, P) (quaternion.hpp) as a matrix,
///   R_ii = (q_w² + v_i²) − (v_n² + v_p²),
///   R_in = 2 (v_i v_n − q_w v_p),  R_ip = 2 (v_i v_p + q_w v_n),
/// and t_i = 2 ((c_w v_i − q_w c_i) + (c_n v_p − c_p v_n)), so that every lane sums the same
/// pattern: P'_i = ((R_ii P_i + R_in P_n) + R_ip P_p) + w t_i; the weight is (q_w² + v·v) w.
/// Lanes in the point's storage order (z, y, x, w): n and p are lanes (2, 0, 1) and (1, 2, 0).
template <class T>
inline Point<T> apply_lanes(const Motor<T>& mo, const Point<T>& x) {
  V4<T> lo, hi, pt;  // (s, e01, e02, e03), (e12, e31, e23, e0123), (e021, e013, e032, e123)
  load_motor_lanes<T>(mo, lo, hi), load_lanes<T>(x, 0, pt);
  const V4<T> v = -hi, c = PGAMESH_LANES(lo, 3, 2, 1, 0);  // (z, y, x, ·) of q_v and c_v
  const V4<T> qw = PGAMESH_LANES(lo, 0, 0, 0, 0), cw = PGAMESH_LANES(hi, 3, 3, 3, 3);
  const V4<T> w = PGAMESH_LANES(pt, 3, 3, 3, 3);
  const V4<T> vn = PGAMESH_LANES(v, 2, 0, 1, 3), vp = PGAMESH_LANES(v, 1, 2, 0, 3);
  const V4<T> cn = PGAMESH_LANES(c, 2, 0, 1, 3), cp = PGAMESH_LANES(c, 1, 2, 0, 3);
  const V4<T> pn = PGAMESH_LANES(pt, 2, 0, 1, 3), pp = PGAMESH_LANES(pt, 1, 2, 0, 3);
  const V4<T> vv = v * v;
  const V4<T> a = qw * qw + vv, b = PGAMESH_LANES(vv, 2, 0, 1, 3) + PGAMESH_LANES(vv, 1, 2, 0, 3);
  const V4<T> rii = a - b, weight = (a + b) * w;  // weight: lane 0 holds (q_w² + v·v) w
  const V4<T> rin = v * vn - qw * vp, rip = v * vp + qw * vn;
  const V4<T> t = (cw * v - qw * c) + (cn * vp - cp * vn);
  const V4<T> r = ((rii * pt + (rin + rin) * pn) + (rip + rip) * pp) + (w + w) * t;
  Point<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(r, weight, 0, 1, 2, 4));
  return out;
}

/// The plane sandwich with lane-uniform sums, for float (to rounding), M p M̃ (docs/conventions.md
/// §7, planes §2): the normal n' = R n with
/// apply_lanes' matrix R, and the e0 coefficient |q|² d + 2 Σ_i ((q_w c_i − c_w v_i) n_i +
/// (v × n)_i c_i), apply_generic's 2 (−c_w (v·n) + q_w (n·c) + (v × n)·c) summed lane by lane.
/// Lanes in the plane's storage order (e0, e1, e2, e3): n and p of lanes 1, 2, 3 are lanes
/// (2, 3, 1) and (3, 1, 2).
template <class T>
inline Plane<T> apply_lanes(const Motor<T>& mo, const Plane<T>& pl) {
  V4<T> lo, hi, n;  // (s, e01, e02, e03), (e12, e31, e23, e0123), (e0, e1, e2, e3)
  load_motor_lanes<T>(mo, lo, hi), load_lanes<T>(pl, 0, n);
  const V4<T> v = -PGAMESH_LANES(hi, 3, 2, 1, 0), c = lo;  // (·, x, y, z) of q_v and c_v
  const V4<T> qw = PGAMESH_LANES(lo, 0, 0, 0, 0), cw = PGAMESH_LANES(hi, 3, 3, 3, 3);
  const V4<T> d = PGAMESH_LANES(n, 0, 0, 0, 0);
  const V4<T> vn = PGAMESH_LANES(v, 0, 2, 3, 1), vp = PGAMESH_LANES(v, 0, 3, 1, 2);
  const V4<T> nn = PGAMESH_LANES(n, 0, 2, 3, 1), np = PGAMESH_LANES(n, 0, 3, 1, 2);
  const V4<T> vv = v * v;
  const V4<T> a = qw * qw + vv, b = PGAMESH_LANES(vv, 0, 2, 3, 1) + PGAMESH_LANES(vv, 0, 3, 1, 2);
  const V4<T> rin = v * vn - qw * vp, rip = v * vp + qw * vn;
  const V4<T> r = ((a - b) * n + (rin + rin) * nn) + (rip + rip) * np;
  const V4<T> e = (qw * c - cw * v) * n + (vn * np - vp * nn) * c;
  const V4<T> sum = (e + PGAMESH_LANES(e, 0, 2, 3, 1)) + PGAMESH_LANES(e, 0, 3, 1, 2);
  const V4<T> offset = (a + b) * d + (sum + sum);  // lane 1: the e0 coefficient
  Plane<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(r, offset, 5, 1, 2, 3));
  return out;
}
#endif
}  // namespace detail

/// M X M̃ for a point X = w I3 − ε P: weight |q|² w, weighted position q P q* + w t with
/// t = 2 (c_w q_v − q_w c_v + c_v × q_v) the translation (−2 vec(c q*)). For a normalized M,
/// the rigid motion of the point (a direction, w = 0, is only rotated). float runs apply_lanes
/// (to rounding), double the generic formula or its four-lane form (the same bits; docs/pga3.md
/// "Speed").
template <class T>
constexpr Point<T> apply(const Motor<T>& m, const Point<T>& x) {
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (std::is_same_v<T, float>) {
    if (!std::is_constant_evaluated()) return detail::apply_lanes(m, x);
  } else if constexpr (detail::kHasSimd<T>) {
    if (!std::is_constant_evaluated()) return detail::apply_simd(m, x);
  }
#endif
  if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
    if (!std::is_constant_evaluated()) return detail::apply(detail::Isa::avx2, m, x);
  return detail::apply_generic(m, x);
}

/// M p M̃ for a plane p = n + d e0: normal q n q*, e0 coefficient |q|² d + 2 Re(q n c*)
/// (= d − n·t for a unit rotation-free motor translating by t). float runs apply_lanes (to
/// rounding), double the generic formula or, under AVX, its four-lane form.
template <class T>
constexpr Plane<T> apply(const Motor<T>& m, const Plane<T>& p) {
#ifdef PGAMESH_PGA3_SIMD
  if constexpr (std::is_same_v<T, float>) {
    if (!std::is_constant_evaluated()) return detail::apply_lanes(m, p);
  } else if constexpr (detail::kHasSimd<T>) {
    if (!std::is_constant_evaluated()) return detail::apply_simd(m, p);
  }
#endif
  return detail::apply_generic(m, p);
}

/// M L M̃ for a line L = (0, −l) + ε (0, m): direction q l q*, moment q m q* − 2 vec(q l c*)
/// (= m + t × l for a translation by t).
template <class T>
constexpr Line<T> apply(const Motor<T>& mo, const Line<T>& line) {
  using detail::dual_part, detail::real_part;
  const auto q = real_part(mo), c = dual_part(mo);
  const Vec3<T> l = line.direction();
  const detail::Quat<T> ql{-dot(q.v, l), q.w * l + cross(q.v, l)};  // q l
  const Vec3<T> qlc = c.w * ql.v - ql.w * c.v - cross(ql.v, c.v);   // vec(q l c*)
  return line_from_plucker(detail::rotate(q, l), detail::rotate(q, line.moment()) - T(2) * qlc);
}

/// M N M̃ for a motor N (conjugation: the motion N seen in the frame moved by M).
template <class T>
constexpr Motor<T> apply(const Motor<T>& m, const Motor<T>& n) {
  return m * n * reverse(m);
}

}  // namespace pgamesh::pga3
