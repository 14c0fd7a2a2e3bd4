#include "support/reference_self_intersections.hpp"

#ifdef PGAMESH_HAVE_GMP

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <set>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh::test {

namespace {

using RationalPoint = Vec3<mpq_class>;

RationalPoint rational_point(const Vec3d& p) {
  return {mpq_class(p.x), mpq_class(p.y), mpq_class(p.z)};
}

struct RationalFanTriangle {
  std::uint32_t face;
  std::array<std::uint32_t, 3> v;
  std::array<RationalPoint, 3> p;
  std::array<double, 3> lo, hi;  // the corners' box, for a quick exact rejection
};

bool is_zero_vector(const RationalPoint& a) {
  return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0;
}

// The points of `polygon` (a convex polygon, segment or point, as a cycle) with h ≥ 0, h affine.
template <class H>
std::vector<RationalPoint> clip_by_half_space(const std::vector<RationalPoint>& polygon,
                                              const H& h) {
  std::vector<RationalPoint> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const RationalPoint& p = polygon[i];
    const RationalPoint& q = polygon[(i + 1) % polygon.size()];
    const mpq_class hp = h(p), hq = h(q);
    if (sgn(hp) >= 0) out.push_back(p);
    if ((sgn(hp) > 0 && sgn(hq) < 0) || (sgn(hp) < 0 && sgn(hq) > 0)) {
      const mpq_class t = hp / (hp - hq);
      out.push_back(p + (q - p) * t);
    }
  }
  return out;
}

// Whether triangles t and u meet beyond the hull of the welded vertices they share.
bool fan_triangles_meet(const RationalFanTriangle& t, const RationalFanTriangle& u) {
  std::vector<std::uint32_t> shared;
  for (std::uint32_t a : t.v)
    if (std::find(u.v.begin(), u.v.end(), a) != u.v.end()) shared.push_back(a);
  if (shared.size() == 3) return true;  // the same triangle
  const RationalPoint& a = u.p[0];
  const RationalPoint n = cross(u.p[1] - u.p[0], u.p[2] - u.p[0]);
  std::vector<RationalPoint> part(t.p.begin(), t.p.end());
  part = clip_by_half_space(part, [&](const RationalPoint& x) { return mpq_class(dot(n, x - a)); });
  part =
      clip_by_half_space(part, [&](const RationalPoint& x) { return mpq_class(-dot(n, x - a)); });
  for (int k = 0; k < 3 && !part.empty(); ++k) {
    const RationalPoint& e0 = u.p[k];
    const RationalPoint inward = cross(n, u.p[(k + 1) % 3] - e0);
    part = clip_by_half_space(
        part, [&](const RationalPoint& x) { return mpq_class(dot(inward, x - e0)); });
  }
  auto position = [&](std::uint32_t v) {
    for (int k = 0; k < 3; ++k)
      if (t.v[k] == v) return t.p[k];
    return t.p[0];
  };
  for (const RationalPoint& x : part) {
    if (shared.empty()) return true;
    const RationalPoint s0 = position(shared[0]);
    if (shared.size() == 1) {
      if (!(x == s0)) return true;
      continue;
    }
    const RationalPoint s1 = position(shared[1]);
    const RationalPoint d = s1 - s0;
    if (!is_zero_vector(cross(d, x - s0))) return true;
    const mpq_class along = dot(x - s0, d);
    if (sgn(along) < 0 || along > dot(d, d)) return true;
  }
  return false;
}

bool corner_boxes_overlap(const RationalFanTriangle& t, const RationalFanTriangle& u) {
  for (int k = 0; k < 3; ++k)
    if (t.lo[k] > u.hi[k] || u.lo[k] > t.hi[k]) return false;
  return true;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> reference_self_intersections(
    const Mesh& mesh) {
  const WeldResult welded = weld(mesh);
  const Mesh& m = welded.mesh;
  std::vector<RationalFanTriangle> fan;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const std::uint32_t* c = m.face(f);
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      RationalFanTriangle t;
      t.face = static_cast<std::uint32_t>(f);
      t.v = {c[0], c[k], c[k + 1]};
      for (int i = 0; i < 3; ++i) {
        const Vec3d& x = m.vertices[t.v[i]];
        t.p[i] = rational_point(x);
        for (int a = 0; a < 3; ++a) {
          t.lo[a] = i == 0 ? x[a] : std::min(t.lo[a], x[a]);
          t.hi[a] = i == 0 ? x[a] : std::max(t.hi[a], x[a]);
        }
      }
      if (is_zero_vector(cross(t.p[1] - t.p[0], t.p[2] - t.p[0]))) continue;  // collinear: left out
      fan.push_back(t);
    }
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < fan.size(); ++i)
    for (std::size_t j = i + 1; j < fan.size(); ++j) {
      const RationalFanTriangle &t = fan[i], &u = fan[j];
      if (t.face == u.face || !corner_boxes_overlap(t, u)) continue;
      const auto key = std::minmax(t.face, u.face);
      if (pairs.count(key)) continue;
      if (fan_triangles_meet(t, u)) pairs.insert(key);  // t clipped by u is t ∩ u
    }
  return {pairs.begin(), pairs.end()};
}

}  // namespace pgamesh::test

#endif
