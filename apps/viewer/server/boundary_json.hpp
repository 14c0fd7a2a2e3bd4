// What `pgamesh check` finds, as the viewer draws and lists it: boundary, non-manifold and
// inconsistently oriented edges as segments, the holes' loops, and the defects' counts, from the
// topology report (mesh/topology.hpp).
#pragma once

#include <string>

#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::viewer {

/// {boundary_edges, segments: [[x0,y0,z0,x1,y1,z1], ...] (at most the report's list cap),
/// loops: [{area, perimeter, vector_area}], gap_area, nonmanifold_edges, nonmanifold_segments,
/// inconsistent_edges, inconsistent_segments, duplicated_faces, zero_area_faces, components,
/// closed_components, cavity_components, inward_components, self_intersecting_pairs,
/// self_intersections_complete, self_intersecting_faces: [[x0,y0,z0, x1,y1,z1, ...], ...] (the
/// faces of the report's listed pairs, each once, as polygons of `mesh`, whose report it is),
/// notes}.
std::string boundary_json(const TopologyReport& topology, const Mesh& mesh);

}  // namespace pgamesh::viewer
