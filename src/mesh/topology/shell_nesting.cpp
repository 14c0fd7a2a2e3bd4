#include "pgamesh/mesh/topology/shell_nesting.hpp"

#include <algorithm>
#include <numbers>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh {

namespace {

// The solid angle of the triangle (a, b, c) seen from the origin, signed by the triangle's
// orientation (Van Oosterom and Strackee): positive when the origin is on the side its
// counter-clockwise normal points away from.
double nesting_solid_angle(Vec3d a, Vec3d b, Vec3d c) {
  const double la = length(a), lb = length(b), lc = length(c);
  const double numerator = dot(a, cross(b, c));
  const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2 * std::atan2(numerator, denominator);
}

// Whether a winding number w (turns, not steradians) says "inside": its nearest integer is odd
// (parity, so either orientation of the other shell counts). Within 1/4 of a half-integer the
// point lies on the other shell's surface: counted as outside (docs/conventions.md §8).
bool winding_says_inside(double w) {
  const double nearest = std::round(w);
  if (!(std::abs(w - nearest) < 0.25)) return false;
  return std::fmod(std::abs(nearest), 2.0) == 1.0;
}

}  // namespace

std::vector<std::uint32_t> shell_depths(std::span<const std::uint32_t> face_component,
                                        std::span<const std::uint8_t> is_shell,
                                        const FaceCorners& corners) {
  const std::size_t n = is_shell.size();
  std::vector<std::uint32_t> depth(n, 0);
  std::vector<std::uint32_t> shell_of(n, no_edge);  // component → shell number
  std::vector<std::uint32_t> component_of;          // shell number → component
  for (std::size_t k = 0; k < n; ++k)
    if (is_shell[k]) {
      shell_of[k] = static_cast<std::uint32_t>(component_of.size());
      component_of.push_back(static_cast<std::uint32_t>(k));
    }
  const std::size_t shells = component_of.size();
  if (shells < 2) return depth;  // the common case: nothing to read

  // Pass 1: each shell's bounding box and test point (the centroid of its first fan triangle of
  // non-zero area, in face order).
  std::vector<Box3> box(shells);
  std::vector<Vec3d> point(shells);
  std::vector<std::uint8_t> has_point(shells, 0);
  std::vector<Vec3d> p;
  for (std::size_t f = 0; f < face_component.size(); ++f) {
    const std::uint32_t k = face_component[f];
    if (k == no_edge || shell_of[k] == no_edge) continue;
    const std::uint32_t s = shell_of[k];
    corners(static_cast<std::uint32_t>(f), p);
    for (const Vec3d& q : p) box[s].add(q);
    for (std::size_t i = 2; i < p.size() && !has_point[s]; ++i) {
      const Vec3d normal = cross(p[i - 1] - p[0], p[i] - p[0]);
      if (normal.x == 0 && normal.y == 0 && normal.z == 0) continue;
      point[s] = (p[0] + p[i - 1] + p[i]) / 3.0;
      has_point[s] = 1;
    }
  }

  // The shells whose test point lies in shell s's box: the only ones s can hold. The points
  // sorted by x, each box looks only at those in its x range (many separate parts stay cheap).
  std::vector<std::uint32_t> by_x;
  for (std::size_t a = 0; a < shells; ++a)
    if (has_point[a]) by_x.push_back(static_cast<std::uint32_t>(a));
  std::sort(by_x.begin(), by_x.end(),
            [&](std::uint32_t a, std::uint32_t b) { return point[a].x < point[b].x; });
  std::vector<std::vector<std::uint32_t>> candidates(shells);
  for (std::size_t s = 0; s < shells; ++s) {
    const Box3& b = box[s];
    auto first = std::lower_bound(by_x.begin(), by_x.end(), b.lo.x,
                                  [&](std::uint32_t a, double x) { return point[a].x < x; });
    for (auto it = first; it != by_x.end() && point[*it].x <= b.hi.x; ++it) {
      const Vec3d q = point[*it];
      if (*it != s && q.y >= b.lo.y && q.y <= b.hi.y && q.z >= b.lo.z && q.z <= b.hi.z)
        candidates[s].push_back(*it);
    }
  }

  // Pass 2: winding[s][i] = Σ solid angles of s's fan triangles about candidates[s][i].
  std::vector<std::vector<double>> winding(shells);
  for (std::size_t s = 0; s < shells; ++s) winding[s].assign(candidates[s].size(), 0.0);
  for (std::size_t f = 0; f < face_component.size(); ++f) {
    const std::uint32_t k = face_component[f];
    if (k == no_edge || shell_of[k] == no_edge) continue;
    const std::uint32_t s = shell_of[k];
    if (candidates[s].empty()) continue;
    corners(static_cast<std::uint32_t>(f), p);
    for (std::size_t i = 0; i < candidates[s].size(); ++i) {
      const Vec3d q = point[candidates[s][i]];
      for (std::size_t j = 2; j < p.size(); ++j)
        winding[s][i] += nesting_solid_angle(p[0] - q, p[j - 1] - q, p[j] - q);
    }
  }
  for (std::size_t s = 0; s < shells; ++s)
    for (std::size_t i = 0; i < candidates[s].size(); ++i)
      if (winding_says_inside(winding[s][i] / (4 * std::numbers::pi)))
        ++depth[component_of[candidates[s][i]]];
  return depth;
}

}  // namespace pgamesh
