// The viewer's JSON for mass properties, in the field names of `pgamesh props --json`
// (DESIGN.md §5), written with the CLI's JsonWriter (%.17g numbers, null for NaN).
#pragma once

#include <string>

#include "pgamesh/mesh/mass_properties.hpp"
#include "pgamesh/mesh/topology.hpp"

namespace pgamesh::viewer {

/// {triangles, faces, vertices, area, volume, density, mass, center_of_mass, inertia_com,
/// inertia_origin, products_of_inertia_com, principal_moments, principal_axes (row i = axis of
/// moment i), principal_degenerate, gap_area, inertia_convention, warnings}, and with a topology
/// report also closed, boundary_edges, nonmanifold_edges, orientation_consistent, volume_valid and
/// its notes.
std::string props_json(const MassProperties& p, const TopologyReport* topology = nullptr);

/// {boundary_edges, segments: [[x0,y0,z0,x1,y1,z1], ...] (at most the report's list cap),
/// loops: [{area, perimeter, vector_area}], gap_area} for drawing the holes of an open mesh.
std::string boundary_json(const TopologyReport& topology);

}  // namespace pgamesh::viewer
