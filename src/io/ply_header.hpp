// Internal: the header of a PLY file (its elements, their properties and types) and the loading of
// binary values, shared by the PLY reader (read_ply.cpp) and the topology pass that re-reads a
// binary PLY's faces from the file (ply_topology.cpp).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/text_cursor.hpp"
#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh::detail {

enum class PlyType { none, i8, u8, i16, u16, i32, u32, f32, f64 };

inline PlyType ply_type(std::string_view w) {
  if (w == "char" || w == "int8") return PlyType::i8;
  if (w == "uchar" || w == "uint8") return PlyType::u8;
  if (w == "short" || w == "int16") return PlyType::i16;
  if (w == "ushort" || w == "uint16") return PlyType::u16;
  if (w == "int" || w == "int32") return PlyType::i32;
  if (w == "uint" || w == "uint32") return PlyType::u32;
  if (w == "float" || w == "float32") return PlyType::f32;
  if (w == "double" || w == "float64") return PlyType::f64;
  return PlyType::none;
}

inline std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::i8:
    case PlyType::u8:
      return 1;
    case PlyType::i16:
    case PlyType::u16:
      return 2;
    case PlyType::i32:
    case PlyType::u32:
    case PlyType::f32:
      return 4;
    case PlyType::f64:
      return 8;
    case PlyType::none:
      break;
  }
  return 0;
}

inline bool is_integer(PlyType t) {
  return t != PlyType::f32 && t != PlyType::f64 && t != PlyType::none;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::none;        // the value type (of each list entry for lists)
  PlyType count_type = PlyType::none;  // set for lists only
  bool is_list() const { return count_type != PlyType::none; }
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> props;
  const char* at = nullptr;  // the `element` line, for errors
};

template <class U>
inline U load_raw(const unsigned char* p, bool swap) {
  U u;
  std::memcpy(&u, p, sizeof u);
  if (swap) {
    if constexpr (sizeof(U) == 2) u = static_cast<U>(__builtin_bswap16(u));
    if constexpr (sizeof(U) == 4) u = __builtin_bswap32(u);
    if constexpr (sizeof(U) == 8) u = __builtin_bswap64(u);
  }
  return u;
}

// One binary value of type t as T: double for coordinates, std::int64_t for counts and indices
// (which must not pass through double; the header check allows only integer types for them, so a
// floating-point type read as an integer gives 0 here and never occurs).
template <class T>
inline T load_as(const unsigned char* p, PlyType t, bool swap) {
  switch (t) {
    case PlyType::i8:
      return static_cast<std::int8_t>(p[0]);
    case PlyType::u8:
      return p[0];
    case PlyType::i16:
      return static_cast<std::int16_t>(load_raw<std::uint16_t>(p, swap));
    case PlyType::u16:
      return load_raw<std::uint16_t>(p, swap);
    case PlyType::i32:
      return static_cast<std::int32_t>(load_raw<std::uint32_t>(p, swap));
    case PlyType::u32:
      return load_raw<std::uint32_t>(p, swap);
    case PlyType::f32:
      if constexpr (std::is_floating_point_v<T>)
        return std::bit_cast<float>(load_raw<std::uint32_t>(p, swap));
      break;
    case PlyType::f64:
      if constexpr (std::is_floating_point_v<T>)
        return std::bit_cast<double>(load_raw<std::uint64_t>(p, swap));
      break;
    case PlyType::none:
      break;
  }
  return 0;
}

// The roles of the properties of the vertex and face elements.
struct Layout {
  int vertex_element = -1, face_element = -1;
  int coord[3] = {-1, -1, -1};  // property index of x, y, z in the vertex element
  int indices = -1;             // property index of the index list in the face element
};

struct Header {
  MeshFormat format = MeshFormat::unknown;
  std::vector<PlyElement> elements;
  const char* data = nullptr;  // first byte after "end_header\n"
};

// The header at c (c.p at the file's first byte), c left after "end_header\n". Throws InputError
// for a malformed header.
Header parse_header(TextCursor& c);

// The roles of the header's properties. Throws InputError for a vertex element without x, y, z
// or a face element without an integer index list, or faces without vertices.
Layout find_layout(const Header& h, const TextCursor& c);

}  // namespace pgamesh::detail
