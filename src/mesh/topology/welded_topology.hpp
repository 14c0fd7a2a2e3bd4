// The topology pass (topology.hpp) on a welded mesh, for faces of any size. Edges are never stored
// as a table: the half-edges are bucketed by their lower end (a counting sort) and each vertex's
// bucket is grouped by the upper end and judged on the spot (edge_group.hpp) — use count,
// direction, union–find of the faces, runs of faces with the same vertices (duplicate_faces.hpp) —
// keeping only the defective edges and the boundary sides. One template walks both face layouts
// (face_layout.hpp): triangles, in arithmetic, and polygons, through their offsets.
#pragma once

#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

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

// The topology report of a welded mesh with faces of any size (weld.hpp: welded.mesh holds the
// representatives' coordinates and the renumbered corners of a mesh that passed
// check_mesh_structure) whose input mesh had its bounding-box centre at `reference`. For a mesh of
// triangles it is analyze_welded_triangles' report, bit for bit. Throws std::invalid_argument for
// a bad option (options.weld_tolerance is ignored: the weld is done).
TopologyReport analyze_welded_mesh(const WeldResult& welded, Vec3d reference,
                                   const TopologyOptions& options = {});

}  // namespace pgamesh
