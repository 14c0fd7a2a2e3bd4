#include "io/xml_arena.hpp"

#include <algorithm>
#include <mutex>
#include <pugixml.hpp>

namespace pgamesh::detail {

namespace {

thread_local XmlArena* current_arena = nullptr;

// pugixml's allocation functions are process-wide. Those installed before the arena's (malloc and
// free by default, or a program's own when it uses pugixml too and set them first) serve every
// allocation outside an arena and free every block an arena does not own, so documents made
// before, beside or after a 3MF parse keep the allocator they were made with.
pugi::allocation_function outer_allocate = nullptr;
pugi::deallocation_function outer_deallocate = nullptr;

void* pugixml_allocate(std::size_t bytes) {
  return current_arena ? current_arena->allocate(bytes) : outer_allocate(bytes);
}

void pugixml_deallocate(void* p) {
  if (!current_arena || !current_arena->owns(p)) outer_deallocate(p);
}

}  // namespace

XmlArena::XmlArena() : previous_(current_arena) {
  // Installed at the first arena, and again if the program has since set functions of its own
  // (which then become the outer ones).
  static std::mutex install;
  const std::lock_guard<std::mutex> lock(install);
  if (pugi::get_memory_allocation_function() != pugixml_allocate) {
    outer_allocate = pugi::get_memory_allocation_function();
    outer_deallocate = pugi::get_memory_deallocation_function();
    pugi::set_memory_management_functions(pugixml_allocate, pugixml_deallocate);
  }
  current_arena = this;
}

XmlArena::~XmlArena() {
  current_arena = previous_;
}

void* XmlArena::allocate(std::size_t bytes) {
  constexpr std::size_t align = alignof(std::max_align_t);
  bytes = (bytes + align - 1) & ~(align - 1);
  if (chunks_.empty() || chunks_.back().size - chunks_.back().used < bytes) {
    // Chunks grow from 1 MiB to 64 MiB: a small part costs little, a large one few chunks.
    const std::size_t last = chunks_.empty() ? 0 : chunks_.back().size;
    const std::size_t size = std::max(
        bytes, std::clamp<std::size_t>(2 * last, std::size_t{1} << 20, std::size_t{64} << 20));
    chunks_.push_back({uninitialized_array<char>(size), size, 0});
  }
  Chunk& c = chunks_.back();
  void* p = c.bytes.get() + c.used;
  c.used += bytes;
  return p;
}

bool XmlArena::owns(const void* p) const {
  const auto* b = static_cast<const char*>(p);
  return std::any_of(chunks_.begin(), chunks_.end(), [b](const Chunk& c) {
    return b >= c.bytes.get() && b < c.bytes.get() + c.size;
  });
}

}  // namespace pgamesh::detail
