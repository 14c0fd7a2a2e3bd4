// Shared body of the reader harnesses: read the bytes with a forced (or detected) format; bad
// input must end in InputError, and whatever is accepted must be a well-formed Mesh — finite
// vertices, corner indices in range, monotonic face offsets with at least 3 corners per face —
// that survives a write/read round trip through OBJ unchanged.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"

namespace pgamesh::fuzz {

inline void require(bool ok) {
  if (!ok) __builtin_trap();
}

// Whether two doubles have the same bits (NaNs and the sign of zero included): the harnesses that
// hold two paths to one result compare them so.
inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

inline void check_mesh(const Mesh& m) {
  require(!m.face_offsets.empty() && m.face_offsets.front() == 0);
  require(m.face_offsets.back() == m.corners.size());
  for (std::size_t f = 0; f < m.face_count(); ++f) require(m.face_size(f) >= 3);
  for (std::uint32_t c : m.corners) require(c < m.vertices.size());
  for (const Vec3d& v : m.vertices)
    require(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

inline int read_bytes(const std::uint8_t* data, std::size_t size, MeshFormat format) {
  Mesh m;
  try {
    MeshSource src;
    m = read_mesh_bytes({reinterpret_cast<const char*>(data), size}, "fuzz", &src, format);
  } catch (const InputError&) {
    return 0;  // rejected with a position: the expected outcome for most inputs
  }
  check_mesh(m);
  if (m.corners.size() > 100000) return 0;  // keep each run short
  const std::string obj = write_mesh_bytes(m, MeshFormat::obj);
  const Mesh back =
      read_mesh_bytes({obj.data(), obj.size()}, "fuzz-roundtrip", nullptr, MeshFormat::obj);
  require(back.corners == m.corners && back.face_offsets == m.face_offsets);
  require(back.vertices.size() == m.vertices.size());
  require(m.vertices.empty() || std::memcmp(back.vertices.data(), m.vertices.data(),
                                            m.vertices.size() * sizeof(Vec3d)) == 0);
  return 0;
}

}  // namespace pgamesh::fuzz
