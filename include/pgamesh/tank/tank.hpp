// A closed mesh prepared for fuel queries: its triangles (polygons fanned from their first
// corner), a reference point near the mesh (ERRATA §6) and the sums of the whole tank.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pgamesh/algebra/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/mesh/mesh.hpp"

namespace pgamesh::tank {

struct Tank {
  std::vector<Vec3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Vec3d lower{}, upper{};  // bounding box of the vertices
  Vec3d reference{};       // centre of the bounding box: sums are accumulated about it
  BoundarySums total;      // the whole tank about `reference`
  double volume = 0;       // signed volume (positive for an outward-oriented closed mesh)
  double area = 0;         // wall area
  double gap_area = 0;     // ½‖Σ F‖: 0 for a closed mesh (Cor. 4.1)
};

/// Prepares a mesh: polygons with n > 3 corners are fanned from their first corner (exact for
/// planar polygons: their carrier is the sum of the fan's carriers). Throws std::invalid_argument
/// for an empty mesh, an index out of range or a non-finite coordinate.
Tank make_tank(const Mesh& mesh);

/// Lowest and highest value of up·v over the vertices (the empty and full levels).
struct LevelRange {
  double lowest = 0, highest = 0;
};
LevelRange level_range(const Tank& tank, Vec3d unit_up);

/// Whether the tank is fit for gauging: closed within `relative_gap` (gap area / wall area) and
/// with a positive volume (outward orientation).
bool is_gaugeable(const Tank& tank, double relative_gap = 1e-9);

}  // namespace pgamesh::tank
