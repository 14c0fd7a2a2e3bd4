// The fused fast path for ASCII STL: mass properties accumulated while the mapped text is parsed,
// on every core, without building a Mesh (DESIGN.md §6). The file is cut into pieces of a fixed
// size at `facet` lines, each piece is parsed and summed on its own, and the piece sums are added
// in file order, so the result does not depend on the thread count.
//
// The fast path reads only the plain form nearly every exporter writes (triangular facets, the
// keywords in any letter case, numbers as std::from_chars reads them, several solids in a row).
// Anything else — a polygon facet, a syntax error, a NaN — makes it decline, and the caller reads
// the file with read_mesh_bytes(), whose careful parser keeps polygons and reports errors with
// their line:column. Both give the same figures (to rounding: the accumulation order differs).
#pragma once

#include <optional>
#include <span>
#include <string>

#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

// Bytes of text per piece: large enough that a piece costs far more than handing it out, small
// enough that two threads share a file of a few MB evenly. Pieces start at a `facet` line.
inline constexpr std::size_t stl_ascii_piece_bytes = std::size_t{1} << 19;

// Mass properties of the ASCII STL in `bytes`, parsed and accumulated in one pass about the centre
// of a sample of its vertices (of every vertex when the file is at most one piece). Fills faces =
// triangles = facets and vertices = 3 × facets; adds the reader's "missing 'endsolid'" warning
// (with `name`) when the last solid is not closed. Returns nullopt when the bytes are not an ASCII
// STL of plain triangular facets (see above), or not detected as ASCII STL by detect_format(): read
// them with read_mesh_bytes() instead. Never throws for bad input; std::invalid_argument for a
// non-finite density or mass, as mass_properties_from_sums(). With `release_pages` — only for the
// bytes of a read-only file mapping, as in read_mesh_bytes() — each piece's pages are given back
// to the kernel once it is summed (a declined file is then read again from the page cache).
std::optional<MassProperties> ascii_stl_mass_properties(std::span<const char> bytes,
                                                        const std::string& name,
                                                        const MassOptions& options = {},
                                                        bool release_pages = false);

}  // namespace pgamesh
