#include "pgamesh/tank/fuel_sweep.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "pgamesh/core/bounding_box.hpp"

namespace pgamesh::tank {

namespace {

// A triangle the rising plane crosses, copied out of the mesh while it crosses so that the
// per-level work reads contiguous memory: corners relative to the tank's reference, their
// heights up·v, and the first level rank at which it lies wholly in the fuel.
struct Crossing {
  std::array<Vec3d, 3> v;
  std::array<double, 3> height;
  std::uint32_t whole_from;
  double area_sign;  // tank.hpp, area_sign
};

// Rank of the first sorted level ≥ h (`sorted` not empty): from that rank on, a vertex at height
// h is fuel. std::lower_bound without branches on the data (a select instead).
std::uint32_t first_rank_at_or_above(const std::vector<double>& sorted, double h) {
  const double* base = sorted.data();
  std::size_t n = sorted.size();
  while (n > 1) {
    const std::size_t half = n / 2;
    base = base[half] < h ? base + half : base;
    n -= half;
  }
  return static_cast<std::uint32_t>(base - sorted.data()) + (*base < h);
}

}  // namespace

std::vector<FuelState> fuel_sweep(const Tank& tank, Vec3d up_in, std::span<const double> levels,
                                  const std::function<void(std::size_t, std::size_t)>& progress) {
  const Vec3d up = unit_up(up_in);
  for (double level : levels)
    if (!std::isfinite(level)) throw std::invalid_argument("the level must be finite");
  const auto n = static_cast<std::uint32_t>(tank.triangles.size());
  const std::size_t m = levels.size();
  if (m == 0) return {};
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](auto a, auto b) { return levels[a] < levels[b]; });
  std::vector<double> sorted(m);
  for (std::size_t k = 0; k < m; ++k) sorted[k] = levels[order[k]];

  // Heights of the vertices: p ∨ v = height − level, as fuel_naive computes it. A vertex is fuel
  // from the rank of the first level at or above its height on.
  const std::size_t nv = tank.vertices.size();
  std::vector<double> height(nv);
  std::vector<std::uint32_t> vertex_rank(nv);
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nv; ++i) {
    height[i] = dot(up, tank.vertices[i]);
    vertex_rank[i] = first_rank_at_or_above(sorted, height[i]);
    lowest = std::min(lowest, height[i]);
  }

  // Per triangle, by the ranks of its corners (min ≤ mid ≤ max): it touches the fuel from rank
  // kmin, has two corners in the fuel from kmid and is whole from kmax. Its whole sums go into
  // the bucket of kmid — from there on the fuel wall is the triangle minus the small piece at its
  // dropped corner (paper §4d), and whole from kmax — and it is handed to the crossing set at
  // kmin (counting sort by kmin).
  const Vec3d r = tank.reference;
  std::vector<BoundarySums> mid_bucket(m + 1);
  std::vector<std::uint32_t> enter_start(m + 2, 0);
  std::uint32_t first_whole = static_cast<std::uint32_t>(m), last_whole = 0;
  std::vector<std::array<std::uint32_t, 3>> ranks(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = tank.triangles[t];
    std::array<std::uint32_t, 3> k{vertex_rank[tri[0]], vertex_rank[tri[1]], vertex_rank[tri[2]]};
    std::sort(k.begin(), k.end());
    ranks[t] = k;
    add_fan_triangle(mid_bucket[k[1]], tank.vertices[tri[0]] - r, tank.vertices[tri[1]] - r,
                     tank.vertices[tri[2]] - r, area_sign(tank, t));
    ++enter_start[k[0] + 1];
    first_whole = std::min(first_whole, k[2]);
    last_whole = std::max(last_whole, k[2]);
  }
  std::partial_sum(enter_start.begin(), enter_start.end(), enter_start.begin());
  std::vector<std::uint32_t> by_enter(n);
  {
    std::vector<std::uint32_t> fill(enter_start.begin(), enter_start.end() - 1);
    for (std::uint32_t t = 0; t < n; ++t) by_enter[fill[ranks[t][0]]++] = t;
  }

  // Vertices by rank (counting sort): the box of the fuel-side vertices grows with the level.
  std::vector<std::uint32_t> vertex_start(m + 2, 0);
  for (std::size_t i = 0; i < nv; ++i) ++vertex_start[vertex_rank[i] + 1];
  std::partial_sum(vertex_start.begin(), vertex_start.end(), vertex_start.begin());
  std::vector<std::uint32_t> by_rank(nv);
  {
    std::vector<std::uint32_t> fill(vertex_start.begin(), vertex_start.end() - 1);
    for (std::uint32_t i = 0; i < nv; ++i) by_rank[fill[vertex_rank[i]]++] = i;
  }

  std::vector<FuelState> out(m);
  Box3 kept_box;
  BoundarySums two_in;  // triangles with at least two corners in the fuel, whole
  std::vector<Crossing> crossing;
  for (std::uint32_t k = 0; k < m; ++k) {
    if (progress && k % 1024 == 0) progress(k, m);
    const FuelPlane plane{up, sorted[k]};  // up is already unit: keep its exact value
    const double level = plane.level;
    two_in += mid_bucket[k];
    for (std::uint32_t i = vertex_start[k]; i < vertex_start[k + 1]; ++i)
      kept_box.add(tank.vertices[by_rank[i]]);
    for (std::uint32_t i = enter_start[k]; i < enter_start[k + 1]; ++i) {
      const std::uint32_t t = by_enter[i];
      if (ranks[t][2] <= k) continue;  // never crosses a level: whole at once
      const auto& tri = tank.triangles[t];
      crossing.push_back(
          {{tank.vertices[tri[0]] - r, tank.vertices[tri[1]] - r, tank.vertices[tri[2]] - r},
           {height[tri[0]], height[tri[1]], height[tri[2]]},
           ranks[t][2],
           area_sign(tank, t)});
    }

    SliceContext ctx;
    ctx.frame = surface_frame(plane, r);
    SliceSums sums;
    if (k < first_whole || level <= lowest) {
      // Only pieces (or faces lying in the lowest plane): sum them about o′ on the plane near the
      // fuel-side vertices like the reference pass (eq. 4.13), which keeps every digit of a small
      // fuel region (docs/conventions.md §13).
      std::erase_if(crossing, [&](const Crossing& c) { return c.whole_from <= k; });
      if (!kept_box.empty()) ctx.frame = surface_frame(plane, kept_box.centre());
      ctx.reference = ctx.frame.origin;
      for (std::uint32_t i = 0; i < enter_start[k + 1]; ++i) {
        const auto& tri = tank.triangles[by_enter[i]];
        Vec3d v[3];
        double d[3];
        for (int c = 0; c < 3; ++c) {
          v[c] = tank.vertices[tri[c]] - ctx.reference;
          d[c] = height[tri[c]] - level;
        }
        add_kept_part(sums, ctx, Side::fuel, v, d, area_sign(tank, by_enter[i]));
      }
    } else if (k >= last_whole) {
      crossing.clear();
      ctx.reference = r;
      sums.wall = tank.total;  // full: the very sums of the tank
    } else {
      // The wall is the two-corner triangles, plus the small piece of each one-corner triangle,
      // minus the small (dropped) piece of each two-corner one: one tetrahedron a crossing. The
      // cone from r over the free surface comes from the surface sums (cone_over_surface).
      ctx.reference = r;
      ctx.cone_over_surface = true;
      const Vec3d origin = ctx.frame.origin - r;
      BoundarySums one_in_pieces, two_in_pieces;
      std::size_t kept = 0;  // the crossing set is compacted in the same pass
      for (const Crossing& c : crossing) {
        if (c.whole_from <= k) continue;
        const double d[3] = {c.height[0] - level, c.height[1] - level, c.height[2] - level};
        const CutTriangle cut = cut_triangle(c.v.data(), d);
        add_fan_triangle(cut.a_in_fuel ? one_in_pieces : two_in_pieces, cut.a, cut.ab, cut.ac,
                         c.area_sign);
        add_surface_segment(sums.surface, ctx.frame, origin, cut);
        crossing[kept++] = c;
      }
      crossing.resize(kept);
      sums.wall = two_in;
      sums.wall += one_in_pieces;
      subtract(sums.wall, two_in_pieces);
    }
    out[order[k]] = fuel_state(tank, plane, ctx, sums, Side::fuel);
  }
  if (progress) progress(m, m);
  return out;
}

std::vector<double> even_levels(LevelRange range, int n) {
  if (n < 1) throw std::invalid_argument("a table needs at least one step (N >= 1)");
  std::vector<double> levels(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i)
    levels[i] = range.lowest + (range.highest - range.lowest) * (double(i) / n);
  levels[n] = range.highest;
  return levels;
}

}  // namespace pgamesh::tank
