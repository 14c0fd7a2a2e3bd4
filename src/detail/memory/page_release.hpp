// Internal: giving the pages of a read-only file mapping back to the kernel once a reader has
// passed them, so that the peak resident memory of reading a file is its parsed arrays plus a few
// MiB of the file, not the whole file plus the arrays. madvise(MADV_DONTNEED) on a read-only
// private file mapping only drops this process's page-table entries: the bytes stay valid, and a
// page touched again (an error message computing its line number) is read back from the page cache.
// Never use it on memory the process wrote (a buffer read from a pipe): those pages would be lost.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pgamesh::detail {

// The whole pages inside [from, to): addresses rounded inwards to the system's page boundaries
// (an empty range, end <= begin, when no whole page lies inside).
struct PageRange {
  std::uintptr_t begin = 0, end = 0;
};
PageRange whole_pages(const void* from, const void* to);

// Releases the whole pages inside [from, to) (rounded inwards to page boundaries).
void release_pages(const void* from, const void* to);

// Asks the kernel to map the whole pages inside [from, to) of a file mapping with small pages
// only (madvise(MADV_NOHUGEPAGE)). The page cache may hold a file in 2 MB folios, and a fault
// then maps a whole folio at once, up to 2 MB ahead of a reader that releases the pages behind
// it: a pass that reads a file several times over arrays sized to the file sees that as peak.
void map_small_pages(const void* from, const void* to);

// Releases, in steps of `step` bytes, the pages of a byte range that a single reader passes from
// front to back. Disabled (every call a no-op but one compare) unless constructed with `enabled`.
class PageRelease {
 public:
  static constexpr std::size_t default_step = std::size_t{1} << 22;  // 4 MiB between madvise calls

  PageRelease() = default;
  PageRelease(const void* begin, bool enabled, std::size_t step = default_step)
      : released_(enabled ? static_cast<const char*>(begin) : nullptr), step_(step) {}

  // The reader has read everything before `p`: release whole steps behind it.
  void passed(const void* p) {
    const char* q = static_cast<const char*>(p);
    if (released_ && static_cast<std::size_t>(q - released_) >= step_) {
      release_pages(released_, q);
      released_ = q;
    }
  }

  // The reader is done with everything before `p`: release all of it.
  void finish(const void* p) {
    if (!released_) return;
    if (p > released_) release_pages(released_, p);
    released_ = static_cast<const char*>(p);
  }

 private:
  const char* released_ = nullptr;  // start of the bytes not yet released; null when disabled
  std::size_t step_ = default_step;
};

}  // namespace pgamesh::detail
