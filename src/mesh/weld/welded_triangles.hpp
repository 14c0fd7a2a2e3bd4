// A welded triangle mesh in its leanest form: the welded vertices' coordinates and three welded
// vertex indices per triangle. It is what the topology pass on triangles (welded_topology.hpp)
// reads, and a binary STL is welded into it straight from its float32 records, without building a
// Mesh of three fresh double vertices per facet first (4× smaller, and the file's pages can be
// released as the weld passes them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/stl_binary.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

struct WeldedTriangles {
  std::vector<Vec3d> positions;  // welded vertex → its representative's coordinates
  // Welded vertex → its lowest input vertex index; left empty by weld_triangles when the weld
  // merged nothing (then it is the identity, and an array as long as the positions would only
  // cost memory at the topology pass's peak): read it through input_vertex().
  std::vector<std::uint32_t> representative;
  std::vector<std::uint32_t> corners;  // three welded vertex indices per triangle
  std::size_t input_vertices = 0;      // vertices before the weld
  std::size_t merged = 0;              // input − welded vertices
  double max_moved = 0;                // as in WeldMap
  double tolerance = 0;

  std::size_t triangle_count() const { return corners.size() / 3; }
  // The lowest input vertex that welded vertex w stands for.
  std::uint32_t input_vertex(std::uint32_t w) const {
    return representative.empty() ? w : representative[w];
  }
};

// Whether every face of `mesh` is a triangle (and there is at least one face).
bool all_triangles(const Mesh& mesh);

// Welds a mesh whose faces are all triangles (weld_map of weld.hpp, same numbering; the
// representatives left empty when nothing merged). Throws
// std::invalid_argument when a face is not a triangle and std::out_of_range for a corner index
// beyond the vertex list.
WeldedTriangles weld_triangles(const Mesh& mesh, double tolerance = 0);

// The same weld of a mesh the caller no longer needs, built in its arrays: the corners are
// renumbered in place and the positions compacted in place, so the weld needs no second copy of
// either (the mesh is left empty). Same results and exceptions as above.
WeldedTriangles weld_triangles(Mesh&& mesh, double tolerance = 0);

// Welds the records of a binary STL (or of another array of float32 triangle records,
// BinaryStlView::layout: a GLB's packed positions) exactly: input vertex 3 i + k is vertex k of
// record i (the numbering read_mesh gives), and vertices merge when their float32 bit patterns are
// equal, −0 folded to +0 — the same classes, numbering and representatives as weld_map on the read
// mesh. With `release_records`, the pages of records already welded are returned to the kernel as
// the pass goes (madvise MADV_DONTNEED; only for a read-only file mapping, whose pages are re-read
// from the file if touched again); a view that reads its file (BinaryStlView::file) touches no
// mapped page and releases none. Throws InputError naming `name` for a non-finite coordinate
// (check_binary_stl_finite) or more vertices than 32-bit indices can hold.
WeldedTriangles weld_binary_stl(const BinaryStlView& view, const std::string& name,
                                bool release_records = false);

// Mass properties of the welded triangles about `reference`, accumulated exactly as
// mass_properties() accumulates the unwelded mesh (same faces, same coordinates, same chunking):
// the figures are the same bit for bit. faces = triangles, vertices = input_vertices; with
// `single_precision`, the float32 far-from-origin warning when it applies.
MassProperties mass_properties(const WeldedTriangles& mesh, Vec3d reference,
                               const MassOptions& options, bool single_precision);

// The mass properties of the welded triangles from their sums about `reference` (as
// mass_properties above accumulates them; for a pass that accumulates them along with other
// work): counts and the float32 warning as above.
MassProperties mass_properties_from_welded_sums(const WeldedTriangles& mesh,
                                                const BoundarySums& sums, Vec3d reference,
                                                const MassOptions& options, bool single_precision);

}  // namespace pgamesh
