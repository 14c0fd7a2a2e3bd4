// Internal: transparent huge pages for the weld's hash tables (weld_table.hpp: tens of MB, probed
// at random). Probing such an array misses the TLB on nearly every access with 4 KiB pages; with
// 2 MiB pages a 64 MiB table needs only 32 TLB entries. Measured on the 2-core VM (5·10^6-triangle
// STL): the weld's CPU time drops by about a fifth. Huge pages are not used for the other arrays:
// there the kernel's zeroing of fresh 2 MiB pages cost more CPU than the TLB misses saved. THP is
// often in `madvise` mode
// (/sys/kernel/mm/transparent_hugepage/enabled), where only ranges marked MADV_HUGEPAGE get them.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pgamesh::detail {

// Asks for huge pages on the 2 MiB-aligned part of [data, data + bytes). Call before the pages
// are first touched: the page-fault handler then maps whole huge pages. Only a hint — without THP
// support, or for a range smaller than a huge page, nothing changes.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t huge = std::uintptr_t{1} << 21;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + huge - 1) & ~(huge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// v.reserve(n) with huge pages advised for the new buffer. A buffer this large comes from a fresh
// mmap (glibc's malloc maps allocations above its threshold), so its pages are still untouched.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace pgamesh::detail
