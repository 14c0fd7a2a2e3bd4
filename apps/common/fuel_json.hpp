// The fuel figures as JSON and CSV, shared by `pgamesh fuel` and the viewer server so that both
// speak the same fields (docs/fuel.md lists them with their units).
#pragma once

#include <string>

#include "json_text.hpp"
#include "pgamesh/tank/fuel_state.hpp"

namespace pgamesh::cli {

/// Adds the fields of one fuel state to the JSON object `out`: level, volume, fraction,
/// center_of_mass, inertia_com, wetted_area, surface_area, the free-surface centroid, axes and
/// second moments of area, ullage_volume and ullage_length (= highest − level); mass = density ×
/// volume, and the inertia scaled by the density.
void write_fuel_state(Json& out, const tank::FuelState& st, const tank::LevelRange& range,
                      double density = 1);

/// The "conventions" object: the plane, the side counted as fuel, the inertia sign rule, the
/// free-surface axes and the units.
Json fuel_conventions();

/// The CSV column names (one line, no newline); `attitude` prepends pitch_deg,roll_deg.
std::string fuel_csv_columns(bool attitude);

/// One CSV row for a state (no newline), numbers with %.17g; the last column is the mass =
/// density × volume.
std::string fuel_csv_row(const tank::FuelState& st, const tank::LevelRange& range, bool attitude,
                         double pitch_deg, double roll_deg, double density = 1);

}  // namespace pgamesh::cli
