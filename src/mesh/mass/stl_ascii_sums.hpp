// The mass properties of an ASCII STL without building a Mesh (`props --no-topology`): the reader's
// own grammar (io/stl_ascii_grammar.hpp) hands the facets of each piece of the text to a summing
// consumer, on every core. The figures are mass_properties() of the mesh read_mesh_bytes() reads,
// bit for bit on any thread count, and so are the counts, the warnings and the errors.
#pragma once

#include <span>
#include <string>

#include "io/stl_ascii_grammar.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

// mass_properties(read_mesh_bytes(bytes, name, &source), options, &source) for bytes that
// read_mesh_bytes() reads as ASCII STL (detect_format(bytes) == MeshFormat::stl_ascii): the same
// MassProperties bit for bit and the same source fields (format, warnings). Throws the reader's
// InputError — message and position — for what it rejects, std::invalid_argument for a
// non-finite density or mass. With `release_pages` — only for the bytes of a read-only file
// mapping, as in read_mesh_bytes() — the pages are given back to the kernel as they are parsed.
// `piece_bytes` is the size of the pieces the text is cut into (tests make it small): 4 MiB by
// default, larger than the mesh reader's, so that each piece's vertices fill whole huge pages.
MassProperties ascii_stl_mass_properties(std::span<const char> bytes, const std::string& name,
                                         MeshSource& source, const MassOptions& options = {},
                                         bool release_pages = false,
                                         std::size_t piece_bytes = std::size_t{1} << 22);

}  // namespace pgamesh
