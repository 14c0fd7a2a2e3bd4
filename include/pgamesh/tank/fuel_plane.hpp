// The fuel plane of a tank: up·x = level with a unit up vector; the fuel is the part up·x ≤ level
// (docs/fuel.md, docs/conventions.md §12).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::tank {

/// The normalized plane p = (up·x − level) as a PGA plane (normal up, e0 coefficient −level): its
/// normal points out of the fuel, so p ∨ v > 0 above and p ∨ v ≤ 0 in the fuel (docs/conventions.md
/// §12).
struct FuelPlane {
  Vec3d up{0, 0, 1};  // unit
  double level = 0;

  pga3::Plane<double> plane() const { return pga3::plane(up.x, up.y, up.z, -level); }
};

/// The unit vector along `up`; throws std::invalid_argument for a zero or non-finite vector. A
/// vector whose squared length is exactly 1 is kept as given, so that planes through vertices
/// given with a unit up vector stay exact.
inline Vec3d unit_up(Vec3d up) {
  const double n2 = dot(up, up);
  if (!std::isfinite(up.x) || !std::isfinite(up.y) || !std::isfinite(up.z) || !std::isfinite(n2))
    throw std::invalid_argument("the up vector must be finite");
  if (n2 == 0) throw std::invalid_argument("the up vector must not be zero");
  return n2 == 1 ? up : up / std::sqrt(n2);
}

/// The plane up·x = level with up normalized (unit_up); throws for a bad up vector or a
/// non-finite level.
inline FuelPlane fuel_plane(Vec3d up, double level) {
  if (!std::isfinite(level)) throw std::invalid_argument("the level must be finite");
  return {unit_up(up), level};
}

/// p ∨ v (paper eq. 4.10): the signed height of v above the fuel plane; ≤ 0 is fuel.
inline double height_above(const FuelPlane& p, Vec3d v) {
  return pga3::join(p.plane(), pga3::point(v));
}

}  // namespace pgamesh::tank
