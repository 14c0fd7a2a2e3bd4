#include "solids.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pgamesh::test {

Mesh box_mesh(double a, double b, double c) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
  m.add_face({0, 3, 2, 1});
  m.add_face({4, 5, 6, 7});
  m.add_face({0, 1, 5, 4});
  m.add_face({2, 3, 7, 6});
  m.add_face({1, 2, 6, 5});
  m.add_face({0, 4, 7, 3});
  return m;
}

Mesh tetrahedron_mesh(Vec3d p0, Vec3d p1, Vec3d p2, Vec3d p3) {
  Mesh m;
  m.vertices = {p0, p1, p2, p3};
  if (dot(cross(p1 - p0, p2 - p0), p3 - p0) > 0) std::swap(m.vertices[1], m.vertices[2]);
  m.add_face({0, 1, 2});
  m.add_face({0, 3, 1});
  m.add_face({1, 3, 2});
  m.add_face({0, 2, 3});
  return m;
}

Mesh uv_sphere(double r, int stacks, int slices) {
  Mesh m;
  const double pi = std::numbers::pi;
  m.vertices.push_back({0, 0, r});  // north pole
  for (int i = 1; i < stacks; ++i) {
    const double theta = pi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double phi = 2 * pi * j / slices;
      m.vertices.push_back({r * std::sin(theta) * std::cos(phi),
                            r * std::sin(theta) * std::sin(phi), r * std::cos(theta)});
    }
  }
  m.vertices.push_back({0, 0, -r});  // south pole
  const auto ring = [&](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * slices + (j % slices));
  };
  const auto south = static_cast<std::uint32_t>(m.vertices.size() - 1);
  for (int j = 0; j < slices; ++j) m.add_face({0, ring(1, j), ring(1, j + 1)});
  for (int i = 1; i + 1 < stacks; ++i)
    for (int j = 0; j < slices; ++j)
      m.add_face({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)});
  for (int j = 0; j < slices; ++j)
    m.add_face({ring(stacks - 1, j), south, ring(stacks - 1, j + 1)});
  return m;
}

Mesh transformed(const Mesh& m, const std::function<Vec3d(Vec3d)>& f) {
  Mesh out = m;
  for (Vec3d& v : out.vertices) v = f(v);
  return out;
}

Mesh flipped(const Mesh& m) {
  Mesh out = m;
  for (std::size_t f = 0; f < out.face_count(); ++f) {
    auto* c = out.corners.data() + out.face_offsets[f];
    std::reverse(c, c + out.face_size(f));
  }
  return out;
}

Mesh triangulated(const Mesh& m) {
  Mesh out;
  out.vertices = m.vertices;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const std::uint32_t* c = m.face(f);
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) out.add_face({c[0], c[k], c[k + 1]});
  }
  return out;
}

}  // namespace pgamesh::test
