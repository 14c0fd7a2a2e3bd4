// Planar polygons in PGA R(2,0,1) measured from their edges (paper eqs. 4.6–4.7, Thm 5.1 with
// k = 2): non-convex and self-overlapping polygons and polygons with holes, without triangulation.
// Each ring is closed implicitly (last vertex joins the first). Orientation carries the sign:
// counter-clockwise rings add, clockwise rings (holes) subtract, and a region wound n times counts
// n times (the signed area is ∫ winding number).
#pragma once

#include <array>
#include <span>
#include <vector>

namespace pgamesh::geometry {

using Vec2 = std::array<double, 2>;

struct PolygonMeasures {
  double signed_area = 0;  // ½ o ∨ Σ E_i (eq. 4.7), CCW > 0
  Vec2 centroid{};         // Σ (v_i + v_(i+1) + o)(o ∨ E_i) / (3! A) (eq. 5.3); NaN when A = 0
  double perimeter = 0;    // Σ ‖E_i‖
};

// Measures of the region bounded by the rings. An empty ring or one with fewer than 2 vertices
// contributes nothing.
PolygonMeasures polygon_measures(std::span<const std::vector<Vec2>> rings);

}  // namespace pgamesh::geometry
