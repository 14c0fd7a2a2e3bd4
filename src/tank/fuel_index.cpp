#include "pgamesh/tank/fuel_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "pgamesh/core/bounding_box.hpp"

namespace pgamesh::tank {

namespace {

constexpr std::uint32_t kLeafSize = 8;

// up·x over the box: centre value and half width.
struct Extent {
  double center, radius;
};
Extent extent_along(Vec3d up, Vec3d center, Vec3d half) {
  return {dot(up, center),
          std::abs(up.x) * half.x + std::abs(up.y) * half.y + std::abs(up.z) * half.z};
}

}  // namespace

FuelIndex::FuelIndex(const Tank& tank) : tank_(&tank) {
  const auto n = static_cast<std::uint32_t>(tank.triangles.size());
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0u);
  std::vector<Vec3d> centroids(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const auto& t = tank.triangles[i];
    centroids[i] = (tank.vertices[t[0]] + tank.vertices[t[1]] + tank.vertices[t[2]]) / 3.0;
  }
  nodes_.reserve(2 * (n / kLeafSize + 1));
  if (n) build(0, n, centroids);
}

std::uint32_t FuelIndex::build(std::uint32_t first, std::uint32_t count,
                               std::vector<Vec3d>& centroids) {
  const auto id = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  const double inf = std::numeric_limits<double>::infinity();
  Vec3d lo{inf, inf, inf}, hi{-inf, -inf, -inf}, clo = lo, chi = hi;
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (std::uint32_t k : tank_->triangles[order_[i]])
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], tank_->vertices[k][a]);
        hi[a] = std::max(hi[a], tank_->vertices[k][a]);
      }
    for (int a = 0; a < 3; ++a) {
      clo[a] = std::min(clo[a], centroids[order_[i]][a]);
      chi[a] = std::max(chi[a], centroids[order_[i]][a]);
    }
  }
  nodes_[id].center = (lo + hi) / 2.0;
  nodes_[id].half = (hi - lo) / 2.0;
  if (count <= kLeafSize) {
    Node& leaf = nodes_[id];
    leaf.first = first;
    leaf.count = count;
    const Vec3d r = tank_->reference;
    for (std::uint32_t i = first; i < first + count; ++i) {
      const auto& t = tank_->triangles[order_[i]];
      add_fan_triangle(leaf.sums, tank_->vertices[t[0]] - r, tank_->vertices[t[1]] - r,
                       tank_->vertices[t[2]] - r, area_sign(*tank_, order_[i]));
    }
    return id;
  }
  const Vec3d span = chi - clo;
  const int axis = span.x >= span.y && span.x >= span.z ? 0 : (span.y >= span.z ? 1 : 2);
  const std::uint32_t half = count / 2;
  std::nth_element(
      order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
      [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  const std::uint32_t left = build(first, half, centroids);
  const std::uint32_t right = build(first + half, count - half, centroids);
  BoundarySums sums = nodes_[left].sums;
  sums += nodes_[right].sums;
  nodes_[id].sums = sums;
  nodes_[id].first = right;
  nodes_[id].count = 0;
  return id;
}

void FuelIndex::add_leaf(SliceSums& sums, const SliceContext& ctx, Side side,
                         const FuelPlane& plane, const Node& node) const {
  const pga3::Plane<double> p = plane.plane();
  for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
    const auto& tri = tank_->triangles[order_[i]];
    Vec3d v[3];
    double d[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3d x = tank_->vertices[tri[k]];
      d[k] = pga3::join(p, pga3::point(x));
      v[k] = x - ctx.reference;
    }
    add_kept_part(sums, ctx, side, v, d, area_sign(*tank_, order_[i]));
  }
}

FuelState FuelIndex::query(const FuelPlane& plane) const {
  SliceContext ctx;
  ctx.frame = surface_frame(plane, tank_->reference);
  SliceSums sums;
  if (nodes_.empty()) return fuel_state(*tank_, plane, ctx, sums, Side::fuel);
  const Extent root = extent_along(plane.up, nodes_[0].center, nodes_[0].half);
  const Side side = plane.level > root.center ? Side::ullage : Side::fuel;
  // A node is wholly on one side when its box is, with a margin for the rounding of the box
  // bound; anything closer is opened and its vertices classified exactly as fuel_naive does.
  const double margin =
      1e-12 * (std::abs(root.center) + root.radius + std::abs(plane.level) + 1e-300);
  std::vector<std::uint32_t> whole, open;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top) {
    const std::uint32_t id = stack[--top];
    const Node& node = nodes_[id];
    const Extent e = extent_along(plane.up, node.center, node.half);
    const double lowest = e.center - e.radius - plane.level;
    const double highest = e.center + e.radius - plane.level;
    if (highest < -margin || lowest > margin) {  // wholly in the fuel or wholly in the ullage
      if ((highest < -margin) == (side == Side::fuel)) whole.push_back(id);
      continue;
    }
    if (node.count) {
      open.push_back(id);
    } else {
      stack[top++] = node.first;
      stack[top++] = id + 1;
    }
  }
  if (whole.empty() && side == Side::fuel) {
    // Only split pieces: sum them about o′ on the plane like the reference pass (eq. 4.13), which
    // keeps every digit of a small fuel region (docs/conventions.md §13).
    // o′ near the fuel-side vertices of the open leaves (docs/conventions.md §13), as in
    // fuel_naive.
    Box3 kept;
    const pga3::Plane<double> p = plane.plane();
    for (std::uint32_t id : open)
      for (std::uint32_t i = nodes_[id].first; i < nodes_[id].first + nodes_[id].count; ++i)
        for (std::uint32_t k : tank_->triangles[order_[i]])
          if (pga3::join(p, pga3::point(tank_->vertices[k])) <= 0) kept.add(tank_->vertices[k]);
    if (!kept.empty()) ctx.frame = surface_frame(plane, kept.centre());
    ctx.reference = ctx.frame.origin;
    ctx.cone_over_surface = false;
  } else {
    // Whole nodes carry sums about the tank's reference: add the cone over the free surface.
    ctx.reference = tank_->reference;
    ctx.cone_over_surface = true;
  }
  for (std::uint32_t id : whole) sums.wall += nodes_[id].sums;
  for (std::uint32_t id : open) add_leaf(sums, ctx, side, plane, nodes_[id]);
  return fuel_state(*tank_, plane, ctx, sums, side);
}

LevelRange FuelIndex::range(Vec3d up) const {
  LevelRange r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  if (nodes_.empty()) return r;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top) {
    const Node& node = nodes_[stack[--top]];
    const Extent e = extent_along(up, node.center, node.half);
    if (e.center - e.radius >= r.lowest && e.center + e.radius <= r.highest) continue;
    if (node.count) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
        for (std::uint32_t k : tank_->triangles[order_[i]]) {
          const double h = dot(up, tank_->vertices[k]);
          r.lowest = std::min(r.lowest, h);
          r.highest = std::max(r.highest, h);
        }
    } else {
      const auto self = static_cast<std::uint32_t>(&node - nodes_.data());
      stack[top++] = node.first;
      stack[top++] = self + 1;
    }
  }
  return r;
}

}  // namespace pgamesh::tank
