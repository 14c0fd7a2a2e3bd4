#include "io/xml_arena.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <pugixml.hpp>

namespace pgamesh::detail {

namespace {

thread_local XmlArena* current_arena = nullptr;

void* pugixml_allocate(std::size_t bytes) {
  return current_arena ? current_arena->allocate(bytes) : std::malloc(bytes);
}

// A block of the current arena is freed with the arena; anything else was malloc's.
void pugixml_deallocate(void* p) {
  if (!current_arena || !current_arena->owns(p)) std::free(p);
}

}  // namespace

XmlArena::XmlArena() : previous_(current_arena) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    pugi::set_memory_management_functions(pugixml_allocate, pugixml_deallocate);
  });
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
