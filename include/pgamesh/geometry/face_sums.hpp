// The boundary sums of one face of a polygon mesh: the single place where mass_properties() and
// the readers' summing consumers (ASCII STL, PLY: faces summed as they are parsed) turn a face into
// sums, so every path gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// Adds the polygon face of n ≥ 4 corners vertices[c[0]], …, vertices[c[n − 1]], coordinates taken
// relative to `reference`, by add_polygon (its boundary-edge carriers, paper §4c). Out of line
// (face_sums.cpp): the rare case, kept out of the readers' per-face loops.
void add_mesh_polygon(BoundarySums& s, const Vec3d* vertices, const std::uint32_t* c, std::size_t n,
                      Vec3d reference);

// Adds the face whose n corners are vertices[c[0]], …, vertices[c[n − 1]], coordinates taken
// relative to `reference`: a triangle by add_triangle (inline, as the readers add one per facet),
// a larger polygon by add_mesh_polygon, a face of fewer than three corners not at all. The corner
// indices must name vertices.
inline void add_mesh_face(BoundarySums& s, const Vec3d* vertices, const std::uint32_t* c,
                          std::size_t n, Vec3d reference) {
  if (n == 3) {
    add_triangle(s, vertices[c[0]] - reference, vertices[c[1]] - reference,
                 vertices[c[2]] - reference);
  } else if (n > 3) {
    add_mesh_polygon(s, vertices, c, n, reference);
  }
}

}  // namespace pgamesh
