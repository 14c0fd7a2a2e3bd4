// The undirected edges of a welded polygon mesh and the half-edges that use them. Every corner c
// starts one half-edge: from the corner's vertex to the next corner's vertex of the same face. An
// edge is the unordered pair {v0 < v1} of welded vertices; its uses are the half-edges along it,
// "forward" when they run v0 → v1. A half-edge whose ends weld to the same vertex belongs to no
// edge (a collapsed side). A face with fewer than three distinct welded vertices is collapsed: it
// has no area, and leaving it out keeps its neighbours' edges manifold (a triangle whose two
// corners weld together would otherwise add two uses to the edge its neighbours share).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

inline constexpr std::uint32_t no_edge = std::numeric_limits<std::uint32_t>::max();

struct EdgeTable {
  std::vector<std::uint32_t> corner_face;  // corner → its face
  std::vector<std::uint32_t> corner_edge;  // corner (its outgoing half-edge) → edge, or no_edge
  std::vector<std::uint32_t> v0, v1;       // edge → its welded end vertices, v0 < v1
  std::vector<std::uint32_t> use_offsets;  // edge e is used by uses[use_offsets[e] .. [e + 1])
  std::vector<std::uint32_t> uses;         // corners (half-edges), ascending within an edge
  std::vector<std::uint32_t> collapsed_faces;  // faces with < 3 distinct welded vertices, ascending

  std::size_t edge_count() const { return v0.size(); }
  // Number of half-edges (face sides) along edge e.
  std::uint32_t use_count(std::size_t e) const { return use_offsets[e + 1] - use_offsets[e]; }
  std::span<const std::uint32_t> uses_of(std::size_t e) const {
    return {uses.data() + use_offsets[e], use_count(e)};
  }
};

// The corner after c in its face (cyclically).
inline std::uint32_t next_corner(const Mesh& mesh, const EdgeTable& t, std::uint32_t c) {
  const std::uint32_t f = t.corner_face[c];
  return c + 1 == mesh.face_offsets[f + 1] ? mesh.face_offsets[f] : c + 1;
}

// Builds the edge table of `mesh` whose corners have been welded to `welded_corner` (corner →
// welded vertex, each < welded_vertex_count). Edges are numbered in (v0, v1) order: a counting
// sort by the smaller end, then a small sort per vertex — linear time, no hashing, deterministic.
EdgeTable build_edges(const Mesh& mesh, std::span<const std::uint32_t> welded_corner,
                      std::size_t welded_vertex_count);

// Whether the half-edge starting at corner c runs v0 → v1 along its edge.
inline bool is_forward(const EdgeTable& t, std::span<const std::uint32_t> welded_corner,
                       std::uint32_t c) {
  return welded_corner[c] == t.v0[t.corner_edge[c]];
}

}  // namespace pgamesh
