// Appending a value's bytes in a chosen byte order, for tests that build binary files (PLY little-
// and big-endian) byte by byte, independently of the library's writers.
#pragma once

#include <bit>
#include <cstring>
#include <string>
#include <utility>

namespace pgamesh::test {

// Appends the bytes of `value` to `out`, big-endian when `big`, else little-endian.
template <class T>
void put(std::string& out, T value, bool big) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big == (std::endian::native == std::endian::little))
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

}  // namespace pgamesh::test
