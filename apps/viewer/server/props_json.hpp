// The viewer's JSON for mass properties, in the field names of `pgamesh props --json`
// (DESIGN.md §5), written with the CLI's JsonWriter (%.17g numbers, null for NaN).
#pragma once

#include <string>

#include "pgamesh/mesh/mass_properties.hpp"

namespace pgamesh::viewer {

/// {triangles, faces, vertices, area, volume, density, mass, center_of_mass, inertia_com,
/// inertia_origin, products_of_inertia_com, principal_moments, principal_axes (row i = axis of
/// moment i), principal_degenerate, gap_area, inertia_convention, warnings}.
std::string props_json(const MassProperties& p);

}  // namespace pgamesh::viewer
