// Internal: the glTF 2.0 writer of write_mesh_bytes (write_gltf.cpp).
#pragma once

#include <string>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh::detail {

// `mesh` as one glTF 2.0 mesh of triangles (polygons as fans (v0, vi, vi+1)) under one node:
// positions float32 with their min/max, indices uint32 (none for a triangle soup whose corners are
// its vertices in order, which glTF writes without indices); a .gltf JSON text with the buffer in a
// base64 data: URI, or (`binary`) a .glb container. Throws std::invalid_argument for a coordinate
// that float32 cannot hold (beyond ±3.4e38, or not finite).
std::string write_gltf(const Mesh& mesh, bool binary);

}  // namespace pgamesh::detail
