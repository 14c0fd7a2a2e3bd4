// Internal: the records of a binary STL view, block by block — straight from the view's memory,
// or, when the view names an open file (BinaryStlView::file), read with pread into a buffer of the
// calling thread's.
//
// Why read a mapped file: on a paravirtualised guest the first touch of each 4 KiB page of a file
// mapping exits to the hypervisor. On the 2026-11-25 VM, touching the pages of a 50 MB STL mapping
// took 19–26 ms (1.6 µs a page, MAP_POPULATE or not); reading it through a 256 KB buffer, 7 ms.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "io/stl_binary.hpp"

namespace pgamesh::detail {

// Records per block: 200 KB of STL records, which a core's L2 cache holds while the block is used.
inline constexpr std::uint64_t records_per_block = 4096;

// Records [first, first + count) of the view, count ≤ records_per_block: a pointer into the view's
// memory, or into this thread's buffer (valid until its next call) after reading them from the
// file. Throws InputError naming `name` and the byte offset when the file cannot be read there (an
// I/O error, or a file shortened since the view was made).
const unsigned char* record_block(const BinaryStlView& view, std::uint64_t first,
                                  std::uint64_t count, const std::string& name);

// Whether a pass over the view that was asked to release the mapped pages of its records
// (`release_records`) has any to release: none when it reads them from the file.
inline bool releases_mapped_records(const BinaryStlView& view, bool release_records) {
  return release_records && view.file < 0;
}

// Calls visit(records, begin, end) for consecutive blocks [begin, end) covering [first, last), with
// `records` pointing at record `begin` (record_block above).
template <class Visit>
void for_record_blocks(const BinaryStlView& view, std::uint64_t first, std::uint64_t last,
                       const std::string& name, Visit&& visit) {
  for (std::uint64_t begin = first; begin < last; begin += records_per_block) {
    const std::uint64_t end = std::min(last, begin + records_per_block);
    visit(record_block(view, begin, end - begin, name), begin, end);
  }
}

}  // namespace pgamesh::detail
