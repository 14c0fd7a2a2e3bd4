// Mass properties and topology of a binary PLY triangle mesh without its face list. A Mesh, or
// even the welded triangles of welded_triangles.hpp, would hold 12 bytes of corners per triangle
// — nearly the 13 bytes the file spends on each face — on top of the vertices, a union–find and
// the edge pass's buckets. This pass keeps the welded vertices (float32 or float64, as the file
// gives them), one union–find entry per face and the half-edges of one range of lower-end vertices
// at a time, and re-reads the faces from the (mapped) file: once for the face sums, then once per
// range of vertices for the edges (docs/topology.md).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "mesh/topology/welded_topology.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh {

// Half-edges per range of the edge pass: 0 = from the file's size (a twelfth of it for their
// records), or the number a caller gives (a test forces many passes on a small mesh).
struct PlyPassBudget {
  std::size_t half_edges = 0;
};

// The mass properties and topology report of the binary PLY file in `bytes`: the same figures,
// bit for bit, as reading it with read_mesh_bytes() and calling mass_properties(mesh, mass_options,
// &source) and analyze_topology(mesh, topology_options), and the same `source`. Returns nullopt
// when this pass declines the file, and then the caller reads it the careful way (which also gives
// the exact error of a malformed file): an ASCII file; a vertex element with lists or coordinates
// that are not all float32 or all float64; other elements with data; faces before vertices; a face
// element with other lists; no faces; a face that is not a triangle; an index out of range; data
// shorter than declared; a non-finite coordinate; a vertex that welds to one whose bits differ (−0
// and +0); topology_options.weld_tolerance ≠ 0. Throws InputError for a malformed header and
// std::invalid_argument for a bad option, as the careful path does. With `release_pages` (bytes
// of a read-only file mapping) the pages read are given back to the kernel behind each pass.
std::optional<WeldedTriangleProps> ply_triangle_props(std::span<const char> bytes,
                                                      const std::string& name, MeshSource& source,
                                                      const MassOptions& mass_options = {},
                                                      const TopologyOptions& topology_options = {},
                                                      bool release_pages = false,
                                                      PlyPassBudget budget = {});

}  // namespace pgamesh
