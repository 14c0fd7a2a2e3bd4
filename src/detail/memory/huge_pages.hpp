// Internal: transparent huge pages for the large arrays of the weld and the topology pass (the
// weld's hash tables, its keys, the edge pass's buckets and union–find: megabytes to hundreds of
// megabytes, each written in full or probed at random).
//
// Two costs of 4 KiB pages, both measured on the 2-core VMs this project runs on:
// * TLB misses: probing a table of tens of MB misses the TLB on nearly every access; with 2 MiB
//   pages a 64 MiB table needs 32 TLB entries (5·10^6-triangle STL: the weld's CPU time −20 %).
// * Page faults: every first touch of a fresh 4 KiB page is a fault, and on a paravirtualised
//   guest each one exits to the hypervisor. On the 2026-11-25 VM (AMD EPYC, kernel 6.18) a 12 MB
//   array took 35–53 ms to fault in with 4 KiB pages (about 15 µs a page) and 1 ms with 2 MiB
//   pages, where the kernel zeroes each huge page in one fault. (The VM of 2026-11-21 was slow to
//   back fresh huge pages instead, and only the tables gained there: docs/topology.md.)
//
// Huge pages apply only to whole 2 MiB-aligned ranges: HugePageAllocator gives the large blocks
// that alignment, so that no array keeps a 4 KiB-paged head and tail. THP is often in `madvise`
// mode (/sys/kernel/mm/transparent_hugepage/enabled), where only ranges marked MADV_HUGEPAGE get
// huge pages; without THP everything works on 4 KiB pages.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#include "detail/memory/page_release.hpp"

namespace pgamesh::detail {

inline constexpr std::size_t huge_page_bytes = std::size_t{1} << 21;

// Asks for huge pages on the 2 MiB-aligned part of [data, data + bytes). Call before the pages
// are first touched: the page-fault handler then maps whole huge pages. Only a hint — without THP
// support, or for a range smaller than a huge page, nothing changes.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t huge = huge_page_bytes;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + huge - 1) & ~(huge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(huge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// A std::allocator whose blocks of at least half a huge page start on a huge-page boundary, span
// whole huge pages and are advised MADV_HUGEPAGE before their first touch (a block of 1–2 MiB
// costs at most twice its size in memory, and one fault instead of up to 512). Smaller blocks are
// std::allocator's.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    // Sizes whose round-up to whole huge pages would wrap around are refused.
    if (n > (static_cast<std::size_t>(-1) - huge_page_bytes) / sizeof(T))
      throw std::bad_array_new_length();
    if (n * sizeof(T) < huge_page_bytes / 2) return std::allocator<T>().allocate(n);
    const std::size_t bytes = whole_huge_pages(n);
    void* p = ::operator new (bytes, std::align_val_t{huge_page_bytes});
    advise_huge_pages(p, bytes);
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < huge_page_bytes / 2) return std::allocator<T>().deallocate(p, n);
    // The unsized form: clang before 19 declares the sized one only with -fsized-deallocation.
    ::operator delete (p, std::align_val_t{huge_page_bytes});
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }

 private:
  static std::size_t whole_huge_pages(std::size_t n) {
    return (n * sizeof(T) + huge_page_bytes - 1) & ~(huge_page_bytes - 1);
  }
};

template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

// v.reserve(n) with huge pages advised for the new buffer. A buffer this large comes from a fresh
// mmap (glibc's malloc maps allocations above its threshold), so its pages are still untouched.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

// Gives back the whole pages of v's storage beyond its size (madvise MADV_DONTNEED; the kernel
// splits a huge page to do so): the readers reserve generously (reserve_huge) and fill an unknown
// part, and the last huge page they touch would otherwise stay resident in full, up to 2 MiB per
// array. The storage stays valid: a page given back reads as zeros when touched again.
template <class T, class A>
void release_unused_capacity(std::vector<T, A>& v) {
  release_pages(v.data() + v.size(), v.data() + v.capacity());
}

}  // namespace pgamesh::detail
