// Internal: the memory of pugixml's trees on huge pages. A model part of 10^6 triangles is about
// 100 MB of XML and pugixml's tree of it 250 MB in 32 KiB pages; on the paravirtualised VMs this
// project runs on every first touch of a 4 KiB page costs about 15 µs
// (detail/memory/huge_pages.hpp), which made page faults the largest cost of reading a 3MF. While
// an XmlArena is alive, pugixml's allocations on its thread come from the arena's chunks (huge
// pages, bump-allocated, freed all at once); elsewhere they are those of the allocation functions
// pugixml had before the first arena (malloc's by default, or a program's own).
#pragma once

#include <cstddef>
#include <vector>

#include "detail/memory/uninitialized_array.hpp"

namespace pgamesh::detail {

class XmlArena {
 public:
  XmlArena();
  ~XmlArena();
  XmlArena(const XmlArena&) = delete;
  XmlArena& operator=(const XmlArena&) = delete;

  void* allocate(std::size_t bytes);
  bool owns(const void* p) const;

 private:
  struct Chunk {
    UninitializedArray<char> bytes;
    std::size_t size = 0, used = 0;
  };
  std::vector<Chunk> chunks_;
  XmlArena* previous_ = nullptr;  // the arena current before this one (they nest)
};

}  // namespace pgamesh::detail
