// Self-intersections: pairs of faces of a welded mesh that meet where they should not — two
// overlapping shells in one file, a surface folded through itself, coplanar neighbours that
// overlap. Their signed volume counts the overlap twice or not at all, so a mesh with any is not a
// solid's boundary (TopologyReport::volume_valid). Definitions, the predicates and the cost in
// docs/topology.md, "Self-intersections".
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

struct SelfIntersection {
  std::uint32_t face0 = 0, face1 = 0;  // face0 < face1, the mesh's face indices
  Vec3d point{};  // a point where they meet (computed in doubles: near the intersection)
};

// The pass stops once it has found this many intersecting face pairs: a soup whose faces nearly
// all meet has up to n²/2 of them, and deciding each would take minutes; a count this large
// already says all there is to say.
inline constexpr std::size_t max_counted_intersections = 1000000;

struct SelfIntersections {
  std::size_t pairs = 0;  // intersecting face pairs (at least this many when !complete)
  bool complete = true;   // false: stopped at max_counted_intersections
  // The first pairs in (face0, face1) order, up to the cap (when !complete: of those found).
  std::vector<SelfIntersection> list;
  std::size_t degenerate_triangles = 0;  // fan triangles with collinear corners, left out
  std::size_t nonfinite_triangles = 0;   // fan triangles with an infinite or NaN corner, left out
};

// The self-intersections of a welded mesh: `positions` are the welded vertices, `corners` their
// indices (three per face when `face_offsets` is empty, else faces of any size in Mesh's CSR).
// Two faces intersect when their (fan) triangles meet beyond the welded vertices they share: faces
// sharing a vertex or an edge may meet there, and anywhere else is an intersection (coplanar
// overlapping neighbours, a face passing through a neighbour), while faces sharing no vertex
// intersect when they touch at all. Triangles of one polygon's fan are not tested against each
// other; fan triangles with exactly collinear corners have no interior and are left out. Decided
// exactly (exact orientation predicates on the doubles) after a bounding-volume hierarchy over the
// fan triangles' boxes; the queries run on two threads for large meshes. Coordinates should be
// finite (a fan triangle with an infinite or NaN corner is left out and counted). Throws
// std::out_of_range for a corner beyond the positions.
SelfIntersections find_self_intersections(std::span<const Vec3d> positions,
                                          std::span<const std::uint32_t> corners,
                                          std::span<const std::uint32_t> face_offsets,
                                          std::size_t list_cap = 20);

// The same on a mesh as read: its vertices welded exactly first (bitwise-equal coordinates,
// weld.hpp), so that faces sharing a position share a vertex. Throws std::out_of_range for a
// malformed mesh (check_mesh_structure).
SelfIntersections find_self_intersections(const Mesh& mesh, std::size_t list_cap = 20);

}  // namespace pgamesh
