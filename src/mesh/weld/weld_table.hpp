// Internal: the open-addressing table behind the exact welds (weld.cpp for meshes of doubles,
// weld_binary_stl.cpp for float32 STL records, ply_topology.cpp for float32 and float64 PLY
// vertices), and the hash mixer and coordinate keys they share.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "detail/memory/huge_pages.hpp"

namespace pgamesh::detail {

// MurmurHash3's 64-bit finaliser: every input bit affects every output bit, so coordinates that
// differ only in their last mantissa bits still land in different slots.
inline std::uint64_t mix64(std::uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

// Open addressing with linear probing over ids into a caller's key array. A slot holds
// (upper 32 hash bits << 32) | (id + 1), 0 = empty: the tag rejects almost every non-matching
// slot without touching the key array. Traits supplies `static std::uint64_t hash(const Key&)`
// and `static bool same(const Key&, const Key&)` (the weld's notion of equal coordinates). The key
// array is a std::vector<Key> or anything with its size(), operator[] and push_back (weld.cpp keeps
// the keys in the input's own array, compacted as the classes appear).
template <class Key, class Traits>
class WeldTable {
 public:
  static constexpr std::uint32_t none = 0xffffffffu;

  explicit WeldTable(std::size_t expected) {
    std::size_t cap = 64;
    while (cap < 2 * expected) cap *= 2;
    slots_.assign(cap, 0);  // probed at random: huge pages spare the TLB misses
    mask_ = cap - 1;
  }

  // Where the probe for hash h starts (for prefetching).
  const std::uint64_t* slot_address(std::uint64_t h) const { return &slots_[h & mask_]; }

  // Prefetches the key that the probe for hash h compares first, when the first slot's tag
  // matches: the probe's second memory access (the slot itself should have been prefetched a few
  // steps earlier, via slot_address, so that reading it here does not stall).
  template <class Keys>
  void prefetch_key(std::uint64_t h, const Keys& keys) const {
    const std::uint64_t s = slots_[h & mask_];
    if (s != 0 && (s >> 32) == (h >> 32)) __builtin_prefetch(&keys[(s & 0xffffffffULL) - 1]);
  }

  // The id of `k` (hash h) among `keys`, or none.
  template <class Keys>
  std::uint32_t find(const Key& k, std::uint64_t h, const Keys& keys) const {
    const std::uint64_t tag = h >> 32;
    for (std::size_t pos = h & mask_;; pos = (pos + 1) & mask_) {
      const std::uint64_t s = slots_[pos];
      if (s == 0) return none;
      if ((s >> 32) == tag) {
        const auto id = static_cast<std::uint32_t>((s & 0xffffffffULL) - 1);
        if (Traits::same(keys[id], k)) return id;
      }
    }
  }

  // The id of `k` (hash h), appending it to `keys` when it is new (then `inserted` is true).
  template <class Keys>
  std::uint32_t find_or_insert(const Key& k, std::uint64_t h, Keys& keys, bool& inserted) {
    const std::uint64_t tag = h >> 32;
    for (std::size_t pos = h & mask_;; pos = (pos + 1) & mask_) {
      const std::uint64_t s = slots_[pos];
      if (s == 0) {
        const auto id = static_cast<std::uint32_t>(keys.size());
        keys.push_back(k);
        slots_[pos] = (tag << 32) | (std::uint64_t{id} + 1);
        inserted = true;
        if (2 * keys.size() > slots_.size()) grow(keys);
        return id;
      }
      if ((s >> 32) == tag) {
        const auto id = static_cast<std::uint32_t>((s & 0xffffffffULL) - 1);
        if (Traits::same(keys[id], k)) {
          inserted = false;
          return id;
        }
      }
    }
  }

 private:
  template <class Keys>
  void grow(const Keys& keys) {
    HugeVector<std::uint64_t> old(slots_.size() * 2, 0);
    old.swap(slots_);
    mask_ = slots_.size() - 1;
    for (std::size_t id = 0; id < keys.size(); ++id) {
      const std::uint64_t h = Traits::hash(keys[id]);
      std::size_t pos = h & mask_;
      while (slots_[pos] != 0) pos = (pos + 1) & mask_;
      slots_[pos] = ((h >> 32) << 32) | (std::uint64_t{id} + 1);
    }
  }

  HugeVector<std::uint64_t> slots_;
  std::size_t mask_ = 0;
};

// A table's keys kept in an array of the caller's (the welded vertices' coordinates written over
// the input's own, since class ids never run ahead of the vertex being welded): the key array
// WeldTable takes, without a second copy of the keys.
template <class Key>
struct KeysInPlace {
  Key* data;
  std::size_t count = 0;
  std::size_t size() const { return count; }
  const Key& operator[](std::size_t id) const { return data[id]; }
  void push_back(const Key& k) { data[count++] = k; }
};

// Calls visit(i, hash(i)) for i in [0, n) in order, each hash computed `ahead` vertices early and
// its slot in `table` prefetched: the table is far larger than the caches, and this hides most
// of a probe's memory latency. Stops, returning false, when visit returns false.
template <class Table, class Hash, class Visit>
bool visit_prefetched(const Table& table, std::size_t n, const Hash& hash, const Visit& visit) {
  constexpr std::size_t ahead = 16;
  std::array<std::uint64_t, 32> ring{};
  for (std::size_t i = 0; i < std::min(ahead, n); ++i) ring[i & 31] = hash(i);
  for (std::size_t i = 0; i < n; ++i) {
    if (i + ahead < n) {
      const std::uint64_t h = hash(i + ahead);
      ring[(i + ahead) & 31] = h;
      __builtin_prefetch(table.slot_address(h));
    }
    if (!visit(i, ring[i & 31])) return false;
  }
  return true;
}

}  // namespace pgamesh::detail

namespace pgamesh::detail {

// The bits of three floating-point coordinates (Bits = std::uint32_t for float32, std::uint64_t for
// float64): the key of the exact weld of vertices read as bits.
template <class Bits>
using CoordinateKey = std::array<Bits, 3>;
using Float32Key = CoordinateKey<std::uint32_t>;

// A coordinate's bits with −0 folded to +0 (−0 is the sign bit alone), so that the two zeros weld
// while every other value welds only with itself.
template <class Bits>
inline Bits folded_zero(Bits u) {
  constexpr Bits negative_zero = Bits{1} << (8 * sizeof(Bits) - 1);
  return u == negative_zero ? Bits{0} : u;
}

// Keys keep their own bits (the representative's coordinates, −0 included), and hash and compare
// folded.
template <class Bits>
struct CoordinateKeyTraits {
  static std::uint64_t hash(const CoordinateKey<Bits>& k) {
    const Bits x = folded_zero(k[0]), y = folded_zero(k[1]), z = folded_zero(k[2]);
    if constexpr (sizeof(Bits) == 4)
      return mix64(((std::uint64_t{x} << 32) | y) ^ mix64(z + 0x9e3779b97f4a7c15ULL));
    else
      return mix64(x ^ mix64(y ^ mix64(z + 0x9e3779b97f4a7c15ULL)));
  }
  // Coordinate by coordinate, in registers: comparing folded copies of the arrays made the
  // compiler store them and reload 8 bytes spanning two 4-byte stores, a store-forwarding stall
  // on every probe.
  static bool same(const CoordinateKey<Bits>& a, const CoordinateKey<Bits>& b) {
    return folded_zero(a[0]) == folded_zero(b[0]) && folded_zero(a[1]) == folded_zero(b[1]) &&
           folded_zero(a[2]) == folded_zero(b[2]);
  }
};
using Float32KeyTraits = CoordinateKeyTraits<std::uint32_t>;

}  // namespace pgamesh::detail
