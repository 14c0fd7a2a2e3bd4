// Internal: one vertex's half-edges grouped by their upper end, the step shared by the edge table
// (edges.cpp) and the triangle pass (triangle_topology.cpp): after the sort, each run of equal
// upper ends is one edge, and its uses stay in ascending half-edge order.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace pgamesh::detail {

// (upper end, half-edge or corner id) pairs of one vertex.
using EdgeGroup = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// Stable sort by upper end: insertion sort for the usual handful (a vertex of a mesh has about
// six), std::stable_sort for the rare large fan.
inline void sort_by_upper_end(EdgeGroup& group) {
  if (group.size() <= 16) {
    for (std::size_t i = 1; i < group.size(); ++i)
      for (std::size_t j = i; j > 0 && group[j - 1].first > group[j].first; --j)
        std::swap(group[j - 1], group[j]);
  } else {
    std::stable_sort(group.begin(), group.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
  }
}

}  // namespace pgamesh::detail
