// Internal: arrays that are written in full before they are read (the edge pass's bucket of
// half-edges): std::vector would zero them first, a pass over tens of MB for nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>

#include "detail/memory/huge_pages.hpp"

namespace pgamesh::detail {

// An array of trivial values on HugePageAllocator's blocks (huge_pages.hpp), freed as allocated.
template <class T>
struct HugeArrayDelete {
  std::size_t n = 0;
  void operator()(T* p) const noexcept { HugePageAllocator<T>().deallocate(p, n); }
};
template <class T>
using UninitializedArray = std::unique_ptr<T[], HugeArrayDelete<T>>;

// n default-initialised (that is, uninitialised) T.
template <class T>
UninitializedArray<T> uninitialized_array(std::size_t n) {
  static_assert(std::is_trivially_default_constructible_v<T>);
  return UninitializedArray<T>(HugePageAllocator<T>().allocate(n), HugeArrayDelete<T>{n});
}

}  // namespace pgamesh::detail
