// Test helpers for the mesh readers: reading from a string, catching the expected InputError, and
// building binary STL bytes by hand (independently of the library's writer).
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh::test {

inline Mesh read_text(std::string_view text, MeshSource* source = nullptr,
                      MeshFormat format = MeshFormat::unknown) {
  return read_mesh_bytes({text.data(), text.size()}, "mem", source, format);
}

// The InputError that reading `bytes` must raise; a test failure (and an empty error) otherwise.
inline InputError read_error(std::string_view bytes, MeshFormat format = MeshFormat::unknown) {
  try {
    read_mesh_bytes({bytes.data(), bytes.size()}, "mem", nullptr, format);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", {}, "");
}

inline bool mentions(const InputError& e, std::string_view text) {
  return std::string_view(e.what()).find(text) != std::string_view::npos;
}

// Expects a text error at line:column whose message contains `text`.
#define EXPECT_TEXT_ERROR(err, ln, col, text)                      \
  do {                                                             \
    const ::pgamesh::InputError& e_ = (err);                       \
    EXPECT_TRUE(e_.where().has_line) << e_.what();                 \
    EXPECT_EQ(e_.where().line, ln) << e_.what();                   \
    EXPECT_EQ(e_.where().column, col) << e_.what();                \
    EXPECT_TRUE(::pgamesh::test::mentions(e_, text)) << e_.what(); \
  } while (0)

// Expects a binary error at byte `offset` whose message contains `text`.
#define EXPECT_BYTE_ERROR(err, offset, text)                       \
  do {                                                             \
    const ::pgamesh::InputError& e_ = (err);                       \
    EXPECT_FALSE(e_.where().has_line) << e_.what();                \
    EXPECT_EQ(e_.where().byte_offset, offset) << e_.what();        \
    EXPECT_TRUE(::pgamesh::test::mentions(e_, text)) << e_.what(); \
  } while (0)

// A binary STL built byte by byte: 80-byte header, `declared` count, then one record per
// triangle (zero normal, nine float32 coordinates, two attribute bytes).
inline std::string binary_stl(const std::vector<std::array<float, 9>>& triangles,
                              std::uint32_t declared, std::string header = "test") {
  header.resize(80, '\0');
  std::string out = header;
  for (int k = 0; k < 4; ++k) out += static_cast<char>((declared >> (8 * k)) & 0xFF);
  for (const auto& t : triangles) {
    out.append(12, '\0');
    for (float f : t) {
      std::uint32_t u;
      std::memcpy(&u, &f, 4);
      for (int k = 0; k < 4; ++k) out += static_cast<char>((u >> (8 * k)) & 0xFF);
    }
    out.append(2, '\0');
  }
  return out;
}

// Path of a file in ../shared/meshes, or empty (and the test is skipped) when it is absent.
inline std::string shared_mesh(const std::string& relative) {
  const std::string path = std::string(PGAMESH_SHARED_MESHES_DIR) + "/" + relative;
  if (!std::filesystem::exists(path)) return {};
  return path;
}

#define SHARED_MESH_OR_SKIP(var, relative)                        \
  const std::string var = ::pgamesh::test::shared_mesh(relative); \
  if (var.empty()) GTEST_SKIP() << "shared mesh " << (relative) << " is absent"

// For an extra test of one third-party file that is not bundled (its licence): the path, or the
// test is skipped, and says so, when the file is absent. A test of our own input covers its
// property on a lone clone and never skips.
#define SHARED_MESH_EXTRA(var, relative)                                                      \
  const std::string var = ::pgamesh::test::shared_mesh(relative);                             \
  if (var.empty())                                                                            \
  GTEST_SKIP() << "extra test of " << (relative)                                              \
               << " (not bundled, comes with ../shared/meshes); its property is tested on a " \
                  "mesh of our own"

// Six times the signed volume: Σ det(v0, vi, vi+1) over the fan of every face (o ∨ F,
// docs/conventions.md §5).
inline double six_volume(const Mesh& m) {
  double s = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const auto* c = m.face(f);
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      const Vec3d a = m.vertices[c[0]], b = m.vertices[c[k]], d = m.vertices[c[k + 1]];
      s += a.x * (b.y * d.z - b.z * d.y) - a.y * (b.x * d.z - b.z * d.x) +
           a.z * (b.x * d.y - b.y * d.x);
    }
  }
  return s;
}

}  // namespace pgamesh::test
