// The boundary sums of one face of a polygon mesh: the single place where mass_properties() and
// the readers' summing consumers (ASCII STL, PLY: faces summed as they are parsed) turn a face into
// sums, so every path gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// Adds the face whose n corners are vertices[c[0]], …, vertices[c[n − 1]], coordinates taken
// relative to `reference`: a triangle by add_triangle, a larger polygon by add_polygon (its
// boundary-edge carriers, paper §4c), a face of fewer than three corners not at all. The corner
// indices must name vertices.
inline void add_mesh_face(BoundarySums& s, const Vec3d* vertices, const std::uint32_t* c,
                          std::size_t n, Vec3d reference) {
  if (n == 3) {
    add_triangle(s, vertices[c[0]] - reference, vertices[c[1]] - reference,
                 vertices[c[2]] - reference);
  } else if (n > 3) {
    // Relative coordinates of one polygon; a small buffer covers nearly every face.
    thread_local std::vector<Vec3d> v;
    v.resize(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = vertices[c[k]] - reference;
    add_polygon(s, v.data(), n);
  }
}

}  // namespace pgamesh
