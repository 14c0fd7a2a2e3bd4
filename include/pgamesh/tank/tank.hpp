// A closed mesh prepared for fuel queries: its triangles (polygons fanned from their first
// corner), a reference point near the mesh (ERRATA §6) and the sums of the whole tank.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
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

/// Prepares a mesh: polygons with n > 3 corners are fanned from their first corner, and the tank
/// is that triangle surface throughout (its total, every slice): volumes and moments are exact
/// for planar polygons, concave ones included (their carrier is the sum of the fan's carriers);
/// areas are those of the fan triangles, which for a concave face counts the fan's inverted
/// triangles positively, and for a non-planar face differs from add_polygon's ½‖F‖. Throws
/// std::invalid_argument for an empty mesh, an index out of range or a non-finite coordinate.
Tank make_tank(const Mesh& mesh);

/// The bounding box of some vertices, grown one at a time: its centre is a reference point near
/// them (ERRATA §6).
struct VertexBox {
  Vec3d lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity()};
  Vec3d upper = -lower;

  void add(Vec3d v) {
    for (int i = 0; i < 3; ++i) {
      lower[i] = std::min(lower[i], v[i]);
      upper[i] = std::max(upper[i], v[i]);
    }
  }
  bool empty() const { return !(lower.x <= upper.x); }
  Vec3d center() const { return (lower + upper) / 2.0; }
};

/// Lowest and highest value of up·v over the vertices (the empty and full levels).
struct LevelRange {
  double lowest = 0, highest = 0;
};
LevelRange level_range(const Tank& tank, Vec3d unit_up);

/// Whether the tank is fit for gauging: closed within `relative_gap` (gap area / wall area) and
/// with a positive volume (outward orientation).
bool is_gaugeable(const Tank& tank, double relative_gap = 1e-9);

}  // namespace pgamesh::tank
