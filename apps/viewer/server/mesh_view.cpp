#include "mesh_view.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh::viewer {

namespace {

std::size_t fan_triangle_count(const Mesh& mesh) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) >= 3) n += mesh.face_size(f) - 2;
  return n;
}

template <class T>
void append_le(std::string& out, T value) {
  static_assert(std::endian::native == std::endian::little, "the page reads little-endian data");
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

Bounds face_vertex_bounds(const Mesh& mesh) {
  if (mesh.corners.empty()) return {};
  Bounds b{mesh.vertices[mesh.corners[0]], mesh.vertices[mesh.corners[0]]};
  for (const std::uint32_t i : mesh.corners) {
    const Vec3d& v = mesh.vertices[i];
    b.min = {std::min(b.min.x, v.x), std::min(b.min.y, v.y), std::min(b.min.z, v.z)};
    b.max = {std::max(b.max.x, v.x), std::max(b.max.y, v.y), std::max(b.max.z, v.z)};
  }
  return b;
}

Vec3d drawing_origin(const Mesh& mesh) {
  const Bounds b = face_vertex_bounds(mesh);
  return (b.min + b.max) * 0.5;
}

nlohmann::json mesh_summary_json(const StoredMesh& stored) {
  const Mesh& m = stored.mesh;
  const Bounds b = face_vertex_bounds(m);
  const Vec3d o = drawing_origin(m);
  return {
      {"id", stored.id},
      {"name", stored.name},
      {"format", format_name(stored.source.format)},
      {"single_precision", stored.source.single_precision},
      {"vertices", m.vertices.size()},
      {"faces", m.face_count()},
      {"triangles", fan_triangle_count(m)},
      {"bounds", {{"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}}},
      {"drawing_origin", {o.x, o.y, o.z}},
      {"weld_tolerance", stored.weld_tolerance},
      {"warnings", stored.source.warnings},
  };
}

std::string mesh_geometry_binary(const Mesh& mesh) {
  const Vec3d o = drawing_origin(mesh);
  const std::size_t triangles = fan_triangle_count(mesh);
  std::string out;
  out.reserve(8 + 12 * mesh.vertices.size() + 12 * triangles);
  append_le(out, static_cast<std::uint32_t>(mesh.vertices.size()));
  append_le(out, static_cast<std::uint32_t>(triangles));
  for (const Vec3d& v : mesh.vertices) {
    append_le(out, static_cast<float>(v.x - o.x));
    append_le(out, static_cast<float>(v.y - o.y));
    append_le(out, static_cast<float>(v.z - o.z));
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    for (std::size_t k = 1; k + 1 < mesh.face_size(f); ++k) {
      append_le(out, c[0]);
      append_le(out, c[k]);
      append_le(out, c[k + 1]);
    }
  }
  return out;
}

}  // namespace pgamesh::viewer
