// The exact weld of a binary STL straight from its records (welded_triangles.hpp): the 96-bit
// pattern of each float32 triple is the key of an open-addressing hash table, so no Mesh of
// doubles is built and every record is read once.
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "detail/memory/populate_pages.hpp"
#include "detail/parallel/two_threads.hpp"
#include "io/stl_record_blocks.hpp"
#include "mesh/weld/weld_table.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh {

namespace {

using Key = detail::Float32Key;

inline std::uint32_t load_le32(const unsigned char* p) {
  std::uint32_t u;
  std::memcpy(&u, p, 4);
  if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap32(u);
  return u;
}

// Vertex k of the record at r, of layout L, as float32 bits. Returns false for NaN or infinity
// (all exponent bits set).
template <TriangleRecordLayout L>
inline bool vertex_key(const unsigned char* r, int k, Key& key) {
  bool finite = true;
  for (int j = 0; j < 3; ++j) {
    std::uint32_t u = load_le32(r + L.coords + 12 * k + 4 * j);
    finite &= (u & 0x7f800000u) != 0x7f800000u;
    key[j] = u;
  }
  return finite;
}

// The bits of the float32 triples, −0 folded to +0 (weld_table.hpp), as weld_map welds the
// doubles they become.
using KeyTable = detail::WeldTable<Key, detail::Float32KeyTraits>;

// The weld of input vertices [first, last) into their own table: corners[i − first] gets the id
// among this range's classes (numbered by first occurrence), first_vertex[id] the input index of
// its first occurrence.
struct RangeWeld {
  KeyTable table{0};
  detail::HugeVector<Key> keys;
  std::vector<std::uint32_t> first_vertex;
  bool finite = true;
};

// Welds input vertices [first, last) of the view, whose layout is L, into `out`.
template <TriangleRecordLayout L>
void weld_range(const BinaryStlView& view, const std::string& name, std::size_t first,
                std::size_t last, std::uint32_t* corners, bool release_records, RangeWeld& out) {
  const std::size_t n = last - first;
  // A closed STL shares each vertex among about six corners: start for n / 4 classes and grow.
  out.table = KeyTable(n / 4 + 16);
  out.keys.reserve(n / 4 + 16);
  detail::reserve_huge(out.first_vertex, n / 4 + 16);

  // The table is larger than the caches: hash a few vertices ahead and prefetch their slots, and
  // half as far ahead, their first slot's key (a probe's two memory accesses, both hidden). The
  // records come in blocks (stl_record_blocks.hpp); the look-ahead stays within a block.
  constexpr std::size_t ahead = 16, key_ahead = 8;
  std::array<std::uint64_t, 32> ring{};
  std::array<Key, 32> ring_key{};
  detail::PageRelease release(view.records + L.stride * (first / 3),
                              detail::releases_mapped_records(view, release_records));
  detail::for_record_blocks(
      view, first / 3, last / 3, name,
      [&](const unsigned char* records, std::uint64_t record_begin, std::uint64_t record_end) {
        const std::size_t begin = 3 * record_begin, end = 3 * record_end;
        auto load = [&](std::size_t i) {
          out.finite &= vertex_key<L>(records + L.stride * (i / 3 - record_begin),
                                      static_cast<int>(i % 3), ring_key[i & 31]);
          ring[i & 31] = detail::Float32KeyTraits::hash(ring_key[i & 31]);
        };
        for (std::size_t i = begin; i < std::min(begin + ahead, end); ++i) load(i);
        for (std::size_t i = begin; i < end; ++i) {
          if (i + ahead < end) {
            load(i + ahead);
            __builtin_prefetch(out.table.slot_address(ring[(i + ahead) & 31]));
          }
          if (i + key_ahead < end) out.table.prefetch_key(ring[(i + key_ahead) & 31], out.keys);
          bool inserted = false;
          corners[i - first] =
              out.table.find_or_insert(ring_key[i & 31], ring[i & 31], out.keys, inserted);
          if (inserted) out.first_vertex.push_back(static_cast<std::uint32_t>(i));
        }
        release.passed(view.records + L.stride * record_end);
      });
  release.finish(view.records + L.stride * (last / 3));
}

// found[j] = the id of keys[j] in the table of `low`, or KeyTable::none, for j in [begin, end).
// Hashes a few keys ahead with their slots and keys prefetched, as in the weld.
void find_in_range(const RangeWeld& low, const detail::HugeVector<Key>& keys, std::size_t begin,
                   std::size_t end, std::uint32_t* found) {
  constexpr std::size_t ahead = 16, key_ahead = 8;
  std::array<std::uint64_t, 32> ring{};
  for (std::size_t j = begin; j < std::min(begin + ahead, end); ++j)
    ring[j & 31] = detail::Float32KeyTraits::hash(keys[j]);
  for (std::size_t j = begin; j < end; ++j) {
    if (j + ahead < end) {
      ring[(j + ahead) & 31] = detail::Float32KeyTraits::hash(keys[j + ahead]);
      __builtin_prefetch(low.table.slot_address(ring[(j + ahead) & 31]));
    }
    if (j + key_ahead < end) low.table.prefetch_key(ring[(j + key_ahead) & 31], low.keys);
    found[j] = low.table.find(keys[j], ring[j & 31], low.keys);
  }
}

// Records below which a second thread does not pay for the merge.
constexpr std::uint64_t records_per_thread = std::uint64_t{1} << 15;

}  // namespace

WeldedTriangles weld_binary_stl(const BinaryStlView& view, const std::string& name,
                                bool release_records) {
  if (3 * view.count > 0xFFFFFFFFull)
    throw InputError(name, InputPosition{0, 0, 80, false},
                     std::to_string(view.count) + " triangles exceed the 32-bit vertex indices");
  const std::size_t n = 3 * static_cast<std::size_t>(view.count);
  WeldedTriangles w;
  w.input_vertices = n;
  detail::resize_populated(w.corners, n);
  if (n == 0) return w;

  // Two threads weld the two halves of the records into tables of their own; the second half's
  // classes are then looked up in the first half's table and numbered after it in their own
  // first-occurrence order — the numbering and representatives of one sequential pass.
  RangeWeld low, high;
  // The first half's first occurrences become the representatives of every class below (moved,
  // then resized to the class count): reserved for every corner — address space only, pages are
  // touched as the array fills — so that the resize neither copies them into a fresh array on one
  // thread (1.5 ms at 10^6 triangles) nor faults in a second array.
  detail::reserve_huge(low.first_vertex, n);
  const std::size_t split = view.count >= 2 * records_per_thread ? 3 * (view.count / 2) : n;
  with_record_layout(view.layout, [&](auto layout) {
    constexpr TriangleRecordLayout L = decltype(layout)::layout;
    detail::run_both(
        split != n,
        [&] { weld_range<L>(view, name, 0, split, w.corners.data(), release_records, low); },
        [&] {
          if (split != n)
            weld_range<L>(view, name, split, n, w.corners.data() + split, release_records, high);
        });
  });
  // A NaN or infinity: name the first one, with its byte offset (throws).
  if (!low.finite || !high.finite) check_binary_stl_finite(view, name);

  // The first half's classes keep their ids; with two halves, the second half's are looked up in
  // the first half's table, each half of them on a thread (the table is only read), and those not
  // found are numbered after the first half's in their own first-occurrence order.
  const std::size_t first_classes = low.keys.size();
  detail::HugeVector<std::uint32_t> global;  // second half's class → welded id
  if (split != n) {
    const std::size_t m = high.keys.size();
    global.resize(m);
    detail::run_both(
        true, [&] { find_in_range(low, high.keys, 0, m / 2, global.data()); },
        [&] { find_in_range(low, high.keys, m / 2, m, global.data()); });
    high.table = KeyTable(0);
  }
  low.table = KeyTable(0);

  // The arrays are sized once (the classes are counted first), so that no push_back reallocates
  // and copies them; the positions of the first half's classes are converted and the second
  // half's corners renumbered on two threads.
  const std::size_t fresh =
      static_cast<std::size_t>(std::count(global.begin(), global.end(), KeyTable::none));
  const std::size_t classes = first_classes + fresh;
  detail::resize_populated(w.positions, classes);
  w.representative = std::move(low.first_vertex);
  w.representative.resize(classes);
  auto position = [](const Key& k) {
    return Vec3d{std::bit_cast<float>(k[0]), std::bit_cast<float>(k[1]),
                 std::bit_cast<float>(k[2])};
  };
  for (std::size_t j = 0, id = first_classes; j < global.size(); ++j) {
    if (global[j] != KeyTable::none) continue;
    global[j] = static_cast<std::uint32_t>(id);
    w.positions[id] = position(high.keys[j]);
    w.representative[id] = high.first_vertex[j];
    ++id;
  }
  high = RangeWeld{};
  auto convert_and_renumber = [&](int part) {
    const std::size_t half = first_classes / 2;
    for (std::size_t id = part == 0 ? 0 : half; id < (part == 0 ? half : first_classes); ++id)
      w.positions[id] = position(low.keys[id]);
    const std::size_t mid = split + (n - split) / 2;
    for (std::size_t c = part == 0 ? split : mid; c < (part == 0 ? mid : n); ++c)
      w.corners[c] = global[w.corners[c]];
  };
  detail::run_both(
      split != n, [&] { convert_and_renumber(0); }, [&] { convert_and_renumber(1); });
  w.merged = n - w.positions.size();
  return w;
}

}  // namespace pgamesh
