// Internal: arrays that are written in full before they are read (the edge pass's bucket of
// half-edges): std::vector would zero them first, a pass over tens of MB for nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

namespace pgamesh::detail {

// n default-initialised (that is, uninitialised) T.
template <class T>
std::unique_ptr<T[]> uninitialized_array(std::size_t n) {
  static_assert(std::is_trivially_default_constructible_v<T>);
  return std::unique_ptr<T[]>(new T[n]);
}

}  // namespace pgamesh::detail
