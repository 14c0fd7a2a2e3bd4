#include "pgamesh/mesh/topology/boundary_loops.hpp"

#include <algorithm>

#include "pgamesh/geometry/edge_loop.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh {

std::vector<BoundaryLoop> trace_boundary_loops(std::span<const std::uint32_t> sides,
                                               std::span<const std::uint32_t> tails,
                                               std::span<const std::uint32_t> heads,
                                               std::span<const Vec3d> positions, Vec3d reference) {
  std::vector<BoundaryLoop> loops;
  if (sides.empty()) return loops;
  const std::size_t n_vertices = positions.size();
  const auto side_count = static_cast<std::uint32_t>(sides.size());

  // Outgoing boundary sides per vertex (CSR, ascending), in-degrees, and per-vertex cursors.
  std::vector<std::uint32_t> out_start(n_vertices + 1, 0), in_degree(n_vertices, 0);
  for (std::uint32_t i = 0; i < side_count; ++i) {
    ++out_start[tails[i] + 1];
    ++in_degree[heads[i]];
  }
  for (std::size_t v = 0; v < n_vertices; ++v) out_start[v + 1] += out_start[v];
  std::vector<std::uint32_t> out_side(side_count), cursor(out_start.begin(), out_start.end() - 1);
  for (std::uint32_t i = 0; i < side_count; ++i) out_side[cursor[tails[i]]++] = i;
  std::copy(out_start.begin(), out_start.end() - 1, cursor.begin());
  std::vector<std::uint8_t> used(side_count, 0);

  auto position = [&](std::uint32_t w) { return positions[w] - reference; };
  auto emit = [&](std::vector<std::uint32_t>::const_iterator begin,
                  std::vector<std::uint32_t>::const_iterator end, bool closed) {
    BoundaryLoop loop;
    loop.closed = closed;
    EdgeChainSums sums;
    for (auto it = begin; it != end; ++it) {
      loop.half_edges.push_back(sides[*it]);
      add_edge(sums, position(tails[*it]), position(heads[*it]));
    }
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
  std::vector<std::uint32_t> path;                          // side indices
  auto trace = [&](std::uint32_t first) {
    path.clear();
    std::uint32_t i = first;
    for (;;) {
      used[i] = 1;
      path_index[tails[i]] = static_cast<std::uint32_t>(path.size());
      path.push_back(i);
      const std::uint32_t v = heads[i];
      if (path_index[v] != none) {
        const std::uint32_t k = path_index[v];
        for (std::size_t j = k; j < path.size(); ++j) path_index[tails[path[j]]] = none;
        emit(path.begin() + k, path.end(), true);
        path.resize(k);
      }
      while (cursor[v] < out_start[v + 1] && used[out_side[cursor[v]]]) ++cursor[v];
      if (cursor[v] == out_start[v + 1]) break;
      i = out_side[cursor[v]];
    }
    if (!path.empty()) {  // an open chain (boundary in- and out-degrees differ somewhere)
      for (std::uint32_t j : path) path_index[tails[j]] = none;
      emit(path.begin(), path.end(), false);
    }
  };

  for (std::uint32_t i = 0; i < side_count; ++i) {
    const std::uint32_t v = tails[i];
    if (!used[i] && out_start[v + 1] - out_start[v] > in_degree[v]) trace(i);
  }
  for (std::uint32_t i = 0; i < side_count; ++i)
    if (!used[i]) trace(i);
  return loops;
}

}  // namespace pgamesh
