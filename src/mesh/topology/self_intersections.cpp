#include "pgamesh/mesh/topology/self_intersections.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>

#include "detail/parallel/two_threads.hpp"
#include "mesh/topology/exact_predicates.hpp"
#include "mesh/topology/triangle_intersection.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh {

namespace {

// A box in floats, rounded outward: a conservative test for the boxes of the doubles (the narrow
// phase is exact, so a box only has to contain its triangle). 24 bytes instead of 48.
struct FloatBox {
  float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity()};
  float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity()};

  void add(const FloatBox& b) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  bool overlaps(const FloatBox& b) const {
    return lo[0] <= b.hi[0] && b.lo[0] <= hi[0] && lo[1] <= b.hi[1] && b.lo[1] <= hi[1] &&
           lo[2] <= b.hi[2] && b.lo[2] <= hi[2];
  }
};

// The float at or below x, and at or above (beyond the float range: its largest value or ±∞).
float float_at_or_below(double x) {
  constexpr float largest = std::numeric_limits<float>::max();
  if (x >= largest) return largest;
  if (x < -static_cast<double>(largest)) return -std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -largest) : f;
}
float float_at_or_above(double x) {
  constexpr float largest = std::numeric_limits<float>::max();
  if (x <= -largest) return -largest;
  if (x > static_cast<double>(largest)) return std::numeric_limits<float>::infinity();
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, largest) : f;
}

// A fan triangle that takes part: its face, its place in the face's fan and its welded vertices.
struct FanPrimitive {
  std::uint32_t face;
  std::uint32_t fan_index;
  std::uint32_t v[3];
};

// A fan triangle and its box: 44 bytes, what the hierarchy holds per triangle besides its nodes.
struct FanItem {
  FloatBox box;
  FanPrimitive primitive;
};

// The box of the triangle with corners a, b, c.
FloatBox box_of(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  FloatBox box;
  for (const Vec3d* x : {&a, &b, &c})
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::min(box.lo[k], float_at_or_below((*x)[k]));
      box.hi[k] = std::max(box.hi[k], float_at_or_above((*x)[k]));
    }
  return box;
}

// A node of the hierarchy: primitives [first, first + count) of the reordered list, and its
// children at `left` and left + 1 (left == 0: a leaf; the root is never a child).
struct HierarchyNode {
  FloatBox box;
  std::uint32_t first = 0, count = 0, left = 0;
};

constexpr std::uint32_t hierarchy_leaf_size = 4;
// Primitives per thread below which the queries stay on one thread.
constexpr std::size_t primitives_per_thread = std::size_t{1} << 13;

class FanHierarchy {
 public:
  // Median splits along the longest axis of the centres' box, the items themselves reordered
  // (no permutation to apply afterwards), so that every node's items are contiguous.
  // A large hierarchy's two halves are built on two threads, each into nodes of its own, then
  // joined: the same splits, so the same tree, its nodes in another order.
  FanHierarchy(std::span<const Vec3d> positions, std::vector<FanItem> items)
      : positions_(positions), items_(std::move(items)) {
    const auto n = static_cast<std::uint32_t>(items_.size());
    if (n == 0) return;
    nodes_.push_back({});
    if (n < 2 * primitives_per_thread) {
      nodes_.reserve(2 * (n / hierarchy_leaf_size) + 1);
      build(nodes_, 0, 0, n);
      return;
    }
    const std::uint32_t middle = split(nodes_[0], 0, n);
    std::vector<HierarchyNode> halves[2];
    detail::run_both(
        true, [&] { build_half(halves[0], 0, middle); }, [&] { build_half(halves[1], middle, n); });
    // Root, the halves' roots at 1 and 2, then the rest of each half: node k ≥ 1 of half h moves
    // to offset[h] + k, its children with it.
    nodes_[0].left = 1;
    const std::uint32_t offset[2] = {2, static_cast<std::uint32_t>(2 + halves[0].size() - 1)};
    nodes_.resize(1 + halves[0].size() + halves[1].size());
    for (int h = 0; h < 2; ++h)
      for (std::size_t k = 0; k < halves[h].size(); ++k) {
        HierarchyNode node = halves[h][k];
        if (node.left != 0) node.left += offset[h];
        nodes_[k == 0 ? 1 + h : offset[h] + k] = node;
      }
  }

  std::size_t size() const { return items_.size(); }

  // pair(i, j) for every j > i whose box overlaps i's and whose face differs from i's.
  template <class Pair>
  void query(std::uint32_t i, std::vector<std::uint32_t>& stack, const Pair& pair) const {
    const FloatBox& box = items_[i].box;
    const std::uint32_t face = items_[i].primitive.face;
    stack.clear();
    stack.push_back(0);
    while (!stack.empty()) {
      const HierarchyNode& node = nodes_[stack.back()];
      stack.pop_back();
      if (node.first + node.count <= i + 1 || !node.box.overlaps(box)) continue;
      if (node.left != 0) {
        stack.push_back(node.left);
        stack.push_back(node.left + 1);
        continue;
      }
      for (std::uint32_t j = std::max(node.first, i + 1); j < node.first + node.count; ++j)
        if (items_[j].primitive.face != face && items_[j].box.overlaps(box)) pair(j);
    }
  }

  const FanPrimitive& primitive(std::uint32_t i) const { return items_[i].primitive; }
  detail::IndexedTriangle triangle(std::uint32_t i) const {
    return triangle_of(items_[i].primitive);
  }

  detail::IndexedTriangle triangle_of(const FanPrimitive& p) const {
    detail::IndexedTriangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = p.v[k];
      t.p[k] = positions_[p.v[k]];
    }
    return t;
  }

 private:
  void build_half(std::vector<HierarchyNode>& nodes, std::uint32_t first, std::uint32_t end) {
    nodes.reserve(2 * ((end - first) / hierarchy_leaf_size) + 1);
    nodes.push_back({});
    build(nodes, 0, first, end);
  }

  // Node `node` of `nodes` over items [first, end), and below it its subtree.
  void build(std::vector<HierarchyNode>& nodes, std::uint32_t node, std::uint32_t first,
             std::uint32_t end) {
    const std::uint32_t middle = split(nodes[node], first, end);
    if (middle == end) return;
    const auto left = static_cast<std::uint32_t>(nodes.size());
    nodes[node].left = left;
    nodes.push_back({});
    nodes.push_back({});
    build(nodes, left, first, middle);
    build(nodes, left + 1, middle, end);
  }

  // Sets `node` over items [first, end) and, unless it is a leaf, reorders the items about its
  // split; returns the split (end for a leaf).
  std::uint32_t split(HierarchyNode& node, std::uint32_t first, std::uint32_t end) {
    FloatBox box, centres;
    for (std::uint32_t i = first; i < end; ++i) {
      const FloatBox& b = items_[i].box;
      box.add(b);
      FloatBox c;
      for (int a = 0; a < 3; ++a) c.lo[a] = c.hi[a] = b.lo[a] / 2 + b.hi[a] / 2;
      centres.add(c);
    }
    node.box = box;
    node.first = first;
    node.count = end - first;
    if (end - first <= hierarchy_leaf_size) return end;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (centres.hi[a] - centres.lo[a] > centres.hi[axis] - centres.lo[axis]) axis = a;
    const std::uint32_t middle = first + (end - first) / 2;
    // Twice the centre; a box from −∞ to +∞ (corners beyond the float range on both sides) sorts
    // as 0, so the order stays a strict weak one.
    auto centre = [axis](const FanItem& x) {
      const float c = x.box.lo[axis] + x.box.hi[axis];
      return c == c ? c : 0.0f;
    };
    std::nth_element(
        items_.begin() + first, items_.begin() + middle, items_.begin() + end,
        [&centre](const FanItem& x, const FanItem& y) { return centre(x) < centre(y); });
    return middle;
  }

  std::span<const Vec3d> positions_;
  std::vector<FanItem> items_;
  std::vector<HierarchyNode> nodes_;
};

// The fan triangles of face f: corner `begin` with each pair of consecutive later corners.
template <class Visit>
void for_each_fan_triangle(std::span<const std::uint32_t> corners, std::uint32_t begin,
                           std::uint32_t size, const Visit& visit) {
  for (std::uint32_t k = 1; k + 1 < size; ++k)
    visit(FanPrimitive{0, k - 1, {corners[begin], corners[begin + k], corners[begin + k + 1]}});
}

}  // namespace

SelfIntersections find_self_intersections(std::span<const Vec3d> positions,
                                          std::span<const std::uint32_t> corners,
                                          std::span<const std::uint32_t> face_offsets,
                                          std::size_t list_cap) {
  for (std::size_t c = 0; c < corners.size(); ++c)
    if (corners[c] >= positions.size())
      throw std::out_of_range("self-intersections: corner " + std::to_string(c) + " names vertex " +
                              std::to_string(corners[c]) + " of " +
                              std::to_string(positions.size()));
  const bool triangles = face_offsets.empty();
  const std::size_t faces = triangles ? corners.size() / 3 : face_offsets.size() - 1;
  auto begin = [&](std::size_t f) {
    return triangles ? static_cast<std::uint32_t>(3 * f) : face_offsets[f];
  };
  auto size = [&](std::size_t f) { return triangles ? 3u : face_offsets[f + 1] - face_offsets[f]; };

  SelfIntersections result;
  std::vector<FanItem> items;
  items.reserve(triangles ? faces : corners.size());
  for (std::size_t f = 0; f < faces; ++f)
    for_each_fan_triangle(corners, begin(f), size(f), [&](FanPrimitive p) {
      p.face = static_cast<std::uint32_t>(f);
      if (!is_finite(positions[p.v[0]]) || !is_finite(positions[p.v[1]]) ||
          !is_finite(positions[p.v[2]]))
        ++result.nonfinite_triangles;
      else if (detail::collinear(positions[p.v[0]], positions[p.v[1]], positions[p.v[2]]))
        ++result.degenerate_triangles;
      else
        items.push_back({box_of(positions[p.v[0]], positions[p.v[1]], positions[p.v[2]]), p});
    });
  const FanHierarchy bvh(positions, std::move(items));

  // Fan triangle k of face f, false when it takes no part (non-finite or collinear corners).
  auto fan_triangle = [&](std::uint32_t f, std::uint32_t k, detail::IndexedTriangle& t) {
    const std::uint32_t b = begin(f);
    const std::uint32_t v[3] = {corners[b], corners[b + k + 1], corners[b + k + 2]};
    for (int i = 0; i < 3; ++i) {
      t.v[i] = v[i];
      t.p[i] = positions[v[i]];
      if (!is_finite(t.p[i])) return false;
    }
    return !detail::collinear(t.p[0], t.p[1], t.p[2]);
  };
  // Whether fan triangles (k0 of f0, k1 of f1), f0 < f1, which meet, are the first such pair of
  // the two faces in (k0, k1) order: a face pair is counted once, at its first meeting pair, so
  // no pair needs to be stored. Triangles have one fan triangle each.
  auto first_meeting = [&](std::uint32_t f0, std::uint32_t k0, std::uint32_t f1, std::uint32_t k1) {
    if (size(f0) == 3 && size(f1) == 3) return true;
    detail::IndexedTriangle t, u;
    for (std::uint32_t a = 0; a <= k0; ++a) {
      if (!fan_triangle(f0, a, t)) continue;
      const std::uint32_t end = a == k0 ? k1 : size(f1) - 2;
      for (std::uint32_t b = 0; b < end; ++b)
        if (fan_triangle(f1, b, u) && detail::triangles_intersect(t, u)) return false;
    }
    return true;
  };

  // The narrow phase, on two threads in chunks taken in turn; each counts its pairs and keeps the
  // lowest list_cap of them in a max-heap (lower face in the high half of the key).
  const auto n = static_cast<std::uint32_t>(bvh.size());
  constexpr std::uint32_t chunk = 1024;
  std::atomic<std::uint32_t> next_chunk{0};
  std::atomic<std::size_t> found_pairs{0};  // both threads, for the stop at the bound
  std::atomic<bool> stop{false};
  struct Found {
    std::size_t count = 0;
    std::priority_queue<std::uint64_t> lowest;
  };
  auto work = [&](Found& found) {
    std::vector<std::uint32_t> stack;
    for (;;) {
      const std::uint32_t start = next_chunk.fetch_add(chunk);
      if (start >= n) break;
      for (std::uint32_t i = start; i < std::min(n, start + chunk) && !stop; ++i) {
        const detail::IndexedTriangle t = bvh.triangle(i);
        bvh.query(i, stack, [&](std::uint32_t j) {
          if (!detail::triangles_intersect(t, bvh.triangle(j))) return;
          FanPrimitive p = bvh.primitive(i), q = bvh.primitive(j);
          if (p.face > q.face) std::swap(p, q);
          if (!first_meeting(p.face, p.fan_index, q.face, q.fan_index)) return;
          ++found.count;
          if (found_pairs.fetch_add(1) + 1 >= max_counted_intersections) stop = true;
          const std::uint64_t key = std::uint64_t{p.face} << 32 | q.face;
          if (found.lowest.size() < list_cap) {
            found.lowest.push(key);
          } else if (list_cap > 0 && key < found.lowest.top()) {
            found.lowest.pop();
            found.lowest.push(key);
          }
        });
      }
    }
  };
  Found first, second;
  detail::run_both(
      n >= 2 * primitives_per_thread, [&] { work(first); }, [&] { work(second); });
  result.pairs = first.count + second.count;
  result.complete = !stop;
  std::vector<std::uint64_t> pairs;
  for (Found* found : {&first, &second})
    for (; !found->lowest.empty(); found->lowest.pop()) pairs.push_back(found->lowest.top());
  std::sort(pairs.begin(), pairs.end());

  // The listed pairs again, for a point where they meet.
  for (std::size_t k = 0; k < pairs.size() && k < list_cap; ++k) {
    SelfIntersection s;
    s.face0 = static_cast<std::uint32_t>(pairs[k] >> 32);
    s.face1 = static_cast<std::uint32_t>(pairs[k] & 0xffffffffu);
    bool found = false;
    detail::IndexedTriangle t, u;
    for (std::uint32_t a = 0; a + 2 < size(s.face0) && !found; ++a)
      for (std::uint32_t b = 0; b + 2 < size(s.face1) && !found; ++b)
        found = fan_triangle(s.face0, a, t) && fan_triangle(s.face1, b, u) &&
                detail::triangles_intersect(t, u, &s.point);
    result.list.push_back(s);
  }
  return result;
}

SelfIntersections find_self_intersections(const Mesh& mesh, std::size_t list_cap) {
  check_mesh_structure(mesh);
  const WeldResult welded = weld(mesh);
  return find_self_intersections(welded.mesh.vertices, welded.mesh.corners,
                                 welded.mesh.face_offsets, list_cap);
}

}  // namespace pgamesh
