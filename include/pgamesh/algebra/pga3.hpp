// PGA R(3,0,1), hand-specialised by grade (the hot path). Conventions: ERRATA §0.1 —
// basis 1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032, e123, e0123;
// e0² = 0, e1² = e2² = e3² = 1; point (x,y,z) = e123 + x e032 + y e013 + z e021;
// plane a x + b y + c z + d = 0  ↔  a e1 + b e2 + c e3 + d e0; join A ∨ B = (A* ∧ B*)^(−*)
// (eq. 2.2).
//
// Grade types, named as klein names them: Plane (grade 1), Line (grade 2), Point (grade 3),
// Motor (even: scalar + bivector + pseudoscalar) and the full 16-component Multivector.
#pragma once

#include <cmath>

#include "pgamesh/algebra/vec3.hpp"

namespace pgamesh::pga3 {

// Grade 1: the plane a x + b y + c z + d = 0 as a e1 + b e2 + c e3 + d e0.
template <class T>
struct Plane {
  T e0{}, e1{}, e2{}, e3{};
  Vec3<T> normal() const { return {e1, e2, e3}; }
};

// Grade 2: a line. Its Euclidean part (e23, e31, e12) is the direction, its ideal part
// (e01, e02, e03) the moment: v0 ∨ v1 has direction v1 − v0 and moment v0 × v1 (paper eq. 3.10).
template <class T>
struct Line {
  T e01{}, e02{}, e03{}, e12{}, e31{}, e23{};
  Vec3<T> direction() const { return {e23, e31, e12}; }
  Vec3<T> moment() const { return {e01, e02, e03}; }
};

// Grade 3: the point w·(x,y,z) = w e123 + w x e032 + w y e013 + w z e021; w = 0 is a direction.
template <class T>
struct Point {
  T e021{}, e013{}, e032{}, e123{};
  T weight() const { return e123; }
  Vec3<T> weighted() const { return {e032, e013, e021}; }  // w·(x,y,z)
  Vec3<T> euclidean() const { return Vec3<T>{e032, e013, e021} / e123; }
};

template <class T>
constexpr Point<T> point(T x, T y, T z) {
  return {z, y, x, T(1)};
}
template <class T>
constexpr Point<T> point(Vec3<T> v) {
  return {v.z, v.y, v.x, T(1)};
}
// Ideal point (direction): weight 0.
template <class T>
constexpr Point<T> direction(T x, T y, T z) {
  return {z, y, x, T(0)};
}
// The origin o = e123 (= e0*).
template <class T>
constexpr Point<T> origin() {
  return {T(0), T(0), T(0), T(1)};
}
template <class T>
constexpr Plane<T> plane(T a, T b, T c, T d) {
  return {d, a, b, c};
}

// ---- join (regressive product, eq. 2.2) for the grade pairs that build carriers
// ---------------------

// a ∨ b: direction w_a P_b − w_b P_a, moment P_a × P_b (eq. 3.10 for unit weights).
template <class T>
constexpr Line<T> join(const Point<T>& a, const Point<T>& b) {
  const Vec3<T> pa = a.weighted(), pb = b.weighted();
  const Vec3<T> d = a.e123 * pb - b.e123 * pa;
  const Vec3<T> m = cross(pa, pb);
  return {m.x, m.y, m.z, d.z, d.y, d.x};
}

// L ∨ v: normal d × P + w m, e0 coefficient −m·P (ERRATA §0.1: v0 ∨ v1 ∨ v2 = n − det e0).
template <class T>
constexpr Plane<T> join(const Line<T>& l, const Point<T>& v) {
  const Vec3<T> d = l.direction(), m = l.moment(), p = v.weighted();
  const Vec3<T> n = cross(d, p) + v.e123 * m;
  return {-dot(m, p), n.x, n.y, n.z};
}

// v ∨ L = L ∨ v (grades 3 and 2: the sign (−1)^((4−3)(4−2)) is +1).
template <class T>
constexpr Plane<T> join(const Point<T>& v, const Line<T>& l) {
  return join(l, v);
}

// p ∨ v = a x + b y + c z + d for a unit-weight point (eq. 4.10); v ∨ p is its negative.
template <class T>
constexpr T join(const Plane<T>& p, const Point<T>& v) {
  return p.e1 * v.e032 + p.e2 * v.e013 + p.e3 * v.e021 + p.e0 * v.e123;
}
template <class T>
constexpr T join(const Point<T>& v, const Plane<T>& p) {
  return -join(p, v);
}

// v0 ∨ v1 ∨ v2: the carrier of a triangle, normal (v1 − v0) × (v2 − v0), e0 coefficient −det.
template <class T>
constexpr Plane<T> join(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
  return join(join(a, b), c);
}

template <class T>
constexpr Line<T> operator&(const Point<T>& a, const Point<T>& b) {
  return join(a, b);
}
template <class T>
constexpr Plane<T> operator&(const Line<T>& l, const Point<T>& v) {
  return join(l, v);
}
template <class T>
constexpr Plane<T> operator&(const Point<T>& v, const Line<T>& l) {
  return join(v, l);
}
template <class T>
constexpr T operator&(const Plane<T>& p, const Point<T>& v) {
  return join(p, v);
}
template <class T>
constexpr T operator&(const Point<T>& v, const Plane<T>& p) {
  return join(v, p);
}

// ---- norms (ERRATA §0.1): Euclidean = coefficients without e0, ideal = those with e0
// -------------

template <class T>
T norm(const Plane<T>& p) {
  return std::sqrt(p.e1 * p.e1 + p.e2 * p.e2 + p.e3 * p.e3);
}
template <class T>
T ideal_norm(const Plane<T>& p) {
  return std::abs(p.e0);
}
template <class T>
T norm(const Line<T>& l) {
  return std::sqrt(l.e12 * l.e12 + l.e31 * l.e31 + l.e23 * l.e23);
}
template <class T>
T ideal_norm(const Line<T>& l) {
  return std::sqrt(l.e01 * l.e01 + l.e02 * l.e02 + l.e03 * l.e03);
}
template <class T>
T norm(const Point<T>& v) {
  return std::abs(v.e123);
}
template <class T>
T ideal_norm(const Point<T>& v) {
  return std::sqrt(v.e021 * v.e021 + v.e013 * v.e013 + v.e032 * v.e032);
}

}  // namespace pgamesh::pga3
