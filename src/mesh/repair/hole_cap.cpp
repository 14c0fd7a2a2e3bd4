#include "pgamesh/mesh/repair/hole_cap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "pgamesh/geometry/edge_loop.hpp"

namespace pgamesh {

namespace {

constexpr std::size_t max_rim_vertices = 100000;

struct Point2 {
  double u = 0, v = 0;
};

// Twice the signed area of the triangle a, b, c (> 0 counter-clockwise).
double orient(Point2 a, Point2 b, Point2 c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// Whether the closed segments pq and rs share a point.
bool segments_meet(Point2 p, Point2 q, Point2 r, Point2 s) {
  const double d1 = orient(p, q, r), d2 = orient(p, q, s), d3 = orient(r, s, p),
               d4 = orient(r, s, q);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  const auto on = [](Point2 a, Point2 b, Point2 c) {  // c on segment ab, given collinear
    return std::min(a.u, b.u) <= c.u && c.u <= std::max(a.u, b.u) && std::min(a.v, b.v) <= c.v &&
           c.v <= std::max(a.v, b.v);
  };
  return (d1 == 0 && on(p, q, r)) || (d2 == 0 && on(p, q, s)) || (d3 == 0 && on(r, s, p)) ||
         (d4 == 0 && on(r, s, q));
}

// Whether the closed polygon crosses or touches itself anywhere but at the shared ends of
// consecutive sides. Quadratic, for rims of moderate size.
bool is_simple(const std::vector<Point2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  return true;
}

// Whether c lies inside or on the counter-clockwise triangle (a, b, d).
bool in_triangle(Point2 a, Point2 b, Point2 d, Point2 c) {
  return orient(a, b, c) >= 0 && orient(b, d, c) >= 0 && orient(d, a, c) >= 0;
}

// Ear clipping of a simple counter-clockwise polygon: indices into `p`, counter-clockwise
// triangles. An ear is a strictly convex corner whose triangle holds no other remaining vertex;
// a simple polygon always has one (the two-ears theorem). Collinear corners are clipped last.
std::vector<std::array<std::uint32_t, 3>> clip_ears(const std::vector<Point2>& p) {
  std::vector<std::uint32_t> ring(p.size());
  for (std::uint32_t i = 0; i < ring.size(); ++i) ring[i] = i;
  std::vector<std::array<std::uint32_t, 3>> out;
  std::size_t i = 0, misses = 0;
  while (ring.size() > 3) {
    const std::size_t n = ring.size();
    const std::uint32_t a = ring[(i + n - 1) % n], b = ring[i % n], c = ring[(i + 1) % n];
    bool ear = orient(p[a], p[b], p[c]) > 0;
    for (std::size_t k = 0; ear && k < n; ++k) {
      const std::uint32_t q = ring[k];
      if (q != a && q != b && q != c && in_triangle(p[a], p[b], p[c], p[q])) ear = false;
    }
    // A simple polygon always has an ear, but rounding can hide all of them on a nearly
    // degenerate rim: after a full turn without one, clip the corner at hand (a thin triangle)
    // rather than turn for ever.
    if (ear || misses > n) {
      out.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i % n));
      misses = 0;
      if (i >= ring.size()) i = 0;
    } else {
      ++i;
      ++misses;
    }
  }
  if (ring.size() == 3) out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

std::string describe(const char* format, double a, double b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

}  // namespace

HoleCap cap_hole(std::span<const Vec3d> positions, std::span<const std::uint32_t> rim,
                 const HoleCapOptions& options) {
  HoleCap cap;
  const std::size_t n = rim.size();
  if (n < 3) {
    cap.refused = "fewer than three vertices";
    return cap;
  }
  if (n > max_rim_vertices) {
    cap.refused = "more than 100000 vertices";
    return cap;
  }
  {
    std::vector<std::uint32_t> sorted(rim.begin(), rim.end());
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      cap.refused = "the rim passes twice through one vertex (two holes touching)";
      return cap;
    }
  }
  // The plane: the rim's vector area (half the moment of its summed edge carriers) gives the
  // normal; the centroid of its vertices a point. Coordinates relative to the first vertex keep
  // the moments' digits (docs/conventions.md §13).
  const Vec3d origin = positions[rim[0]];
  EdgeChainSums sums;
  Vec3d centroid{}, lo = origin, hi = origin;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d a = positions[rim[i]], b = positions[rim[(i + 1) % n]];
    add_edge(sums, a - origin, b - origin);
    centroid += a - origin;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], a[k]);
      hi[k] = std::max(hi[k], a[k]);
    }
  }
  centroid = centroid / static_cast<double>(n);
  cap.diameter = length(hi - lo);
  // The rim runs the way its faces do, so the hole's own orientation is the opposite one.
  const Vec3d rim_area = vector_area(sums);
  cap.area = length(rim_area);
  if (!(cap.area > 0) || !std::isfinite(cap.area)) {
    cap.refused = "the rim encloses no area";
    return cap;
  }
  cap.normal = -rim_area / cap.area;
  for (std::size_t i = 0; i < n; ++i)
    cap.max_deviation = std::max(cap.max_deviation,
                                 std::abs(dot(positions[rim[i]] - origin - centroid, cap.normal)));
  if (cap.max_deviation > options.planarity * cap.diameter && !options.force) {
    cap.refused = describe(
        "not planar: a vertex lies %.3g from the best-fit plane (%.3g of the "
        "rim's size; --force caps it anyway)",
        cap.max_deviation, cap.max_deviation / cap.diameter);
    return cap;
  }
  // Coordinates in the plane, (e1, e2, normal) right-handed, so the cap, which runs against the
  // rim, is counter-clockwise.
  const Vec3d helper = std::abs(cap.normal.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  Vec3d e1 = cross(helper, cap.normal);
  e1 = e1 / length(e1);
  const Vec3d e2 = cross(cap.normal, e1);
  std::vector<Point2> p(n);
  std::vector<std::uint32_t> vertex(n);
  for (std::size_t i = 0; i < n; ++i) {  // the rim reversed: the cap's own order
    const std::uint32_t v = rim[n - 1 - i];
    const Vec3d d = positions[v] - origin;
    p[i] = {dot(d, e1), dot(d, e2)};
    vertex[i] = v;
  }
  if (!is_simple(p)) {
    cap.refused = "the rim crosses itself in its plane: a cap would intersect itself";
    return cap;
  }
  for (const auto& t : clip_ears(p))
    cap.triangles.push_back({vertex[t[0]], vertex[t[1]], vertex[t[2]]});
  return cap;
}

}  // namespace pgamesh
