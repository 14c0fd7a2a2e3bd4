// Many levels for one up vector (a gauge table) by a sorted sweep: triangles sorted by their
// lowest and highest vertex; as the level rises a triangle joins the crossing set when its lowest
// vertex is reached and moves into the running sum of whole triangles when its highest is.
// All N levels cost O(T log T + N + Σ crossings) instead of N full passes.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "pgamesh/tank/fuel_state.hpp"
#include "pgamesh/tank/tank.hpp"

namespace pgamesh::tank {

/// The fuel at each level (any order) below the plane up·x = level; up is normalized by
/// unit_up. Equal to fuel_naive at each level up to rounding. `progress`, when given, is called
/// with (levels done, levels) every 1024 levels and at the end.
std::vector<FuelState> fuel_sweep(
    const Tank& tank, Vec3d up, std::span<const double> levels,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

/// N + 1 evenly spaced levels from `lowest` to `highest` (both included exactly), N ≥ 1.
std::vector<double> even_levels(LevelRange range, int n);

}  // namespace pgamesh::tank
