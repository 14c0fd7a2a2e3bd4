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

/// The motor product and the point and plane sandwiches summed in the order of the
/// dual-quaternion formulas (quaternion.hpp; the products q_a q_b, q_a c_b + c_a q_b and the
/// rotation q x q* as dot and cross products), for any scalar type. Their values equal the
/// operators' to rounding; they are the forms the mass properties and the tank's attitude are
/// computed with, whose bits stay the same from one version to the next (docs/pga3.md "Two
/// summation orders"), and the operators' forms for other scalar types and constant evaluation.
namespace quaternion_order {
/// The geometric product A B of two motors, (q_a + ε c_a)(q_b + ε c_b) =
/// q_a q_b + ε (q_a c_b + c_a q_b) (docs/conventions.md §7).
template <class T>
constexpr Motor<T> geometric_product(const Motor<T>& a, const Motor<T>& b) {
  using detail::dual_part, detail::real_part;
  const auto qa = real_part(a), qb = real_part(b), ca = dual_part(a), cb = dual_part(b);
  return detail::motor_from(qa * qb, qa * cb + ca * qb);
}
}  // namespace quaternion_order

namespace detail {
#ifdef PGAMESH_PGA3_SIMD
/// A motor's eight coefficients in two four-lane vectors, in its storage order: the dual
/// quaternion's halves lo = (s, e23, e31, e12) (q with its vector part negated) and
/// hi = (e0123, e01, e02, e03) (c).
template <class T>
[[gnu::always_inline]] inline void load_motor_lanes(const Motor<T>& m, V4<T>& lo, V4<T>& hi) {
  load_lanes<T>(m, 0, lo), load_lanes<T>(m, 4, hi);
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

/// The motor product with lane-uniform sums: every lane does the same operations, on operands
/// shuffled so that lane 0 holds the scalar (or e0123) coefficient and lanes 1, 2, 3 the three
/// bivector coefficients, in cyclic order (i, j, k). With a = (s, e23, e31, e12) and
/// b = (e0123, e01, e02, e03) of the left factor, c and d the same of the right one (the two halves
/// as stored), the product is
///   e_0 = a_0 c_0 − (a_1 c_1 + a_2 c_2 + a_3 c_3),
///   e_i = a_0 c_i + a_i c_0 + a_k c_j − a_j c_k                       → (s, e23, e31, e12),
///   f_0 = a_0 d_0 + b_0 c_0 + Σ_i (a_i d_i + b_i c_i),
///   f_i = a_0 d_i + b_i c_0 + a_k d_j + b_k c_j − (a_i d_0 + b_0 c_i + a_j d_k + b_j c_k)
///                                                                     → (e0123, e01, e02, e03)
/// (the dual-quaternion product of quaternion.hpp written out, motors as in docs/conventions.md
/// §7). Each sum is a few products of two shuffled vectors, and a term subtracted in lanes 1, 2, 3
/// is added in lane 0 by one flip of lane 0's sign bit; the lane-0 products are placed so that the
/// shuffles are shared: 14 shuffles, 12 multiplications, 10 additions, 2 sign flips. Other rounding
/// than the quaternion order of quaternion_order::geometric_product (a few ulps; docs/pga3.md "Two
/// summation orders").
template <class T>
inline Motor<T> geometric_product_lanes(const Motor<T>& left, const Motor<T>& right) {
  V4<T> a, b, c, d;
  load_motor_lanes<T>(left, a, b), load_motor_lanes<T>(right, c, d);
  constexpr T P = T(0), N = -T(0);
  const V4<T> lane0 = {N, P, P, P};  // flips lane 0
  const V4<T> a0 = PGAMESH_LANES(a, 0, 0, 0, 0), a_i = PGAMESH_LANES(a, 1, 1, 2, 3);
  const V4<T> a_k = PGAMESH_LANES(a, 2, 3, 1, 2), a_j = PGAMESH_LANES(a, 3, 2, 3, 1);
  const V4<T> c0 = PGAMESH_LANES(c, 1, 0, 0, 0), c_j = PGAMESH_LANES(c, 2, 2, 3, 1);
  const V4<T> c_k = PGAMESH_LANES(c, 3, 3, 1, 2);
  // e: a_i c_0 + a_k c_j (lane 0: a_1 c_1 + a_2 c_2) with lane 0 negated, then − a_j c_k.
  V4<T> t = a_i * c0 + a_k * c_j;
  flip_signs<T>(t, lane0);
  const V4<T> e = (a0 * c + t) - a_j * c_k;
  // f: the added terms, then the subtracted ones (added in lane 0).
  const V4<T> b_i = PGAMESH_LANES(b, 1, 1, 2, 3), b_j = PGAMESH_LANES(b, 3, 2, 3, 1);
  const V4<T> b_k = PGAMESH_LANES(b, 2, 3, 1, 2), b0 = PGAMESH_LANES(b, 0, 0, 0, 0);
  const V4<T> d0 = PGAMESH_LANES(d, 1, 0, 0, 0), d_j = PGAMESH_LANES(d, 2, 2, 3, 1);
  const V4<T> d_k = PGAMESH_LANES(d, 3, 3, 1, 2);
  const V4<T> added = (a0 * d + b_i * c0) + (a_k * d_j + b_k * c_j);
  V4<T> subtracted = ((a_i * d0 + b0 * c) + a_j * d_k) + b_j * c_k;
  flip_signs<T>(subtracted, lane0);
  Motor<T> out;
  store_lanes<T>(out, 0, e);
  store_lanes<T>(out, 4, added - subtracted);
  return out;
}
#endif
}  // namespace detail

/// The geometric product A B of two motors, (q_a + ε c_a)(q_b + ε c_b) =
/// q_a q_b + ε (q_a c_b + c_a q_b). As a motion, B acts first: (A B) X (A B)~ = A (B X B̃) Ã.
/// float, and double with AVX2, sum every coefficient in one pattern (geometric_product_lanes: to
/// rounding the quaternion order of quaternion_order::geometric_product; docs/pga3.md "Two
/// summation orders").
template <class T>
constexpr Motor<T> geometric_product(const Motor<T>& a, const Motor<T>& b) {
  if (!std::is_constant_evaluated()) {
    if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
      return detail::kRunsAvx2 ? detail::avx2::geometric_product(a, b)
                               : quaternion_order::geometric_product(a, b);
#ifdef PGAMESH_PGA3_SIMD
    else if constexpr (detail::kHasSimd<T>)
      return detail::geometric_product_lanes(a, b);
#endif
  }
  return quaternion_order::geometric_product(a, b);
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
  return {.s = m.s,
          .e23 = -m.e23,
          .e31 = -m.e31,
          .e12 = -m.e12,
          .e0123 = m.e0123,
          .e01 = -m.e01,
          .e02 = -m.e02,
          .e03 = -m.e03};
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
  return {.s = c, .e23 = -s * axis.x, .e31 = -s * axis.y, .e12 = -s * axis.z};
}

/// The translator by t: T = 1 − ½ (t_x e01 + t_y e02 + t_z e03) (docs/conventions.md §7)
/// = exp(−½ t·e0i).
template <class T>
constexpr Motor<T> translator(Vec3<T> t) {
  return {.s = T(1), .e01 = -t.x / 2, .e02 = -t.y / 2, .e03 = -t.z / 2};
}

namespace quaternion_order {
/// M X M̃ for a point (apply below).
template <class T>
constexpr Point<T> apply(const Motor<T>& m, const Point<T>& x) {
  using detail::dual_part, detail::real_part, detail::rotate;
  const auto q = real_part(m), c = dual_part(m);
  const T w = x.e123;
  const Vec3<T> t = T(2) * (c.w * q.v - q.w * c.v + cross(c.v, q.v));
  const Vec3<T> p = rotate(q, x.weighted()) + w * t;
  return {.e123 = dot4(q, q) * w, .e032 = p.x, .e013 = p.y, .e021 = p.z};
}
/// M p M̃ for a plane (apply below).
template <class T>
constexpr Plane<T> apply(const Motor<T>& m, const Plane<T>& p) {
  using detail::dual_part, detail::real_part, detail::rotate;
  const auto q = real_part(m), c = dual_part(m);
  const Vec3<T> n = p.normal();
  const Vec3<T> rn = rotate(q, n);
  const T d =
      dot4(q, q) * p.e0 + T(2) * (-c.w * dot(q.v, n) + q.w * dot(n, c.v) + dot(cross(q.v, n), c.v));
  return {d, rn.x, rn.y, rn.z};
}
}  // namespace quaternion_order

namespace detail {
#ifdef PGAMESH_PGA3_SIMD
/// The point sandwich with lane-uniform sums (to rounding quaternion_order::apply, whose sums are
/// grouped in the quaternion order): the same M X M̃ (motors as in docs/conventions.md §7, points
/// §2, in the dual-quaternion form of quaternion.hpp). With q_v = v, c_v = c and lane i's next and
/// previous coordinates n, p (x → y → z → x), rotate(q, P) (quaternion.hpp) as a matrix,
///   R_ii = (q_w² + v_i²) − (v_n² + v_p²),
///   R_in = 2 (v_i v_n − q_w v_p),  R_ip = 2 (v_i v_p + q_w v_n),
/// and t_i = 2 ((c_w v_i − q_w c_i) + (c_n v_p − c_p v_n)), so that every lane sums the same
/// pattern: P'_i = R_ii P_i + 2 h_i, h_i = (R_in/2 P_n + R_ip/2 P_p) + w t_i/2 (the halves are
/// what is computed: one doubling instead of three); the weight is (q_w² + v·v) w.
/// The point's lanes (w, x, y, z) match the motor halves' (s, e23, e31, e12) = (q_w, −v) and
/// (e0123, e01, e02, e03) = (c_w, c), so the halves are used as loaded (u = −v: the signs are
/// folded into the formulas); n and p are lanes (2, 3, 1) and (3, 1, 2), and lane 0 sums
/// (q_w² + u_3²) + (u_1² + u_2²) for the weight.
template <class T>
inline Point<T> apply_lanes(const Motor<T>& mo, const Point<T>& x) {
  V4<T> u, c, pt;  // (q_w, −v), (c_w, c), (w, x, y, z)
  load_motor_lanes<T>(mo, u, c), load_lanes<T>(x, 0, pt);
  const V4<T> qw = PGAMESH_LANES(u, 0, 0, 0, 0), cw = PGAMESH_LANES(c, 0, 0, 0, 0);
  const V4<T> w = PGAMESH_LANES(pt, 0, 0, 0, 0);
  const V4<T> ui = PGAMESH_LANES(u, 3, 1, 2, 3);  // lane 0: u_3, for the weight
  const V4<T> un = PGAMESH_LANES(u, 1, 2, 3, 1), up = PGAMESH_LANES(u, 2, 3, 1, 2);
  const V4<T> cn = PGAMESH_LANES(c, 0, 2, 3, 1), cp = PGAMESH_LANES(c, 0, 3, 1, 2);
  const V4<T> pn = PGAMESH_LANES(pt, 0, 2, 3, 1), pp = PGAMESH_LANES(pt, 0, 3, 1, 2);
  const V4<T> a = qw * qw + ui * ui, b = un * un + up * up;
  const V4<T> rii = a - b, weight = (a + b) * w;  // weight: lane 0 holds (q_w² + v·v) w
  const V4<T> rin = u * un + qw * up, rip = u * up - qw * un;  // R_in / 2, R_ip / 2
  const V4<T> t = (cp * un - cn * up) - (cw * u + qw * c);     // t / 2
  const V4<T> half = (rin * pn + rip * pp) + w * t;
  const V4<T> r = rii * pt + (half + half);
  Point<T> out;
  store_lanes<T>(out, 0, PGAMESH_LANES2(r, weight, 4, 1, 2, 3));
  return out;
}

/// The plane sandwich with lane-uniform sums (to rounding quaternion_order::apply), M p M̃
/// (docs/conventions.md §7, planes §2): the normal n' = R n with apply_lanes' matrix R, and the e0
/// coefficient |q|² d + 2 Σ_i ((q_w c_i − c_w v_i) n_i + (v × n)_i c_i), quaternion_order::apply's
/// 2 (−c_w (v·n) + q_w (n·c) + (v × n)·c) summed lane by lane. As for points, u = −v is used as
/// loaded, its signs folded into the formulas. Lanes in the plane's storage order (e0, e1, e2, e3):
/// n and p of lanes 1, 2, 3 are lanes (2, 3, 1) and (3, 1, 2).
template <class T>
inline Plane<T> apply_lanes(const Motor<T>& mo, const Plane<T>& pl) {
  V4<T> u, c, n;  // (q_w, −v), (c_w, c), (d, n_x, n_y, n_z)
  load_motor_lanes<T>(mo, u, c), load_lanes<T>(pl, 0, n);
  const V4<T> qw = PGAMESH_LANES(u, 0, 0, 0, 0), cw = PGAMESH_LANES(c, 0, 0, 0, 0);
  const V4<T> d = PGAMESH_LANES(n, 0, 0, 0, 0);
  const V4<T> un = PGAMESH_LANES(u, 0, 2, 3, 1), up = PGAMESH_LANES(u, 0, 3, 1, 2);
  const V4<T> nn = PGAMESH_LANES(n, 0, 2, 3, 1), np = PGAMESH_LANES(n, 0, 3, 1, 2);
  const V4<T> uu = u * u;
  const V4<T> a = qw * qw + uu, b = PGAMESH_LANES(uu, 0, 2, 3, 1) + PGAMESH_LANES(uu, 0, 3, 1, 2);
  const V4<T> rin = u * un + qw * up, rip = u * up - qw * un;  // R_in / 2, R_ip / 2
  const V4<T> half = rin * nn + rip * np;
  const V4<T> r = (a - b) * n + (half + half);
  const V4<T> e = (qw * c + cw * u) * n + (up * nn - un * np) * c;
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
/// the rigid motion of the point (a direction, w = 0, is only rotated). float, and double with
/// AVX2, run apply_lanes (to rounding the quaternion order of quaternion_order::apply;
/// docs/pga3.md "Two summation orders").
template <class T>
constexpr Point<T> apply(const Motor<T>& m, const Point<T>& x) {
  if (!std::is_constant_evaluated()) {
    if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
      return detail::kRunsAvx2 ? detail::avx2::apply(m, x) : quaternion_order::apply(m, x);
#ifdef PGAMESH_PGA3_SIMD
    else if constexpr (detail::kHasSimd<T>)
      return detail::apply_lanes(m, x);
#endif
  }
  return quaternion_order::apply(m, x);
}

/// M p M̃ for a plane p = n + d e0: normal q n q*, e0 coefficient |q|² d + 2 Re(q n c*)
/// (= d − n·t for a unit rotation-free motor translating by t). float, and double with AVX2, run
/// apply_lanes, as for points.
template <class T>
constexpr Plane<T> apply(const Motor<T>& m, const Plane<T>& p) {
  if (!std::is_constant_evaluated()) {
    if constexpr (std::is_same_v<T, double> && detail::kDoubleOutOfLine)
      return detail::kRunsAvx2 ? detail::avx2::apply(m, p) : quaternion_order::apply(m, p);
#ifdef PGAMESH_PGA3_SIMD
    else if constexpr (detail::kHasSimd<T>)
      return detail::apply_lanes(m, p);
#endif
  }
  return quaternion_order::apply(m, p);
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
