#include "pgamesh/mesh/boundary_loops.hpp"

#include <algorithm>

#include "pgamesh/geometry/edge_loop.hpp"

namespace pgamesh {

std::vector<BoundaryLoop> boundary_loops(const Mesh& mesh, const WeldMap& weld,
                                         std::span<const std::uint32_t> welded_corner,
                                         const EdgeTable& edges, Vec3d reference) {
  std::vector<BoundaryLoop> loops;
  // The boundary half-edges, ascending.
  std::vector<std::uint32_t> sides;
  for (std::size_t e = 0; e < edges.edge_count(); ++e)
    if (edges.use_count(e) == 1) sides.push_back(edges.uses_of(e)[0]);
  if (sides.empty()) return loops;
  std::sort(sides.begin(), sides.end());

  const std::size_t n_vertices = weld.welded_count();
  auto tail = [&](std::uint32_t c) { return welded_corner[c]; };
  auto head = [&](std::uint32_t c) { return welded_corner[next_corner(mesh, edges, c)]; };

  // Outgoing boundary sides per vertex (CSR, ascending), in-degrees, and per-vertex cursors.
  std::vector<std::uint32_t> out_start(n_vertices + 1, 0), in_degree(n_vertices, 0);
  for (std::uint32_t c : sides) {
    ++out_start[tail(c) + 1];
    ++in_degree[head(c)];
  }
  for (std::size_t v = 0; v < n_vertices; ++v) out_start[v + 1] += out_start[v];
  std::vector<std::uint32_t> out_side(sides.size()), cursor(out_start.begin(), out_start.end() - 1);
  for (std::uint32_t i = 0; i < sides.size(); ++i) out_side[cursor[tail(sides[i])]++] = i;
  std::copy(out_start.begin(), out_start.end() - 1, cursor.begin());
  std::vector<std::uint8_t> used(sides.size(), 0);

  auto position = [&](std::uint32_t w) {
    return mesh.vertices[weld.representative[w]] - reference;
  };
  auto emit = [&](std::vector<std::uint32_t>::const_iterator begin,
                  std::vector<std::uint32_t>::const_iterator end, bool closed) {
    BoundaryLoop loop;
    loop.half_edges.assign(begin, end);
    loop.closed = closed;
    EdgeChainSums sums;
    for (std::uint32_t c : loop.half_edges) add_edge(sums, position(tail(c)), position(head(c)));
    loop.vector_area = vector_area(sums);
    loop.area = enclosed_area(sums);
    loop.perimeter = sums.length;
    loops.push_back(std::move(loop));
  };

  // Follows unused sides from `first`. Whenever the path comes back to a vertex it has already
  // passed, the sides since then form a simple cycle and become a loop of their own: two holes
  // touching at a vertex are two loops, not one figure-eight.
  constexpr std::uint32_t none = no_edge;
  std::vector<std::uint32_t> path_index(n_vertices, none);  // vertex → index of its side in path
  std::vector<std::uint32_t> path;
  auto trace = [&](std::uint32_t first) {
    path.clear();
    std::uint32_t i = first;
    for (;;) {
      used[i] = 1;
      const std::uint32_t c = sides[i];
      path_index[tail(c)] = static_cast<std::uint32_t>(path.size());
      path.push_back(c);
      const std::uint32_t v = head(c);
      if (path_index[v] != none) {
        const std::uint32_t k = path_index[v];
        for (std::size_t j = k; j < path.size(); ++j) path_index[tail(path[j])] = none;
        emit(path.begin() + k, path.end(), true);
        path.resize(k);
      }
      while (cursor[v] < out_start[v + 1] && used[out_side[cursor[v]]]) ++cursor[v];
      if (cursor[v] == out_start[v + 1]) break;
      i = out_side[cursor[v]];
    }
    if (!path.empty()) {  // an open chain (boundary in- and out-degrees differ somewhere)
      for (std::uint32_t c : path) path_index[tail(c)] = none;
      emit(path.begin(), path.end(), false);
    }
  };

  for (std::uint32_t i = 0; i < sides.size(); ++i) {
    const std::uint32_t v = tail(sides[i]);
    if (!used[i] && out_start[v + 1] - out_start[v] > in_degree[v]) trace(i);
  }
  for (std::uint32_t i = 0; i < sides.size(); ++i)
    if (!used[i]) trace(i);
  return loops;
}

}  // namespace pgamesh
