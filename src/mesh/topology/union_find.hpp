// Internal: the union–find of the face components (components.cpp, welded_topology.cpp).
#pragma once

#include <atomic>
#include <cstdint>
#include <utility>
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

// find_root while other threads unite sets in the same array (unite_roots_shared): the pointers
// are read and halved through atomic_ref. A pointer only ever moves to an ancestor, so it still
// points down within its set.
inline std::uint32_t find_root_shared(std::uint32_t* parent, std::uint32_t x) {
  for (;;) {
    std::atomic_ref<std::uint32_t> px(parent[x]);
    std::uint32_t p = px.load(std::memory_order_relaxed);
    if (p == x) return x;
    const std::uint32_t gp =
        std::atomic_ref<std::uint32_t>(parent[p]).load(std::memory_order_relaxed);
    if (gp != p) px.compare_exchange_weak(p, gp, std::memory_order_relaxed);
    x = gp;
  }
}

// Unites the sets of a and b (roots, or members if another thread has linked them since) while
// other threads do the same, the higher root pointing to the lower as in the sequential version:
// a root is linked by a compare-and-swap that still sees it as a root, else the roots are found
// again. Every set's root is its lowest element whatever the order of the unions, so the sets and
// their roots do not depend on the threads. Returns the root of the union.
inline std::uint32_t unite_roots_shared(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
  for (;;) {
    a = find_root_shared(parent, a);
    b = find_root_shared(parent, b);
    if (a == b) return a;
    if (a < b) std::swap(a, b);
    std::uint32_t expected = a;
    if (std::atomic_ref<std::uint32_t>(parent[a]).compare_exchange_strong(
            expected, b, std::memory_order_relaxed))
      return b;
  }
}

}  // namespace pgamesh::detail
