#include "pgamesh/tank/fuel_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace pgamesh::tank {

std::vector<FuelState> fuel_sweep(const Tank& tank, Vec3d up_in, std::span<const double> levels,
                                  const std::function<void(std::size_t, std::size_t)>& progress) {
  const Vec3d up = unit_up(up_in);
  const auto n = static_cast<std::uint32_t>(tank.triangles.size());
  // Heights of the vertices: p ∨ v = height − level exactly as fuel_naive computes it.
  std::vector<double> height(tank.vertices.size());
  for (std::size_t i = 0; i < height.size(); ++i) height[i] = dot(up, tank.vertices[i]);
  std::vector<double> tmin(n), tmax(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const auto& tri = tank.triangles[t];
    tmin[t] = std::min({height[tri[0]], height[tri[1]], height[tri[2]]});
    tmax[t] = std::max({height[tri[0]], height[tri[1]], height[tri[2]]});
  }
  // Sort (key, triangle) pairs: direct comparisons on contiguous keys.
  auto sorted_by = [&](const std::vector<double>& key) {
    std::vector<std::pair<double, std::uint32_t>> pairs(n);
    for (std::uint32_t t = 0; t < n; ++t) pairs[t] = {key[t], t};
    std::sort(pairs.begin(), pairs.end());
    std::vector<std::uint32_t> ids(n);
    for (std::uint32_t i = 0; i < n; ++i) ids[i] = pairs[i].second;
    return ids;
  };
  const std::vector<std::uint32_t> by_min = sorted_by(tmin), by_max = sorted_by(tmax);
  std::vector<std::size_t> order(levels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return levels[a] < levels[b]; });

  const Vec3d r = tank.reference;
  auto relative = [&](std::uint32_t k) { return tank.vertices[k] - r; };
  std::vector<FuelState> out(levels.size());
  const double lowest = n ? tmin[by_min[0]] : 0;
  BoundarySums whole;  // triangles wholly in the fuel (highest vertex ≤ level)
  std::vector<std::uint32_t> crossing;
  std::size_t next_min = 0, next_max = 0;
  std::size_t done = 0;
  for (std::size_t li : order) {
    if (progress && done % 1024 == 0) progress(done, levels.size());
    ++done;
    if (!std::isfinite(levels[li])) throw std::invalid_argument("the level must be finite");
    const FuelPlane plane{up, levels[li]};  // up is already unit: keep its exact value
    const double level = plane.level;
    while (next_max < n && tmax[by_max[next_max]] <= level) {
      const auto& tri = tank.triangles[by_max[next_max++]];
      add_triangle(whole, relative(tri[0]), relative(tri[1]), relative(tri[2]));
    }
    while (next_min < n && tmin[by_min[next_min]] <= level) {
      const std::uint32_t t = by_min[next_min++];
      if (tmax[t] > level) crossing.push_back(t);
    }
    std::erase_if(crossing, [&](std::uint32_t t) { return tmax[t] <= level; });
    SliceContext ctx;
    ctx.frame = surface_frame(plane, r);
    SliceSums sums;
    auto add_piece = [&](std::uint32_t t) {
      const auto& tri = tank.triangles[t];
      Vec3d v[3];
      double d[3];
      for (int k = 0; k < 3; ++k) {
        v[k] = tank.vertices[tri[k]] - ctx.reference;
        d[k] = height[tri[k]] - level;
      }
      add_kept_part(sums, ctx, Side::fuel, v, d);
    };
    if (next_max == 0 || level <= lowest) {
      // Only pieces (or faces lying in the lowest plane): sum them about o′ on the plane like the
      // reference pass (eq. 4.13), which keeps every digit of a small fuel region (ERRATA §6).
      ctx.reference = ctx.frame.origin;
      for (std::size_t i = 0; i < next_min; ++i) add_piece(by_min[i]);
    } else {
      // Whole triangles are summed about r: add the cone over the free surface.
      ctx.reference = r;
      ctx.cone_over_surface = true;
      sums.wall = next_max == n ? tank.total : whole;  // full: the very sums of the tank
      for (std::uint32_t t : crossing) add_piece(t);
    }
    out[li] = fuel_state(tank, plane, ctx, sums, Side::fuel);
  }
  if (progress) progress(levels.size(), levels.size());
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
