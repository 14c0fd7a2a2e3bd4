// Internal: whether two triangles of a welded mesh intersect in the sense of the self-intersection
// pass (self_intersections.hpp, docs/topology.md "Self-intersections"), decided exactly with the
// orientation predicates of exact_predicates.hpp. Triangles that share welded vertices may meet
// at those vertices and along the edge they span; any other common point is an intersection.
// Triangles that share none intersect when they have any common point, touching included (CGAL's
// Polygon_mesh_processing::self_intersections decides the same).
#pragma once

#include <cstdint>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::detail {

// A triangle: its corners and their welded vertex indices (shared indices are shared vertices).
struct IndexedTriangle {
  Vec3d p[3];
  std::uint32_t v[3];
};

// Whether t and u, neither degenerate (collinear corners, exact_predicates.hpp), intersect beyond
// the vertices they share: for three shared vertices always; for two (an edge) when the triangles
// are coplanar and lie on the same side of it; for one when the edge of either opposite the shared
// vertex meets the other; for none when they have a common point. When `witness` is given and the
// answer is yes, it receives a point of the intersection (rounded: computed in doubles).
bool triangles_intersect(const IndexedTriangle& t, const IndexedTriangle& u,
                         Vec3d* witness = nullptr);

}  // namespace pgamesh::detail
