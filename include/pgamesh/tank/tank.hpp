// A closed mesh prepared for fuel queries: its triangles (polygons fanned from their first
// corner), a reference point near the mesh (docs/conventions.md §13) and the sums of the whole
// tank.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::tank {

struct Tank {
  std::vector<Vec3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // Per triangle, 1 where a polygon's fan folds back over a concave corner (fan_area_sign = −1):
  // its area counts negatively, so the wetted area of every slice is the faces' signed fan area
  // (docs/conventions.md §6, "Face area of a polygon"). Empty when no triangle folds.
  std::vector<std::uint8_t> folded;
  Vec3d lower{}, upper{};  // bounding box of the vertices
  Vec3d reference{};       // centre of the bounding box: sums are accumulated about it
  BoundarySums total;      // the whole tank about `reference`
  double volume = 0;       // signed volume (positive for an outward-oriented closed mesh)
  double area = 0;         // wall area
  double gap_area = 0;     // ½‖Σ F‖: 0 for a closed mesh (Cor. 4.1)
};

/// The sign with which triangle t's area counts: −1 for a folded fan triangle, else +1.
inline double area_sign(const Tank& tank, std::size_t t) {
  return !tank.folded.empty() && tank.folded[t] ? -1.0 : 1.0;
}

/// Prepares a mesh: polygons with n > 3 corners are fanned from their first corner, and the tank
/// is that triangle surface throughout (its total, every slice): volumes and moments are exact
/// for planar polygons, concave ones included (their carrier is the sum of the fan's carriers),
/// and areas are signed fan areas (area_sign), the face areas of `pgamesh props`. Throws
/// std::invalid_argument for an empty mesh, an index out of range, a non-finite coordinate or
/// coordinates so large that the tank's area or volume overflows a double.
Tank make_tank(const Mesh& mesh);

/// Lowest and highest value of up·v over the vertices (the empty and full levels).
struct LevelRange {
  double lowest = 0, highest = 0;
};
LevelRange level_range(const Tank& tank, Vec3d unit_up);

/// Whether a mesh is fit to be gauged as a tank — the one rule of `pgamesh fuel`, the viewer and
/// the bindings: closed, consistently oriented and a valid volume by the topology report of
/// `pgamesh check` (analyze_topology), and a positive signed volume (outward orientation).
struct TankFitness {
  bool fit = false;
  TopologyReport topology;            // the mesh's topology report
  std::vector<std::string> problems;  // why not fit, in plain words (empty when fit)
};
TankFitness tank_fitness(const Mesh& mesh, const Tank& tank);

}  // namespace pgamesh::tank
