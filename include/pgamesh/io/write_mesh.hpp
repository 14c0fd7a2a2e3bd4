// Writing meshes in every format the readers accept. Text formats print each double with the
// shortest representation that reads back to the same bits (std::to_chars, equivalent to %.17g
// for round trips), so text round trips are bit-exact; binary STL is float32 by definition.
#pragma once

#include <string>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

struct WriteOptions {
  // PLY: store coordinates as float32 instead of float64 (text formats always keep full doubles).
  bool single_precision = false;
  // STL: the solid name (ASCII) / header text (binary, truncated to 80 bytes).
  std::string solid_name = "pgamesh";
  // Formats that state a unit (3MF; glTF is metres by definition): the unit the coordinates are
  // in. Coordinates are written as they are, never scaled.
  LengthUnit unit = LengthUnit::unspecified;
};

// The bytes of `mesh` in `format` (stl_ascii, stl_binary, obj, ply_ascii, ply_binary_le,
// ply_binary_be, off, gltf, glb, slp, threemf). STL, SLP, glTF and 3MF hold triangles only: a
// polygon with n > 3 corners is written as the fan (v0, vi, vi+1), which keeps its vector area and
// the signed volume it bounds exactly. glTF (a .gltf text with its buffer in a base64 data: URI,
// or a .glb) stores float32 positions, as binary STL does; its unit is the metre by definition, so
// `mesh` must be in metres (pgamesh convert rescales). SLP is written as ASCII STL text (no
// colours). 3MF is a zip package of one object and one build item, in options.unit (millimeter,
// the 3MF default, when unspecified). Throws std::invalid_argument for MeshFormat::unknown, corner
// indices outside the vertex array, and (3MF) a triangle that repeats a vertex.
std::string write_mesh_bytes(const Mesh& mesh, MeshFormat format, const WriteOptions& options = {});

// Writes write_mesh_bytes(mesh, format, options) to `path` atomically (write_file_atomically:
// the old file or the whole new one, never a truncated one); throws std::runtime_error naming the
// path when it cannot be written.
void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const WriteOptions& options = {});

}  // namespace pgamesh
