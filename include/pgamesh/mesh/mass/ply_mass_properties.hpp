// Mass properties of a PLY file without its face list: the vertices are read as read_mesh_bytes()
// reads them, and each face is summed as it is parsed (face_sums.hpp, in the fixed chunks of
// chunked_sums.hpp), so the file's figures come in the memory of its vertices alone. For a binary
// PLY of float vertices and uchar/int faces — 6 bytes of vertices and 13 of faces per triangle —
// the face list of a Mesh (16 bytes per triangle) would be larger than the whole file.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

namespace pgamesh {

// The mass properties of the PLY file (ASCII, binary little- or big-endian) in `bytes`: the same
// figures, bit for bit, as mass_properties(read_mesh_bytes(bytes, name, &source), options,
// &source), and the same `source` (format, float32 precision, warnings of ignored elements).
// Returns nullopt, having read none of the data, when the face element comes before the vertex
// element (the faces could not be summed as they are read): read the file with read_mesh_bytes().
// Throws the InputError of the PLY reader for malformed data (read_mesh_bytes() may say more, as
// for an empty file: a caller that wants its exact error reads the file again with it). With
// `release_pages` (bytes of a read-only file mapping only, as in read_mesh_bytes) the pages read
// are given back to the kernel as the reader passes them.
std::optional<MassProperties> ply_mass_properties(std::span<const char> bytes,
                                                  const std::string& name, MeshSource& source,
                                                  const MassOptions& options = {},
                                                  bool release_pages = false);

}  // namespace pgamesh
