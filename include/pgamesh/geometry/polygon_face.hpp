// A polygonal face as a boundary element: the carrier of a face with k corners is the sum of the
// carriers of the fan (c0, c_i, c_{i+1}); its normal part is Σ c_i × c_{i+1}, which depends on the
// rim only (paper §4c, docs/conventions.md §6). Its area is the signed fan area of
// add_polygon_surface: the polygon's area for any planar polygon, concave ones included, and the
// fan's area for a non-planar one, whose volume terms are those of the same fan.
#pragma once

#include <cstddef>

#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// The sums of one face with `k` corners, `corner(i)` giving corner i relative to the reference
// point: a triangle by add_triangle, a larger polygon by add_polygon (its signed fan area, not
// Σ ‖F‖, which overcounts a concave polygon). Faces with fewer than three corners add nothing.
template <class CornerAt>
BoundarySums polygon_face_sums(std::size_t k, CornerAt corner) {
  BoundarySums p;
  if (k < 3) return p;
  if (k == 3) {
    add_triangle(p, corner(0), corner(1), corner(2));
    return p;
  }
  add_polygon(p, k, corner);
  return p;
}

// The normal part of the face's carrier, Σ (c_i − c_0) × (c_{i+1} − c_0) = 2 × its vector area,
// from the corners as given. Taken about the face's own first corner it keeps the digits of a face
// that is tiny compared with its distance from the mesh's reference point (the zero-area test).
template <class CornerAt>
Vec3d polygon_normal(std::size_t k, CornerAt corner) {
  Vec3d n{};
  if (k < 3) return n;
  const Vec3d a = corner(0);
  Vec3d b = corner(1);
  for (std::size_t i = 2; i < k; ++i) {
    const Vec3d c = corner(i);
    n += triangle_carrier(a, b, c).normal();
    b = c;
  }
  return n;
}

}  // namespace pgamesh
