// Axis-aligned bounding boxes: the cheap "where is the mesh" that picks the reference point for
// accumulation (docs/conventions.md §13) and the scale for relative thresholds.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

struct Box3 {
  Vec3d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3d hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  // True until a point has been added.
  bool empty() const { return !(lo.x <= hi.x); }
  // Grows the box to contain p (NaN coordinates are ignored by the comparisons).
  void add(Vec3d p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Grows the box to contain the box b.
  void add(const Box3& b) {
    if (!b.empty()) {
      add(b.lo);
      add(b.hi);
    }
  }
  // The centre (the origin for an empty box).
  Vec3d centre() const { return empty() ? Vec3d{} : (lo + hi) / 2.0; }
  // The length of the diagonal (0 for an empty box).
  double diagonal() const { return empty() ? 0.0 : length(hi - lo); }
  // The largest |coordinate| of the box, i.e. how far it reaches from the origin along an axis.
  double max_abs() const {
    if (empty()) return 0;
    double m = 0;
    for (int i = 0; i < 3; ++i) m = std::max({m, std::abs(lo[i]), std::abs(hi[i])});
    return m;
  }
};

// The bounding box of a set of points.
inline Box3 bounding_box(std::span<const Vec3d> points) {
  Box3 b;
  for (const Vec3d& p : points) b.add(p);
  return b;
}

}  // namespace pgamesh
