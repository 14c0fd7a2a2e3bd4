// Carriers of simplices given by Euclidean coordinates: the joins of their vertices (paper
// Def. 4.1), evaluated in the form that keeps the most digits.
#pragma once

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

// The triangle carrier F = a ∨ b ∨ c (docs/conventions.md §5): normal n = (b − a) × (c − a), e0
// coefficient −n·a. Equal to pga3::join(point(a), point(b), point(c)) in exact arithmetic; the e0
// coefficient is formed as −n·a rather than as the triple product −a·(b × c), which cancels badly
// for small triangles far from the origin (docs/conventions.md §13). ‖F‖ = 2 × area; o ∨ F = n·a =
// det(a, b, c) = 6 × the volume of (o, a, b, c).
template <class T>
constexpr pga3::Plane<T> triangle_carrier(Vec3<T> a, Vec3<T> b, Vec3<T> c) {
  const Vec3<T> n = cross(b - a, c - a);
  return pga3::plane(n.x, n.y, n.z, -dot(n, a));
}

// o ∨ F for a plane F and the origin o = e123: −(F ∨ o) = −(F's e0 coefficient)
// (docs/conventions.md §5).
template <class T>
constexpr T origin_join(const pga3::Plane<T>& f) {
  return pga3::join(pga3::origin<T>(), f);
}

}  // namespace pgamesh
