// Capping a hole: the triangles that close one boundary loop, laid in the loop's own best-fit
// plane. The plane comes from the loop's summed edge carriers (geometry/edge_loop.hpp): their
// moment is twice the rim's vector area (paper §4c, Table 1 "planar polygon area", in 3-D as
// docs/conventions.md §6 states it), whose direction is the plane's normal, and the plane passes
// through the rim's centroid. The rim is projected onto that plane and ear-clipped
// (docs/topology.md, "Repair").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

struct HoleCapOptions {
  // The rim is planar enough when every vertex lies within planarity × (the rim's bounding-box
  // diagonal) of the best-fit plane; a rim less planar than that is capped only with `force`.
  double planarity = 1e-6;
  bool force = false;
};

struct HoleCap {
  // The cap's triangles, as vertex indices, running against the rim (each rim edge a → b is used
  // b → a by the cap), so that the capped surface is consistently oriented.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Vec3d normal{};            // unit normal of the best-fit plane, the cap's orientation
  double area = 0;           // area of the rim's projection onto the plane (the cap's area)
  double max_deviation = 0;  // largest distance of a rim vertex from the plane
  double diameter = 0;       // the rim's bounding-box diagonal
  std::string refused;       // why the hole was not capped; empty when it was
  bool capped() const { return refused.empty(); }
};

// Caps the hole bounded by `rim`: vertex indices into `positions`, in the order of the boundary
// half-edges (the direction the neighbouring faces run). Refuses, with the reason in `refused`: a
// rim of fewer than three vertices or of zero area, a rim not planar within the tolerance (unless
// options.force), a rim whose projection crosses itself or repeats a vertex (its cap would
// intersect itself — never capped, whatever `force` says), and a rim of more than 100,000
// vertices (ear clipping is quadratic).
HoleCap cap_hole(std::span<const Vec3d> positions, std::span<const std::uint32_t> rim,
                 const HoleCapOptions& options = {});

}  // namespace pgamesh
