// Internal: one parser per format family, called by read_mesh_bytes() after detection. Each fills
// an empty Mesh and the MeshSource fields it knows (format, precision, groups, warnings). With
// `release_pages` (bytes of a read-only file mapping only) each gives the pages it has passed back
// to the kernel as it goes (page_release.hpp).
#pragma once

#include <span>
#include <string>

#include "pgamesh/mesh/mesh.hpp"

namespace pgamesh::detail {

void read_stl_binary(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                     MeshSource& source, bool release_pages = false);
void read_stl_ascii(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                    MeshSource& source, bool release_pages = false);
void read_obj(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages = false);
void read_ply(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages = false);
void read_off(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages = false);

// A vertex count that fits the 32-bit corner indices of Mesh, or an error at `where`.
inline constexpr std::uint64_t max_vertices = 0xFFFFFFFFull;

// How many elements to reserve for a declared `count` when each element needs at least
// `min_bytes` of the `remaining` input: a declared count is never trusted for allocation before
// the data could hold it.
inline std::size_t bounded_reserve(std::uint64_t count, std::size_t remaining,
                                   std::size_t min_bytes) {
  const std::uint64_t cap = remaining / (min_bytes ? min_bytes : 1);
  return static_cast<std::size_t>(count < cap ? count : cap);
}

}  // namespace pgamesh::detail
