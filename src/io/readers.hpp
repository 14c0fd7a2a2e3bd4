// Internal: one parser per format family, called by read_mesh_bytes() after detection. Each fills
// an empty Mesh and the MeshSource fields it knows (format, precision, groups, warnings). With
// `release_pages` (bytes of a read-only file mapping only) each gives the pages it has passed back
// to the kernel as it goes (page_release.hpp).
#pragma once

#include <optional>
#include <span>
#include <string>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh::detail {

// read_mesh_bytes (read_mesh.hpp), releasing the pages it has parsed when `release_pages` (the
// bytes of a read-only file mapping only): what read_mesh(MappedFile) and the front door call.
// `name_is_path`: `name` is the path of the file the bytes are (a glTF's external buffers are read
// from its folder).
Mesh read_mesh_bytes(std::span<const char> bytes, const std::string& name, MeshSource* source,
                     MeshFormat format, bool release_pages, bool name_is_path = false);

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
// A 3MF package (zip): the whole build, one MeshPart per build item, the unit in `source`.
void read_3mf(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source);
// glTF 2.0 (.gltf JSON or .glb). With `external_files`, `name` is the file's path and buffers in
// files beside it are read (relative URIs that stay inside its folder); without, only data: URIs
// and the GLB binary chunk.
void read_gltf(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
               bool external_files);

// Where a GLB holds its triangles when they can be streamed as records (packed_triangle_layout of
// io/stl_binary.hpp) instead of read into a Mesh: its scene is one node (its world transform
// moving no point) instancing one mesh of one primitive, a non-indexed triangle list (mode 4)
// whose POSITION accessor is float32 VEC3, neither sparse nor normalized, tightly packed
// (byteStride absent or 12) in the GLB's own binary chunk, a multiple of 3 elements.
struct GlbTriangleList {
  std::uint64_t offset = 0;  // of the first coordinate, in the file
  std::uint64_t triangles = 0;
  std::string part_name;  // the MeshPart's name read_gltf gives the node
};

// The triangle list of such a GLB, found by the reader's own parse and checks (the accessor
// inside its bufferView, the bufferView inside its buffer, the buffer inside the chunk), or
// nullopt for any other bytes, a malformed or hostile file included: read_gltf reports those.
std::optional<GlbTriangleList> glb_triangle_list(std::span<const char> bytes,
                                                 const std::string& name);

// The boundary sums of a PLY file's faces about `reference` (reference_point of its vertices),
// accumulated as mesh_boundary_sums accumulates them, and the face counts.
struct PlyFaceSums {
  BoundarySums sums;
  Vec3d reference{};
  std::uint64_t faces = 0, triangles = 0;  // as mass_properties() counts them
};

// read_ply without keeping the faces: the vertices are read into `mesh` (its face list stays
// empty) and each face is summed as it is parsed. The same errors and source fields as read_ply.
// Returns nullopt, having read no data, when the face element comes before the vertex element.
std::optional<PlyFaceSums> read_ply_summing_faces(std::span<const char> bytes,
                                                  const std::string& name, Mesh& mesh,
                                                  MeshSource& source, bool release_pages = false);

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
