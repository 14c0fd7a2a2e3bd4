// PGA R(3,0,1) element types by grade, named as klein names them: Plane (grade 1), Line
// (grade 2), Point (grade 3) and Motor (even: scalar + bivector + pseudoscalar). Conventions:
// docs/conventions.md §1 — basis 1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032,
// e123, e0123; e0² = 0, e1² = e2² = e3² = 1; point (x,y,z) = e123 + x e032 + y e013 + z e021; plane
// a x + b y + c z + d = 0 ↔ a e1 + b e2 + c e3 + d e0.
//
// Every type lists its coefficients in `members` (pointers to members, in basis order), so the
// linear operations (+, −, scaling) are written once for all of them (linear.hpp).
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::pga3 {

namespace detail {
/// The alignment of Plane, Point and Motor: four coefficients (16 bytes in float, 32 in double)
/// for float and double, so that the four-lane kernels' loads and stores (motor.hpp, join.hpp)
/// never straddle a cache line. A motor 16 bytes off a line, on the stack or in an array, made
/// one of its halves straddle it, and the double product took twice its time in half the runs
/// of the benchmark (by where the allocator and the stack put the inputs).
template <class T>
inline constexpr std::size_t kLaneAlign = std::is_floating_point_v<T> ? 4 * sizeof(T) : alignof(T);
}  // namespace detail

// Grade 1: the plane a x + b y + c z + d = 0 as a e1 + b e2 + c e3 + d e0.
template <class T>
struct alignas(detail::kLaneAlign<T>) Plane {
  using scalar_type = T;
  T e0{}, e1{}, e2{}, e3{};
  /// The normal (a, b, c) = (e1, e2, e3) coefficients.
  constexpr Vec3<T> normal() const { return {e1, e2, e3}; }
  static constexpr auto members = std::tuple{&Plane::e0, &Plane::e1, &Plane::e2, &Plane::e3};
};

// Grade 2: a line. Its Euclidean part (e23, e31, e12) is the direction, its ideal part
// (e01, e02, e03) the moment: v0 ∨ v1 has direction v1 − v0 and moment v0 × v1 (paper eq. 3.10).
// A line with zero direction is an ideal line (a line at infinity, e.g. a translation axis).
template <class T>
struct Line {
  using scalar_type = T;
  T e01{}, e02{}, e03{}, e12{}, e31{}, e23{};
  /// The direction (e23, e31, e12) — the Euclidean part (paper eq. 3.10).
  constexpr Vec3<T> direction() const { return {e23, e31, e12}; }
  /// The moment (e01, e02, e03) — the ideal part; p × direction for any point p on the line.
  constexpr Vec3<T> moment() const { return {e01, e02, e03}; }
  static constexpr auto members =
      std::tuple{&Line::e01, &Line::e02, &Line::e03, &Line::e12, &Line::e31, &Line::e23};
};

// Grade 3: the point w·(x,y,z) = w e123 + w x e032 + w y e013 + w z e021; w = 0 is a direction.
// Stored weight first, (e123, e032, e013, e021) = (w, w x, w y, w z), so that the coordinates sit
// in the lanes of the motor halves' (e23, e31, e12); initialise by name. `members` lists the
// basis order.
template <class T>
struct alignas(detail::kLaneAlign<T>) Point {
  using scalar_type = T;
  T e123{}, e032{}, e013{}, e021{};
  /// The weight w (e123 coefficient); 0 for a direction (ideal point).
  constexpr T weight() const { return e123; }
  /// w·(x, y, z) = (e032, e013, e021).
  constexpr Vec3<T> weighted() const { return {e032, e013, e021}; }
  /// (x, y, z) = weighted() / weight() (docs/conventions.md §2); infinite for a direction.
  constexpr Vec3<T> euclidean() const { return Vec3<T>{e032, e013, e021} / e123; }
  static constexpr auto members =
      std::tuple{&Point::e021, &Point::e013, &Point::e032, &Point::e123};
};

// Even grade: s + e01, e02, e03 (ideal bivector) + e12, e31, e23 (Euclidean bivector) + e0123.
// Rotors (rotations), translators and screws are all motors: rotor(angle, axis) and
// translator(t) (motor.hpp) build them; identity_motor() is 1 (a value-initialised Motor is 0,
// like every other element). X ↦ M X M̃ moves every grade (docs/conventions.md §7).
//
// Stored as the two halves of the dual quaternion q + ε c (quaternion.hpp), each ready for one
// four-lane register: (s, e23, e31, e12) and (e0123, e01, e02, e03), the order klein stores
// them in. Initialise by name (Motor<T>{.s = 1, .e01 = …}); `members` lists the basis order.
template <class T>
struct alignas(detail::kLaneAlign<T>) Motor {
  using scalar_type = T;
  T s{}, e23{}, e31{}, e12{}, e0123{}, e01{}, e02{}, e03{};
  static constexpr auto members = std::tuple{&Motor::s,   &Motor::e01, &Motor::e02, &Motor::e03,
                                             &Motor::e12, &Motor::e31, &Motor::e23, &Motor::e0123};
  /// The sandwich M X M̃ (same as apply(M, X), motor.hpp).
  template <class X>
  constexpr X operator()(const X& x) const {
    return apply(*this, x);
  }
};

// ---- construction
// --------------------------------------------------------------------------------

/// The point (x, y, z) = e123 + x e032 + y e013 + z e021 (docs/conventions.md §2, paper eq. 3.8).
template <class T>
constexpr Point<T> point(T x, T y, T z) {
  return {.e123 = T(1), .e032 = x, .e013 = y, .e021 = z};
}
/// The point at position v (weight 1).
template <class T>
constexpr Point<T> point(Vec3<T> v) {
  return {.e123 = T(1), .e032 = v.x, .e013 = v.y, .e021 = v.z};
}
/// The ideal point (direction) (x, y, z): weight 0. Motors rotate it and do not translate it.
template <class T>
constexpr Point<T> direction(T x, T y, T z) {
  return {.e123 = T(0), .e032 = x, .e013 = y, .e021 = z};
}
/// The ideal point (direction) v: weight 0.
template <class T>
constexpr Point<T> direction(Vec3<T> v) {
  return {.e123 = T(0), .e032 = v.x, .e013 = v.y, .e021 = v.z};
}
/// The origin o = e123 (= e0*, paper §3).
template <class T>
constexpr Point<T> origin() {
  return {.e123 = T(1)};
}
/// The plane a x + b y + c z + d = 0 as a e1 + b e2 + c e3 + d e0 (docs/conventions.md §2).
template <class T>
constexpr Plane<T> plane(T a, T b, T c, T d) {
  return {d, a, b, c};
}
/// The plane n·x + d = 0.
template <class T>
constexpr Plane<T> plane(Vec3<T> n, T d) {
  return {d, n.x, n.y, n.z};
}
/// The line with Plücker coordinates (direction, moment): direction on (e23, e31, e12), moment
/// on (e01, e02, e03) — the layout of v0 ∨ v1 (paper eq. 3.10, moment = p × direction).
template <class T>
constexpr Line<T> line_from_plucker(Vec3<T> direction, Vec3<T> moment) {
  return {moment.x, moment.y, moment.z, direction.z, direction.y, direction.x};
}
/// The line through point p with direction d (moment p × d).
template <class T>
constexpr Line<T> line_through(Vec3<T> p, Vec3<T> d) {
  return line_from_plucker(d, cross(p, d));
}
/// The identity motor 1.
template <class T>
constexpr Motor<T> identity_motor() {
  return {.s = T(1)};
}

}  // namespace pgamesh::pga3
