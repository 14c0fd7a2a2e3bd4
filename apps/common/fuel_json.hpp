// The fuel figures as JSON and CSV, shared by `pgamesh fuel` and the viewer server so that both
// speak the same fields (DESIGN.md §5; docs/fuel.md lists them with their units).
#pragma once

#include <string>

#include "json_writer.hpp"
#include "pgamesh/tank/fuel_state.hpp"

namespace pgamesh::cli {

/// Writes the fields of one fuel state into the current JSON object: level, volume, fraction,
/// center_of_mass, inertia_com, wetted_area, surface_area, the free-surface centroid, axes and
/// second moments of area, ullage_volume and ullage_length (= highest − level); mass = density ×
/// volume, and the inertia scaled by the density.
void write_fuel_state(JsonWriter& w, const tank::FuelState& st, const tank::LevelRange& range,
                      double density = 1);

/// Writes the "conventions" object: the plane, the side counted as fuel, the inertia sign rule,
/// the free-surface axes and the units.
void write_fuel_conventions(JsonWriter& w);

/// The CSV column names (one line, no newline); `attitude` prepends pitch_deg,roll_deg.
std::string fuel_csv_columns(bool attitude);

/// One CSV row for a state (no newline), numbers with %.17g; the last column is the mass =
/// density × volume.
std::string fuel_csv_row(const tank::FuelState& st, const tank::LevelRange& range, bool attitude,
                         double pitch_deg, double roll_deg, double density = 1);

}  // namespace pgamesh::cli
