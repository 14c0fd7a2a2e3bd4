// What the page needs to draw a mesh: a JSON summary (counts, bounds, format, reader warnings) and
// the triangles in a compact binary form. Polygons are split into fans for drawing only; every
// measurement is made by the library on the polygons as read.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "mesh_store.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::viewer {

struct Bounds {
  Vec3d min, max;
};

/// Axis-aligned bounds of the vertices that faces use (zero box for a mesh without faces).
Bounds face_vertex_bounds(const Mesh& mesh);

/// The point the page draws about: the centre of the bounds. Coordinates go to the page relative to
/// it, so float32 keeps its precision for meshes far from the origin (docs/conventions.md §13).
Vec3d drawing_origin(const Mesh& mesh);

/// {id, name, format, single_precision, vertices, faces, triangles, bounds{min,max},
/// drawing_origin, warnings}.
nlohmann::json mesh_summary_json(const StoredMesh& stored);

/// Little-endian binary: uint32 vertex count V, uint32 triangle count T, float32[3V] positions
/// relative to drawing_origin(mesh), uint32[3T] vertex indices (polygons as fans).
std::string mesh_geometry_binary(const Mesh& mesh);

}  // namespace pgamesh::viewer
