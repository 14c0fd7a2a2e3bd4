// Many levels for one up vector (a gauge table) by a sweep over the sorted levels: each vertex is
// ranked among the levels (binary search), each triangle bucketed by the ranks of its corners.
// As the level rises a triangle joins the crossing set at the rank of its lowest corner, its
// whole sums join a running sum at the rank of its middle corner (from there on the fuel holds
// the triangle minus the small piece at its one dry corner, paper §4d), and it leaves the
// crossing set at the rank of its highest corner. A level then costs one small tetrahedron and
// one free-surface segment per crossing triangle, plus a constant for the cone over the free
// surface (cone_over_surface): all N levels in O(T log N + N log N + Σ crossings) instead of N
// full passes.
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
