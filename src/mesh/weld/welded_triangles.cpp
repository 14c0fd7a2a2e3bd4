#include "mesh/weld/welded_triangles.hpp"

#include <stdexcept>
#include <string>

#include "detail/memory/huge_pages.hpp"
#include "geometry/chunked_sums.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh {

bool all_triangles(const Mesh& mesh) {
  const std::size_t n = mesh.face_count();
  if (n == 0 || mesh.corners.size() != 3 * n) return false;
  for (std::size_t f = 0; f < n; ++f)
    if (mesh.face_offsets[f + 1] - mesh.face_offsets[f] != 3) return false;
  return true;
}

namespace {

void check_triangles(const Mesh& mesh) {
  if (!all_triangles(mesh)) throw std::invalid_argument("weld_triangles: a face is not a triangle");
  for (std::uint32_t c : mesh.corners)
    if (c >= mesh.vertices.size())
      throw std::out_of_range("weld: corner index " + std::to_string(c) + " out of range (" +
                              std::to_string(mesh.vertices.size()) + " vertices)");
}

}  // namespace

WeldedTriangles weld_triangles(const Mesh& mesh, double tolerance) {
  check_triangles(mesh);
  WeldMap map = weld_map(mesh.vertices, tolerance);
  WeldedTriangles w;
  w.input_vertices = mesh.vertices.size();
  w.merged = map.merged;
  w.max_moved = map.max_moved;
  w.tolerance = map.tolerance;
  detail::reserve_huge(w.positions, map.welded_count());
  w.positions.resize(map.welded_count());
  for (std::size_t i = 0; i < w.positions.size(); ++i)
    w.positions[i] = mesh.vertices[map.representative[i]];
  detail::reserve_huge(w.corners, mesh.corners.size());
  w.corners.resize(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    w.corners[c] = map.to_welded[mesh.corners[c]];
  if (map.merged != 0) w.representative = std::move(map.representative);
  return w;
}

WeldedTriangles weld_triangles(Mesh&& mesh, double tolerance) {
  check_triangles(mesh);
  std::vector<std::uint32_t>().swap(mesh.face_offsets);  // all triangles: the offsets say nothing
  WeldedTriangles w;
  w.input_vertices = mesh.vertices.size();
  WeldMap map = weld_map_compacting(mesh.vertices, tolerance);  // positions in place
  w.merged = map.merged;
  w.max_moved = map.max_moved;
  w.tolerance = map.tolerance;
  for (std::uint32_t& c : mesh.corners) c = map.to_welded[c];  // corners renumbered in place
  std::vector<std::uint32_t>().swap(map.to_welded);
  w.corners = std::move(mesh.corners);
  w.positions = std::move(mesh.vertices);
  if (map.merged != 0) w.representative = std::move(map.representative);
  map = WeldMap{};
  mesh = Mesh{};
  return w;
}

MassProperties mass_properties(const WeldedTriangles& mesh, Vec3d reference,
                               const MassOptions& options, bool single_precision) {
  const Vec3d* p = mesh.positions.data();
  const std::uint32_t* c = mesh.corners.data();
  // The triangle case of mesh_boundary_sums, on the welded coordinates (equal to the input ones).
  const BoundarySums sums =
      chunked_sums(mesh.triangle_count(), options.threads,
                   [&](LanedSums<>& s, std::size_t begin, std::size_t end) {
                     for (std::size_t t = begin; t < end; ++t)
                       add_triangle(s[t], p[c[3 * t]] - reference, p[c[3 * t + 1]] - reference,
                                    p[c[3 * t + 2]] - reference);
                   });
  return mass_properties_from_welded_sums(mesh, sums, reference, options, single_precision);
}

MassProperties mass_properties_from_welded_sums(const WeldedTriangles& mesh,
                                                const BoundarySums& sums, Vec3d reference,
                                                const MassOptions& options, bool single_precision) {
  MassProperties m = mass_properties_from_sums(sums, reference, options);
  m.faces = m.triangles = mesh.triangle_count();
  m.vertices = mesh.input_vertices;
  if (single_precision)
    if (auto w = float32_precision_warning(bounding_box(mesh.positions))) m.warnings.push_back(*w);
  return m;
}

}  // namespace pgamesh
