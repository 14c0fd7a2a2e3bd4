// Reading meshes: STL (ASCII and binary), OBJ, PLY (ASCII, binary little/big endian), OFF and 3MF,
// with the format detected from the content (docs/formats.md). Vertices are kept as given (no
// welding; STL gives three fresh vertices per facet) and faces as polygons (no triangulation). Bad
// input is an InputError naming the file, the line:column or byte offset, and the problem.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh {

// Reads the mesh file at `path` (memory-mapped; "-" reads standard input). `format` forces a
// reader family (unknown = detect from the content). Fills `source` (path, format, precision, OBJ
// group count, warnings about repairs) when given.
Mesh read_mesh(const std::string& path, MeshSource* source = nullptr,
               MeshFormat format = MeshFormat::unknown);

// Reads the mesh of a file the caller has open. When it is a read-only file mapping
// (MappedFile::mapped()) the reader gives the pages it has parsed back to the kernel as it goes
// (madvise MADV_DONTNEED), so that the peak memory is the mesh plus a few MiB of the file; the
// bytes stay readable (the kernel reads them back from the file when touched).
Mesh read_mesh(const MappedFile& file, MeshSource* source = nullptr,
               MeshFormat format = MeshFormat::unknown);

// Reads a mesh from bytes already in memory; `name` is the file name used in errors.
Mesh read_mesh_bytes(std::span<const char> bytes, const std::string& name,
                     MeshSource* source = nullptr, MeshFormat format = MeshFormat::unknown);

// The format of `bytes` by content: 3MF by the zip header "PK\3\4", binary STL by size arithmetic
// (84 + 50 × count == size, even when the header begins with "solid"), "ply" + format line, an OFF
// keyword, "solid" for ASCII STL, OBJ statements; an unrecognised binary file is reported as a
// (broken) binary STL so that its reader explains the size mismatch. unknown for empty or
// unrecognised text.
MeshFormat detect_format(std::span<const char> bytes);

}  // namespace pgamesh
