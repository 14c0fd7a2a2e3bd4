// The topology pass for triangle meshes, on a welded triangle list (welded_triangles.hpp): the
// same report as analyze_polygon_topology (topology.hpp), in fewer passes and less memory. Edges
// are never stored as a table: the half-edges are bucketed by their lower end (a counting sort)
// and each vertex's bucket is grouped by the upper end and judged on the spot — use count,
// direction, union–find of the faces, duplicated faces (two triangles on one edge with the same
// third vertex) — keeping only the defective edges and the boundary sides.
#pragma once

#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh {

// The topology report of welded triangles whose input mesh had its bounding-box centre at
// `reference` (reference_point.hpp): the point the sums are accumulated about. Throws
// std::invalid_argument for a bad option (options.weld_tolerance is ignored: the weld is done).
TopologyReport analyze_welded_triangles(const WeldedTriangles& mesh, Vec3d reference,
                                        const TopologyOptions& options = {});

// Mass properties and topology report of welded triangles, from one pass over the triangles that
// forms each carrier once for both: the same figures, bit for bit, as
// mass_properties(mesh, reference, mass_options, single_precision) and
// analyze_welded_triangles(mesh, reference, topology_options). Throws std::invalid_argument for a
// bad option.
struct WeldedTriangleProps {
  MassProperties mass;
  TopologyReport topology;
};
WeldedTriangleProps analyze_welded_triangles(const WeldedTriangles& mesh, Vec3d reference,
                                             const MassOptions& mass_options,
                                             const TopologyOptions& topology_options,
                                             bool single_precision);

}  // namespace pgamesh
