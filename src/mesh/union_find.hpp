// Internal: the union–find of the face components (components.cpp, triangle_topology.cpp).
#pragma once

#include <cstdint>
#include <vector>

namespace pgamesh::detail {

// The root of x's set, halving the path on the way. The callers unite by index (the higher root
// points to the lower), so a root is always the lowest face of its set.
inline std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

}  // namespace pgamesh::detail
