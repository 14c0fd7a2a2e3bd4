// Zero-copy access to a binary STL: the 80-byte header, a little-endian uint32 triangle count, then
// one 50-byte record per triangle (normal 3 × float32, three vertices 3 × float32, 2 attribute
// bytes). The fast mass-property path walks the records directly; read_mesh() builds a Mesh from
// it. The same passes walk any array of float32 triangles laid out as records: a GLB's tightly
// packed POSITION accessor of a non-indexed triangle list is one of 36-byte records
// (docs/formats.md, "glTF 2.0").
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "detail/simd/double4.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

inline constexpr std::size_t stl_header_bytes = 84;  // 80-byte header + uint32 count
inline constexpr std::size_t stl_record_bytes = 50;

// Where a triangle's nine float32 little-endian coordinates (x y z of its three vertices) lie in
// an array of records: record i begins `stride` bytes after record i − 1, its coordinates `coords`
// bytes into it. The passes are compiled for each layout below (the four-record gather needs
// constant offsets), chosen once per file by with_record_layout().
struct TriangleRecordLayout {
  std::size_t stride;
  std::size_t coords;
  friend constexpr bool operator==(const TriangleRecordLayout&,
                                   const TriangleRecordLayout&) = default;
};
// A binary STL's record: normal, three vertices, attribute bytes.
inline constexpr TriangleRecordLayout stl_record_layout{stl_record_bytes, 12};
// Three tightly packed float32 VEC3 positions: a glTF POSITION accessor (byteStride 12) of a
// non-indexed triangle list.
inline constexpr TriangleRecordLayout packed_triangle_layout{36, 0};

template <TriangleRecordLayout L>
struct RecordLayoutTag {
  static constexpr TriangleRecordLayout layout = L;
};

// f(RecordLayoutTag<L>{}) for the layout L equal to `layout`; std::invalid_argument for another.
template <class F>
decltype(auto) with_record_layout(const TriangleRecordLayout& layout, F&& f) {
  if (layout == stl_record_layout) return f(RecordLayoutTag<stl_record_layout>{});
  if (layout == packed_triangle_layout) return f(RecordLayoutTag<packed_triangle_layout>{});
  throw std::invalid_argument("no streamed pass for a record of " + std::to_string(layout.stride) +
                              " bytes with coordinates at byte " + std::to_string(layout.coords));
}

struct BinaryStlView {
  const unsigned char* records;  // first record (byte 84 of the file)
  std::uint64_t count;           // number of records (triangles)
  // An open descriptor of the file these bytes map (MappedFile::descriptor()), or −1. When set,
  // the streamed passes (binary_stl_mass_properties, weld_binary_stl) read the records with pread
  // in blocks instead of touching the mapping: on a virtual machine each first touch of a mapped
  // page can cost microseconds, a copy through a small buffer a fraction of that.
  int file = -1;
  // The records' layout, and the byte offset of the first one in the file (where pread reads it
  // and errors name it): a binary STL's unless the view is of another array of triangles.
  TriangleRecordLayout layout = stl_record_layout;
  std::uint64_t first_record_offset = stl_header_bytes;
};

// The binary-STL reading of `bytes`, decided by size arithmetic (84 + 50 × count == size), never
// by the first word: a binary header may begin with "solid". Returns nullopt when the bytes are not
// a binary STL (an ASCII STL, another format). Throws InputError naming `name` when they are a
// binary STL but broken: shorter than the 84-byte header, or a header count that disagrees with the
// size (both numbers are in the message; the file is not guessed at — see docs/formats.md).
// Coordinates are not checked here; see check_binary_stl_finite().
std::optional<BinaryStlView> binary_stl_view(std::span<const char> bytes, const std::string& name);

// The nine vertex coordinates of one record of layout L (a 50-byte STL record unless told),
// float32 little-endian, in the host's order. An STL's normal is ignored: the vertex order is the
// truth.
template <TriangleRecordLayout L = stl_record_layout>
inline void stl_record_floats(const unsigned char* record, float f[9]) {
  static_assert(sizeof(float) == 4);
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(f, record + L.coords, 9 * sizeof(float));
  } else {
    for (int i = 0; i < 9; ++i) {
      std::uint32_t u;
      std::memcpy(&u, record + L.coords + 4 * i, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&f[i], &u, 4);
    }
  }
}

// The three vertices of one record, widened to double.
template <TriangleRecordLayout L = stl_record_layout>
inline void stl_triangle(const unsigned char* record, Vec3d out[3]) {
  float f[9];
  stl_record_floats<L>(record, f);
  for (int k = 0; k < 3; ++k) out[k] = {f[3 * k], f[3 * k + 1], f[3 * k + 2]};
}

// The vertices of four consecutive records, lane j holding record j (as stl_triangle reads it).
template <TriangleRecordLayout L = stl_record_layout>
inline void stl_triangles4(const unsigned char* records, Vec3<Double4> out[3]) {
  using Pair = Double4::Pair;
  // The loads below end with the coordinates: never past the last record of an array.
  static_assert(L.coords + 9 * sizeof(float) <= L.stride);
  if constexpr (std::endian::native == std::endian::little) {
    // Each record's nine floats as five widened pairs (f0 f1) (f2 f3) (f4 f5) (f6 f7) (f7 f8),
    // from three 16-byte loads inside the coordinates (bytes 0–16, 16–32, 20–36 of their 36: of
    // an STL record, bytes 12–28, 28–44, 32–48 of its 50).
    using Float4 = float __attribute__((vector_size(16)));
    Pair p[4][5];
    for (int r = 0; r < 4; ++r) {
      const unsigned char* rec = records + L.stride * r + L.coords;
      Float4 a, b, c8;
      std::memcpy(&a, rec, 16);
      std::memcpy(&b, rec + 16, 16);
      std::memcpy(&c8, rec + 20, 16);
      p[r][0] = __builtin_convertvector(__builtin_shufflevector(a, a, 0, 1), Pair);
      p[r][1] = __builtin_convertvector(__builtin_shufflevector(a, a, 2, 3), Pair);
      p[r][2] = __builtin_convertvector(__builtin_shufflevector(b, b, 0, 1), Pair);
      p[r][3] = __builtin_convertvector(__builtin_shufflevector(b, b, 2, 3), Pair);
      p[r][4] = __builtin_convertvector(__builtin_shufflevector(c8, c8, 2, 3), Pair);
    }
    // Coordinate j of records (0, 1) and (2, 3): element j % 2 of pair j / 2 (j = 8: element 1 of
    // pair 4), gathered across the records.
    Double4 coord[9];
    for (int j = 0; j < 9; ++j) {
      const int q = j < 8 ? j / 2 : 4;
      const bool second = j < 8 ? (j % 2 == 1) : true;
      coord[j] = second ? Double4(__builtin_shufflevector(p[0][q], p[1][q], 1, 3),
                                  __builtin_shufflevector(p[2][q], p[3][q], 1, 3))
                        : Double4(__builtin_shufflevector(p[0][q], p[1][q], 0, 2),
                                  __builtin_shufflevector(p[2][q], p[3][q], 0, 2));
    }
    for (int k = 0; k < 3; ++k) out[k] = {coord[3 * k], coord[3 * k + 1], coord[3 * k + 2]};
  } else {
    float f[4][9];
    for (int j = 0; j < 4; ++j) stl_record_floats<L>(records + L.stride * j, f[j]);
    for (int k = 0; k < 3; ++k)
      out[k] = {Double4(f[0][3 * k], f[1][3 * k], f[2][3 * k], f[3][3 * k]),
                Double4(f[0][3 * k + 1], f[1][3 * k + 1], f[2][3 * k + 1], f[3][3 * k + 1]),
                Double4(f[0][3 * k + 2], f[1][3 * k + 2], f[2][3 * k + 2], f[3][3 * k + 2])};
  }
}

// Throws InputError (byte offset in the file of the first bad float, whatever the view's layout)
// when any vertex coordinate of the view is NaN or infinite. Cheap enough to run up front; a fused
// accumulation may instead call it only when its result is not finite, to name the culprit.
void check_binary_stl_finite(const BinaryStlView& view, const std::string& name);

}  // namespace pgamesh
