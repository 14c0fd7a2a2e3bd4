// Small meshes built in code for the topology tests, with their expected properties known in
// closed form.
#pragma once

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh::test {

// The unit cube [0,1]³ as 12 outward (CCW from outside) triangles, vertex i = (i&1, i>>1&1,
// i>>2&1), faces in the order of golden/meshes/unit_cube.obj: z=0 (0,1), z=1 (2,3), y=0 (4,5), y=1
// (6,7), x=0 (8,9), x=1 (10,11).
inline Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const std::uint32_t f[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                  {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& t : f) m.add_face({t[0], t[1], t[2]});
  return m;
}

// The unit cube as 6 quads (n-gon faces).
inline Mesh unit_cube_quads() {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.add_face({0, 2, 3, 1});
  m.add_face({4, 5, 7, 6});
  m.add_face({0, 1, 5, 4});
  m.add_face({2, 6, 7, 3});
  m.add_face({0, 4, 6, 2});
  m.add_face({1, 3, 7, 5});
  return m;
}

// Every face gets fresh copies of its vertices, as an STL reader produces them.
inline Mesh unshared(const Mesh& in) {
  Mesh m;
  for (std::size_t f = 0; f < in.face_count(); ++f) {
    for (std::size_t i = 0; i < in.face_size(f); ++i) {
      m.corners.push_back(static_cast<std::uint32_t>(m.vertices.size()));
      m.vertices.push_back(in.vertices[in.face(f)[i]]);
    }
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  }
  return m;
}

inline Mesh without_faces(const Mesh& in, std::set<std::size_t> drop) {
  Mesh m;
  m.vertices = in.vertices;
  for (std::size_t f = 0; f < in.face_count(); ++f) {
    if (drop.count(f)) continue;
    m.corners.insert(m.corners.end(), in.face(f), in.face(f) + in.face_size(f));
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  }
  return m;
}

inline Mesh translated(Mesh m, Vec3d t) {
  for (auto& v : m.vertices) v += t;
  return m;
}

// The faces of b appended to a (b's vertices appended too).
inline Mesh merged(Mesh a, const Mesh& b) {
  const auto base = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (std::size_t f = 0; f < b.face_count(); ++f) {
    for (std::size_t i = 0; i < b.face_size(f); ++i) a.corners.push_back(b.face(f)[i] + base);
    a.face_offsets.push_back(static_cast<std::uint32_t>(a.corners.size()));
  }
  return a;
}

// Reverses the listed faces (keeping each face's first corner).
inline Mesh with_flipped(Mesh m, std::initializer_list<std::size_t> faces) {
  for (std::size_t f : faces)
    std::reverse(m.corners.begin() + m.face_offsets[f] + 1,
                 m.corners.begin() + m.face_offsets[f + 1]);
  return m;
}

}  // namespace pgamesh::test
