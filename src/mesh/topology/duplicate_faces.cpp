#include "pgamesh/mesh/topology/duplicate_faces.hpp"

#include <algorithm>

namespace pgamesh {

namespace {

void sorted_vertex_set(const Mesh& mesh, std::span<const std::uint32_t> welded_corner,
                       std::uint32_t f, std::vector<std::uint32_t>& out) {
  out.assign(welded_corner.begin() + mesh.face_offsets[f],
             welded_corner.begin() + mesh.face_offsets[f + 1]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicated_faces(
    const Mesh& mesh, const EdgeTable& edges, std::span<const std::uint32_t> welded_corner) {
  const std::size_t face_count = mesh.face_count();
  std::vector<std::uint32_t> same_as(face_count, no_edge);
  std::vector<std::uint32_t> set_f, set_g;  // reused buffers
  for (std::uint32_t f = 0; f < face_count; ++f) {
    if (same_as[f] != no_edge) continue;  // its own duplicates were found from the earlier face
    std::uint32_t e = no_edge;
    for (std::uint32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
      if (edges.corner_edge[c] != no_edge) {
        e = edges.corner_edge[c];
        break;
      }
    if (e == no_edge || edges.use_count(e) < 2) continue;  // collapsed, or alone on its edge
    bool have_set = false;
    for (std::uint32_t c : edges.uses_of(e)) {
      const std::uint32_t g = edges.corner_face[c];
      if (g <= f || same_as[g] != no_edge) continue;
      if (!have_set) {
        sorted_vertex_set(mesh, welded_corner, f, set_f);
        have_set = true;
      }
      sorted_vertex_set(mesh, welded_corner, g, set_g);
      if (set_f == set_g) same_as[g] = f;
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t g = 0; g < face_count; ++g)
    if (same_as[g] != no_edge) out.emplace_back(g, same_as[g]);
  return out;
}

}  // namespace pgamesh
