// The mesh file formats by name and extension — the one place they are named: as printed in
// outputs, as accepted by --format, and as told by a file's extension.
#pragma once

#include <string_view>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

// The name printed in outputs: "stl-ascii", "stl-binary", "obj", "ply-ascii",
// "ply-binary-little-endian", "ply-binary-big-endian", "off", "gltf", "glb", "slp", "3mf" (or
// "unknown").
const char* format_name(MeshFormat f);

// The format a name stands for, in any letter case: the names above, the families "stl" (binary),
// "ply" (ASCII), and the short forms "ply-le", "ply-be", "stl_binary", … ; unknown otherwise
// ("auto" included). Given to a reader as --format, a format picks the reader family: ASCII vs
// binary STL is still decided by size arithmetic, and a PLY's own header states its encoding.
MeshFormat format_from_name(std::string_view name);

// The family of the file's extension (.stl, .obj, .ply, .off, .gltf, .glb, .slp, .3mf in any
// letter case), written in `preferred` when that is of the same family, else in the family's
// binary (or only) encoding; unknown for any other extension.
MeshFormat format_for_extension(std::string_view path, MeshFormat preferred = MeshFormat::unknown);

// Whether the file's extension names a format pgamesh reads.
inline bool has_mesh_extension(std::string_view path) {
  return format_for_extension(path) != MeshFormat::unknown;
}

}  // namespace pgamesh
