// Internal: faulting in the pages of a large fresh array on both threads before a vector's
// resize() zero-fills it on one. On the 2-core VM a page fault costs about 3 µs, so zero-filling
// the corners of 10^6 triangles (12 MB) took about 10 ms on one thread, all other work waiting;
// with the pages populated half on each thread first, the zero-fill is a plain 2 ms memset.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "detail/parallel/two_threads.hpp"

namespace pgamesh::detail {

// Populates the whole pages of [data, data + bytes) for writing (madvise MADV_POPULATE_WRITE,
// Linux 5.14), the two halves at once when `parallel`. Only a hint: without kernel support, or
// on a failure, the pages are faulted in later by whoever touches them first.
inline void populate_pages(void* data, std::size_t bytes, bool parallel) {
#ifdef MADV_POPULATE_WRITE
  const PageRange whole = whole_pages(data, static_cast<const char*>(data) + bytes);
  if (whole.end <= whole.begin) return;
  // The halves split on a page boundary: the middle rounded down.
  const auto* first = reinterpret_cast<const char*>(whole.begin);
  const std::uintptr_t begin = whole.begin, end = whole.end,
                       mid = whole_pages(first, first + (end - begin) / 2).end;
  auto populate = [](std::uintptr_t from, std::uintptr_t to) {
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_POPULATE_WRITE);
  };
  run_both(
      parallel, [&] { populate(begin, mid); }, [&] { populate(mid, end); });
#else
  (void)data;
  (void)bytes;
  (void)parallel;
#endif
}

// v.resize(n) of an empty vector of trivial values, its pages populated on two threads first
// when the array is large (see above). The vector is a plain std::vector (the arrays of
// WeldedTriangles), so only its 2 MiB-aligned interior can have huge pages (huge_pages.hpp).
template <class T>
void resize_populated(std::vector<T>& v, std::size_t n) {
  constexpr std::size_t parallel_bytes = std::size_t{1} << 22;  // below, a thread costs more
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  if (n * sizeof(T) >= parallel_bytes) populate_pages(v.data(), n * sizeof(T), true);
  v.resize(n);
}

}  // namespace pgamesh::detail
