// Zero-copy access to a binary STL: the 80-byte header, a little-endian uint32 triangle count, then
// one 50-byte record per triangle (normal 3 × float32, three vertices 3 × float32, 2 attribute
// bytes). The fast mass-property path walks the records directly; read_mesh() builds a Mesh from
// it.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>

#include "pgamesh/algebra/vec3.hpp"

namespace pgamesh {

inline constexpr std::size_t stl_header_bytes = 84;  // 80-byte header + uint32 count
inline constexpr std::size_t stl_record_bytes = 50;

struct BinaryStlView {
  const unsigned char* records;  // first record (byte 84 of the file)
  std::uint64_t count;           // number of 50-byte records
};

// The binary-STL reading of `bytes`, decided by size arithmetic (84 + 50 × count == size), never
// by the first word: a binary header may begin with "solid". Returns nullopt when the bytes are not
// a binary STL (an ASCII STL, another format). Throws InputError naming `name` when they are a
// binary STL but broken: shorter than the 84-byte header, or a header count that disagrees with the
// size (both numbers are in the message; the file is not guessed at — see docs/formats.md).
// Coordinates are not checked here; see check_binary_stl_finite().
std::optional<BinaryStlView> binary_stl_view(std::span<const char> bytes, const std::string& name);

// The three vertices of one 50-byte record, float32 little-endian widened to double. The normal
// is ignored: the vertex order is the truth.
inline void stl_triangle(const unsigned char* record, Vec3d out[3]) {
  static_assert(sizeof(float) == 4);
  float f[9];
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(f, record + 12, sizeof f);
  } else {
    for (int i = 0; i < 9; ++i) {
      std::uint32_t u;
      std::memcpy(&u, record + 12 + 4 * i, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&f[i], &u, 4);
    }
  }
  for (int k = 0; k < 3; ++k) out[k] = {f[3 * k], f[3 * k + 1], f[3 * k + 2]};
}

// Throws InputError (byte offset of the first bad float) when any vertex coordinate of the view is
// NaN or infinite. Cheap enough to run up front; a fused accumulation may instead call it only when
// its result is not finite, to name the culprit.
void check_binary_stl_finite(const BinaryStlView& view, const std::string& name);

}  // namespace pgamesh
