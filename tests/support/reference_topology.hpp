// The combinatorial fields of the topology report computed the slow, obvious way from their
// definitions (docs/topology.md) — a std::map of undirected edges, a breadth-first walk for the
// components, the faces grouped by vertex set for the duplicates — so that the topology pass can be
// checked against code it shares nothing with but the weld (weld_map, tested on its own). The sums
// (area, volume, gap) are left to the closed-form and golden tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh::test {

// An undirected edge {v0 < v1} of welded vertices and its uses (face sides running along it).
struct ReferenceEdge {
  std::uint32_t v0 = 0, v1 = 0;
  std::uint32_t lowest_face = 0;
  std::size_t uses = 0, forward = 0;  // forward: running v0 → v1
};

struct ReferenceTopology {
  WeldMap weld;
  std::size_t triangles = 0;  // Σ (corners − 2) over faces of three corners or more
  std::size_t unreferenced_vertices = 0;
  std::size_t collapsed_faces = 0;            // fewer than three distinct welded vertices
  std::vector<ReferenceEdge> edges;           // ascending by (v0, v1)
  std::vector<std::uint32_t> boundary_sides;  // corners whose sides are an edge's only use
  std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicated;  // (face, same_as), by face
  std::vector<ComponentSummary> components;  // faces and edge counts; no sums
};

ReferenceTopology reference_topology(const Mesh& mesh, double weld_tolerance = 0);

// Every field the reference knows, exactly: counts, the capped edge, duplicate and component lists,
// closedness, and the boundary loops' half-edges (together, the boundary sides).
void expect_matches_reference(const TopologyReport& r, const Mesh& mesh,
                              const TopologyOptions& options = {});

}  // namespace pgamesh::test
