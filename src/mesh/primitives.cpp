#include "pgamesh/mesh/primitives.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pgamesh {

namespace {

// A closed surface of revolution about z from a profile (radius, z) that starts and ends on the
// axis (the two poles): one vertex per pole, `segments` vertices per interior profile point.
Mesh revolve(const std::vector<std::pair<double, double>>& profile, int segments) {
  if (segments < 3 || profile.size() < 3)
    throw std::invalid_argument("revolve: need at least 3 segments and 3 profile points");
  Mesh m;
  const auto rings = static_cast<std::uint32_t>(profile.size() - 2);
  const auto seg = static_cast<std::uint32_t>(segments);
  m.vertices.push_back({0, 0, profile.front().second});
  for (std::uint32_t k = 1; k <= rings; ++k)
    for (std::uint32_t j = 0; j < seg; ++j) {
      const double phi = 2 * std::numbers::pi * j / seg;
      const double r = profile[k].first;
      m.vertices.push_back({r * std::cos(phi), r * std::sin(phi), profile[k].second});
    }
  m.vertices.push_back({0, 0, profile.back().second});
  const std::uint32_t top = static_cast<std::uint32_t>(m.vertices.size() - 1);
  auto ring = [&](std::uint32_t k, std::uint32_t j) { return 1 + (k - 1) * seg + j % seg; };
  for (std::uint32_t j = 0; j < seg; ++j) m.add_face({0, ring(1, j + 1), ring(1, j)});
  for (std::uint32_t k = 1; k < rings; ++k)
    for (std::uint32_t j = 0; j < seg; ++j) {
      m.add_face({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      m.add_face({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
    }
  for (std::uint32_t j = 0; j < seg; ++j) m.add_face({top, ring(rings, j), ring(rings, j + 1)});
  return m;
}

}  // namespace

Mesh icosphere(int level, double radius) {
  if (level < 0 || level > 10) throw std::invalid_argument("icosphere: level must be in 0..10");
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                          {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                          {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3d& p : v) p = p / length(p);
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const Vec3d p = v[a] + v[b];
      v.push_back(p / length(p));
      const auto id = static_cast<std::uint32_t>(v.size() - 1);
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    next.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const std::uint32_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]),
                          ca = mid(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  Mesh m;
  m.vertices.reserve(v.size());
  for (const Vec3d& p : v) m.vertices.push_back(radius * p);
  for (const auto& tri : f) m.add_face({tri[0], tri[1], tri[2]});
  return m;
}

Mesh box(double a, double b, double c) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(
        {(i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * b, (i & 4 ? 0.5 : -0.5) * c});
  // Each quad CCW seen from outside, split along its first diagonal.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {1, 3, 7, 5}, {0, 4, 6, 2}};
  for (const auto& q : quads) {
    m.add_face({q[0], q[1], q[2]});
    m.add_face({q[0], q[2], q[3]});
  }
  return m;
}

Mesh cylinder(double radius, double height, int segments, int rings) {
  if (rings < 1) throw std::invalid_argument("cylinder: need at least one ring");
  std::vector<std::pair<double, double>> profile = {{0.0, -height / 2}};
  for (int k = 0; k <= rings; ++k) profile.push_back({radius, -height / 2 + height * k / rings});
  profile.push_back({0.0, height / 2});
  return revolve(profile, segments);
}

Mesh capsule(double radius, double length, int segments, int rings) {
  if (rings < 1) throw std::invalid_argument("capsule: need at least one ring");
  std::vector<std::pair<double, double>> profile = {{0.0, -length / 2 - radius}};
  for (int k = 1; k <= rings; ++k) {  // lower hemisphere, from the pole up to the equator
    const double a = std::numbers::pi / 2 * (1 - double(k) / rings);
    profile.push_back({radius * std::cos(a), -length / 2 - radius * std::sin(a)});
  }
  for (int k = 0; k < rings; ++k) {  // upper hemisphere, from the equator up to the pole
    const double a = std::numbers::pi / 2 * double(k) / rings;
    profile.push_back({radius * std::cos(a), length / 2 + radius * std::sin(a)});
  }
  profile.push_back({0.0, length / 2 + radius});
  return revolve(profile, segments);
}

}  // namespace pgamesh
