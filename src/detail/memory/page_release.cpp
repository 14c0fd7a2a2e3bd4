#include "detail/memory/page_release.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

namespace pgamesh::detail {

PageRange whole_pages(const void* from, const void* to) {
  static const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  return {(reinterpret_cast<std::uintptr_t>(from) + page - 1) & ~(page - 1),
          reinterpret_cast<std::uintptr_t>(to) & ~(page - 1)};
}

void release_pages(const void* from, const void* to) {
  const PageRange r = whole_pages(from, to);
  if (r.end > r.begin) madvise(reinterpret_cast<void*>(r.begin), r.end - r.begin, MADV_DONTNEED);
}

void map_small_pages(const void* from, const void* to) {
  const PageRange r = whole_pages(from, to);
  if (r.end > r.begin) madvise(reinterpret_cast<void*>(r.begin), r.end - r.begin, MADV_NOHUGEPAGE);
}

}  // namespace pgamesh::detail
