// A bounding-volume hierarchy over the tank's triangles whose nodes carry the accumulated boundary
// sums of their triangles (about the tank's reference point). A query for any plane takes a node
// wholly on the kept side as one block of sums, skips a node wholly on the other side, and opens
// only the nodes the plane crosses: the cost follows the crossed triangles, not the mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "pgamesh/tank/fuel_state.hpp"
#include "pgamesh/tank/tank.hpp"

namespace pgamesh::tank {

class FuelIndex {
 public:
  /// Builds the hierarchy (median splits along the longest axis, up to 8 triangles a leaf). The
  /// index keeps a reference to `tank`, which must outlive it.
  explicit FuelIndex(const Tank& tank);

  /// The fuel below the plane, equal to fuel_naive up to rounding. The smaller side is summed
  /// (paper §4d): above the middle of the tank the ullage is computed and taken from the whole.
  FuelState query(const FuelPlane& plane) const;

  /// Lowest and highest up·v over the vertices, by branch and bound over the boxes.
  LevelRange range(Vec3d unit_up) const;

  const Tank& tank() const { return *tank_; }
  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    Vec3d center{}, half{};   // the box of the node's vertices
    std::uint32_t first = 0;  // leaf: first triangle in order_; inner: index of the right child
    std::uint32_t count = 0;  // triangles of a leaf; 0 for an inner node (left child = next)
    BoundarySums sums;        // all triangles below this node, about the tank's reference
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count, std::vector<Vec3d>& centroids);
  void add_leaf(SliceSums& sums, const SliceContext& ctx, Side side, const FuelPlane& plane,
                const Node& node) const;

  const Tank* tank_;
  std::vector<std::uint32_t> order_;  // triangle indices, leaves are contiguous ranges
  std::vector<Node> nodes_;
};

}  // namespace pgamesh::tank
