// Boundary loops of a welded mesh: the chains of boundary half-edges (sides of edges used by
// exactly one face), each followed in its face's direction. Around each loop the edge carriers sum
// to twice the vector area of the hole's rim (geometry/edge_loop.hpp), and the loops' vector areas
// add up to ½ Σ F's normal part, the gap of Cor. 4.1.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

struct BoundaryLoop {
  std::vector<std::uint32_t>
      half_edges;       // corners whose outgoing half-edges form the loop, in order
  bool closed = true;   // ends where it starts; false for an open chain, which only happens where
                        // orientation is inconsistent (boundary in- and out-degrees differ)
  Vec3d vector_area{};  // ½ Σ a × b (edge-carrier moments), ‖·‖ = area for a planar rim
  double area = 0;      // ‖vector_area‖ = ½ ‖Σ E_i‖∞ (docs/conventions.md §6)
  double perimeter = 0;
};

// The boundary loops through the boundary sides, in a deterministic order: sides[i] is a boundary
// half-edge (its corner; ascending), running from welded vertex tails[i] to heads[i]. Chains are
// traced from the lowest unused boundary half-edge, open chains first (from vertices with more
// outgoing than incoming boundary sides); at a vertex where several boundary sides leave (two
// holes touching) the lowest unused one is taken. Coordinates are positions[w], the welded
// vertices' (their representatives'), taken relative to `reference`.
std::vector<BoundaryLoop> trace_boundary_loops(std::span<const std::uint32_t> sides,
                                               std::span<const std::uint32_t> tails,
                                               std::span<const std::uint32_t> heads,
                                               std::span<const Vec3d> positions, Vec3d reference);

}  // namespace pgamesh
