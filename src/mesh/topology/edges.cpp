#include "pgamesh/mesh/topology/edges.hpp"

#include <algorithm>
#include <utility>

#include "mesh/topology/edge_group.hpp"
#include "mesh/topology/face_layout.hpp"

namespace pgamesh {

EdgeTable build_edges(const Mesh& mesh, std::span<const std::uint32_t> welded_corner,
                      std::size_t welded_vertex_count) {
  EdgeTable t;
  const std::size_t corner_count = mesh.corners.size();
  const std::size_t face_count = mesh.face_count();
  t.corner_face = detail::corner_faces(mesh.face_offsets);
  // Corners of collapsed faces are marked so that the passes below skip them.
  std::vector<std::uint8_t> skip(corner_count, 0);
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::uint32_t begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
    if (detail::collapsed_face(welded_corner.data(), begin, end)) {
      t.collapsed_faces.push_back(static_cast<std::uint32_t>(f));
      std::fill(skip.begin() + begin, skip.begin() + end, std::uint8_t{1});
    }
  }

  // Counting sort of the half-edges by their smaller end vertex.
  std::vector<std::uint32_t> start(welded_vertex_count + 1, 0);
  std::size_t live = 0;
  for (std::uint32_t c = 0; c < corner_count; ++c) {
    if (skip[c]) continue;
    const std::uint32_t a = welded_corner[c], b = welded_corner[next_corner(mesh, t, c)];
    if (a == b) continue;
    ++start[std::min(a, b) + 1];
    ++live;
  }
  for (std::size_t v = 0; v < welded_vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> bucket(live);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t c = 0; c < corner_count; ++c) {
      if (skip[c]) continue;
      const std::uint32_t a = welded_corner[c], b = welded_corner[next_corner(mesh, t, c)];
      if (a == b) continue;
      bucket[fill[std::min(a, b)]++] = c;
    }
  }

  // Within a vertex's bucket (a handful of half-edges), group by the larger end. The bucket holds
  // corners in ascending order and the sort is stable, so each edge's uses stay ascending.
  t.corner_edge.assign(corner_count, no_edge);
  t.v0.reserve(live / 2 + 1);
  t.v1.reserve(live / 2 + 1);
  t.use_offsets.reserve(live / 2 + 2);
  t.uses.resize(live);
  detail::EdgeGroup group;  // (larger end, corner), reused
  std::size_t out = 0;
  for (std::uint32_t v = 0; v < welded_vertex_count; ++v) {
    const std::uint32_t begin = start[v], end = start[v + 1];
    if (begin == end) continue;
    group.clear();
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t c = bucket[i];
      const std::uint32_t a = welded_corner[c], b = welded_corner[next_corner(mesh, t, c)];
      group.emplace_back(std::max(a, b), c);
    }
    detail::sort_by_upper_end(group);
    for (std::size_t i = 0; i < group.size();) {
      const auto e = static_cast<std::uint32_t>(t.v0.size());
      t.v0.push_back(v);
      t.v1.push_back(group[i].first);
      t.use_offsets.push_back(static_cast<std::uint32_t>(out));
      const std::uint32_t other = group[i].first;
      for (; i < group.size() && group[i].first == other; ++i) {
        t.uses[out++] = group[i].second;
        t.corner_edge[group[i].second] = e;
      }
    }
  }
  t.use_offsets.push_back(static_cast<std::uint32_t>(out));
  return t;
}

}  // namespace pgamesh
