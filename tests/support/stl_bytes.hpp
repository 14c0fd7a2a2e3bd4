// Binary STL bytes (float32 coordinates, normals left zero) and ASCII STL text of a mesh built in
// memory, for tests of the STL readers and the streamed STL path.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh::test {

// The binary STL of the mesh's faces, fanned about their first corner.
inline std::vector<char> binary_stl_bytes(const Mesh& m) {
  std::vector<char> out(80, ' ');
  std::uint32_t count = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f)
    if (m.face_size(f) >= 3) count += static_cast<std::uint32_t>(m.face_size(f) - 2);
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((count >> (8 * k)) & 0xff));
  const auto put = [&](float v) {
    char b[4];
    std::memcpy(b, &v, 4);  // the test machines are little-endian, as STL is
    out.insert(out.end(), b, b + 4);
  };
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const std::uint32_t* c = m.face(f);
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      for (int i = 0; i < 3; ++i) put(0.0f);
      for (const std::uint32_t idx : {c[0], c[k], c[k + 1]}) {
        const Vec3d& v = m.vertices[idx];
        put(static_cast<float>(v.x));
        put(static_cast<float>(v.y));
        put(static_cast<float>(v.z));
      }
      out.push_back(0);
      out.push_back(0);
    }
  }
  return out;
}

// The ASCII STL of the mesh's faces, fanned as binary_stl_bytes does, each coordinate printed
// with 7 significant digits (%.6e), as many exporters write them.
inline std::string ascii_stl_text(const Mesh& m) {
  std::string out = "solid test\n";
  char line[128];
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const std::uint32_t* c = m.face(f);
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      out += "facet normal 0 0 0\nouter loop\n";
      for (const std::uint32_t idx : {c[0], c[k], c[k + 1]}) {
        const Vec3d& v = m.vertices[idx];
        std::snprintf(line, sizeof line, "vertex %.6e %.6e %.6e\n", v.x, v.y, v.z);
        out += line;
      }
      out += "endloop\nendfacet\n";
    }
  }
  return out + "endsolid test\n";
}

}  // namespace pgamesh::test
