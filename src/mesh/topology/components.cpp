#include "pgamesh/mesh/topology/components.hpp"

#include <algorithm>

#include "mesh/topology/union_find.hpp"

namespace pgamesh {

using detail::find_root;

FaceComponents face_components(const Mesh& mesh, const EdgeTable& edges) {
  const std::size_t face_count = mesh.face_count();
  std::vector<std::uint32_t> parent(face_count);
  for (std::size_t f = 0; f < face_count; ++f) parent[f] = static_cast<std::uint32_t>(f);
  for (std::size_t e = 0; e < edges.edge_count(); ++e) {
    const auto uses = edges.uses_of(e);
    std::uint32_t root = find_root(parent, edges.corner_face[uses[0]]);
    for (std::size_t i = 1; i < uses.size(); ++i) {
      const std::uint32_t r = find_root(parent, edges.corner_face[uses[i]]);
      if (r == root) continue;
      parent[std::max(r, root)] = std::min(r, root);
      root = std::min(r, root);
    }
  }

  FaceComponents out;
  out.face_component.assign(face_count, no_edge);
  std::vector<std::uint8_t> collapsed(face_count, 0);
  for (std::uint32_t f : edges.collapsed_faces) collapsed[f] = 1;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (collapsed[f]) continue;
    const std::uint32_t r = find_root(parent, static_cast<std::uint32_t>(f));
    if (r == f) {
      out.face_component[f] = static_cast<std::uint32_t>(out.first_face.size());
      out.first_face.push_back(static_cast<std::uint32_t>(f));
      out.face_count.push_back(0);
    } else {
      out.face_component[f] = out.face_component[r];  // r < f: already numbered
    }
    ++out.face_count[out.face_component[f]];
  }
  return out;
}

}  // namespace pgamesh
