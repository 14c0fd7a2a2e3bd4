// Welding coincident vertices: readers keep vertices as given (an STL has three fresh vertices per
// facet), so every topological question — which faces share an edge, where the boundary is — is
// asked of the welded mesh. Faces are never dropped or reordered by a weld; a face whose corners
// collapse onto one vertex stays and is reported as degenerate by the topology pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

// Which input vertex became which welded vertex. Welded vertices are numbered in the order of the
// first input vertex of each class, and each class is represented by that first (lowest-index)
// input vertex, so the result does not depend on hashing or thread count.
struct WeldMap {
  std::vector<std::uint32_t> to_welded;       // input vertex index → welded vertex index
  std::vector<std::uint32_t> representative;  // welded vertex index → its lowest input index
  std::size_t merged = 0;  // input vertices merged into an earlier one (input − welded count)
  double max_moved = 0;    // largest distance from a merged vertex to its representative
  double tolerance = 0;    // the tolerance used (0 = exact)

  std::size_t welded_count() const { return representative.size(); }
};

// Welds `vertices`. tolerance == 0: vertices merge when their coordinates are bitwise equal, with
// −0 treated as +0 (a hash table over the coordinate bits, one pass, no per-vertex allocation).
// tolerance > 0: greedy leader clustering in input order on a grid of cell size `tolerance` — a
// vertex joins the earliest representative within Euclidean distance ≤ tolerance, else it starts
// a new class; merged vertices move at most `tolerance` (reported as max_moved), and a chain of
// vertices each within tolerance of the next does not collapse into one. Throws
// std::invalid_argument for a negative or non-finite tolerance and std::length_error for more than
// 2³² − 1 vertices.
WeldMap weld_map(std::span<const Vec3d> vertices, double tolerance = 0);

// weld_map, leaving `vertices` replaced by the welded positions (vertex i = the coordinates of
// representative i). The exact weld keeps its hash keys in the array itself, compacting it as the
// classes appear, so it needs no second array of coordinates (the peak of welding a large mesh).
// Same results and exceptions as weld_map.
WeldMap weld_map_compacting(std::vector<Vec3d>& vertices, double tolerance = 0);

// A welded mesh: the representatives' coordinates as vertices, corners renumbered, faces unchanged
// in number and order.
struct WeldResult {
  Mesh mesh;
  WeldMap map;
};

// Welds the vertices of `mesh` (see weld_map) and renumbers its corners. Throws
// std::out_of_range for a corner index beyond the vertex list, and weld_map's exceptions.
WeldResult weld(const Mesh& mesh, double tolerance = 0);

// The same weld of a mesh the caller no longer needs, in its own arrays: the vertices compacted by
// weld_map_compacting and the corners renumbered in place, so no second copy of either exists. The
// mesh is left empty. Same results and exceptions as above.
WeldResult weld(Mesh&& mesh, double tolerance = 0);

}  // namespace pgamesh
