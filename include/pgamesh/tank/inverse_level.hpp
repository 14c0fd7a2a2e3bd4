// The inverse gauge: the level that holds a given volume. V(level) is continuous and
// non-decreasing with the exact derivative dV/dlevel = free-surface area (the right derivative
// where a face lies in the plane), so a safeguarded Newton iteration inside a shrinking bracket
// [lowest, highest] always converges.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "pgamesh/tank/fuel_index.hpp"

namespace pgamesh::tank {

struct LevelSolution {
  double level = 0;
  double volume = 0;   // V(level) as evaluated
  int iterations = 0;  // fuel queries spent
};

/// Stopping rule: |V(level) − volume| ≤ 1e-14 × tank volume, or the bracket (or the last Newton
/// step) narrower than 1e-13 × (highest − lowest). A Newton step leaving the bracket, or a zero
/// free surface, is replaced by bisection. Throws std::domain_error when the volume is negative,
/// not finite, or exceeds the tank's volume (beyond 1e-12 relative); volume 0 gives the lowest
/// point, the full volume the highest.
LevelSolution level_for_volume(const FuelIndex& index, Vec3d up, double volume);

/// The same iteration over any fuel query (e.g. fuel_naive, for comparisons): `range` the tank's
/// extent along the unit vector `up`, `tank_volume` its volume.
LevelSolution level_for_volume(const std::function<FuelState(const FuelPlane&)>& query, Vec3d up,
                               LevelRange range, double tank_volume, double volume);

/// The same for a fraction of the tank's volume in [0, 1].
LevelSolution level_for_fraction(const FuelIndex& index, Vec3d up, double fraction);

/// Levels for a list of volumes (a volume → level table).
std::vector<LevelSolution> levels_for_volumes(const FuelIndex& index, Vec3d up,
                                              std::span<const double> volumes);

}  // namespace pgamesh::tank
