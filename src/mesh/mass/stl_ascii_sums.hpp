// The mass properties of an ASCII STL without building a Mesh (`props --no-topology`): the reader's
// own grammar (io/stl_ascii_grammar.hpp) hands the facets of each piece of the text to a summing
// consumer, on every core, which adds each facet to its sums as it is read and keeps nothing else.
// The reference point is the centre of a sample of the vertex lines, known before the parse, as the
// binary STL's streamed sums take it (docs/conventions.md §13). The counts, warnings and errors are
// the reader's; the figures are mass_properties() of the mesh it reads up to rounding (bit for bit
// when the text is one piece and the sample meets every vertex line), the same bits on any thread
// count.
#pragma once

#include <span>
#include <string>

#include "io/stl_ascii_grammar.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

// The mass properties of the facets of `bytes`, which read_mesh_bytes() reads as ASCII STL
// (detect_format(bytes) == MeshFormat::stl_ascii), accumulated about the centre of
// stl_ascii_sampled_box (MassProperties::reference_point): faces, triangles and vertices as the
// reader counts them, and its source fields (format, warnings). Each piece of the text is summed
// in chunks of its own (chunked_sums.hpp), the pieces in file order. Throws the reader's
// InputError — message and position — for what it rejects, std::invalid_argument for a
// non-finite density or mass. With `release_pages` — only for the bytes of a read-only file
// mapping, as in read_mesh_bytes() — the pages are given back to the kernel as they are parsed.
// `piece_bytes` is the size of the pieces the text is cut into (tests make it small).
MassProperties ascii_stl_mass_properties(std::span<const char> bytes, const std::string& name,
                                         MeshSource& source, const MassOptions& options = {},
                                         bool release_pages = false,
                                         std::size_t piece_bytes = detail::stl_ascii_piece_bytes);

}  // namespace pgamesh
