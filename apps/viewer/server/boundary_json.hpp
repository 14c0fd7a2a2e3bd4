// The boundary of an open mesh as the viewer draws it: its edges as segments and its holes'
// loops, from the topology report (mesh/topology.hpp).
#pragma once

#include <string>

#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::viewer {

/// {boundary_edges, segments: [[x0,y0,z0,x1,y1,z1], ...] (at most the report's list cap),
/// loops: [{area, perimeter, vector_area}], gap_area} for drawing the holes of an open mesh.
std::string boundary_json(const TopologyReport& topology);

}  // namespace pgamesh::viewer
