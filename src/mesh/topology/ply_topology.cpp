// The topology pass of a binary PLY that re-reads its faces from the file (ply_topology.hpp). It
// follows analyze_welded_triangles (welded_topology.cpp) step by step — the same face pass, the
// same edge judging (edge_group.hpp), the same parts of the report (topology_parts.hpp) — with the
// corner array replaced by reads of the file's face records: plain binary records (every list
// holding three indices) sit at a fixed stride, so face f is at faces + f × stride.
#include "mesh/topology/ply_topology.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <numeric>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "detail/memory/uninitialized_array.hpp"
#include "geometry/chunked_sums.hpp"
#include "io/ply_header.hpp"
#include "mesh/topology/duplicate_faces.hpp"
#include "mesh/topology/edge_group.hpp"
#include "mesh/topology/face_layout.hpp"
#include "mesh/topology/topology_parts.hpp"
#include "mesh/weld/weld_table.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/topology/boundary_loops.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh {

namespace {

using detail::CoordinateKey;
using detail::PlyType;

// Bytes between the releases of the pages a pass has read: small, as the file's pages in flight
// count in the peak beside the arrays.
constexpr std::size_t release_step = std::size_t{1} << 20;

// A binary PLY whose records this pass reads directly.
struct PlainPly {
  const unsigned char* vertices = nullptr;  // the first vertex record
  std::size_t vertex_count = 0, vertex_stride = 0;
  std::size_t coord_offset[3] = {};
  const unsigned char* faces = nullptr;  // the first face record
  std::size_t face_count = 0;
  std::size_t face_stride = 0;  // of a record whose index list holds three indices
  std::size_t count_offset = 0, index_offset = 0, index_size = 0;
  PlyType count_type = PlyType::none, index_type = PlyType::none;
  PlyType coordinate_type = PlyType::none;  // f32 or f64, the same for x, y and z
  bool swap = false;

  const unsigned char* face(std::size_t f) const { return faces + f * face_stride; }
  const unsigned char* faces_end() const { return face(face_count); }
  // The length of the index list of the face record at r.
  std::int64_t list_length(const unsigned char* r) const {
    return detail::load_as<std::int64_t>(r + count_offset, count_type, swap);
  }
  // Index k of the face record at r.
  std::int64_t index(const unsigned char* r, std::size_t k) const {
    return detail::load_as<std::int64_t>(r + index_offset + k * index_size, index_type, swap);
  }
  // Coordinate k of vertex i as the bits of its type (Bits of coordinate_type's size).
  template <class Bits>
  Bits coordinate_bits(std::size_t i, int k) const {
    return detail::load_raw<Bits>(vertices + i * vertex_stride + coord_offset[k], swap);
  }
};

// The records of the file when it is a binary PLY this pass reads (see ply_triangle_props), else
// nullopt. Face records are laid out as if every index list held three indices; the face pass
// checks that each does, so the stride holds.
std::optional<PlainPly> plain_ply(std::span<const char> bytes, const detail::Header& h,
                                  const detail::Layout& l) {
  if (h.format != MeshFormat::ply_binary_le && h.format != MeshFormat::ply_binary_be)
    return std::nullopt;
  if (l.vertex_element < 0 || l.face_element < l.vertex_element) return std::nullopt;
  for (std::size_t e = 0; e < h.elements.size(); ++e)
    if (static_cast<int>(e) != l.vertex_element && static_cast<int>(e) != l.face_element &&
        h.elements[e].count > 0 && !h.elements[e].props.empty())
      return std::nullopt;
  PlainPly p;
  const detail::PlyElement& ve = h.elements[static_cast<std::size_t>(l.vertex_element)];
  for (std::size_t i = 0; i < ve.props.size(); ++i) {
    const detail::PlyProperty& prop = ve.props[i];
    if (prop.is_list()) return std::nullopt;
    for (int k = 0; k < 3; ++k)
      if (static_cast<int>(i) == l.coord[k]) {
        if (prop.type != PlyType::f32 && prop.type != PlyType::f64) return std::nullopt;
        if (p.coordinate_type != PlyType::none && prop.type != p.coordinate_type)
          return std::nullopt;
        p.coordinate_type = prop.type;
        p.coord_offset[k] = p.vertex_stride;
      }
    p.vertex_stride += detail::type_size(prop.type);
  }
  const detail::PlyElement& fe = h.elements[static_cast<std::size_t>(l.face_element)];
  for (std::size_t i = 0; i < fe.props.size(); ++i) {
    const detail::PlyProperty& prop = fe.props[i];
    if (static_cast<int>(i) == l.indices) {
      p.count_offset = p.face_stride;
      p.count_type = prop.count_type;
      p.index_type = prop.type;
      p.index_size = detail::type_size(prop.type);
      p.index_offset = p.face_stride + detail::type_size(prop.count_type);
      p.face_stride = p.index_offset + 3 * p.index_size;
    } else if (prop.is_list()) {
      return std::nullopt;
    } else {
      p.face_stride += detail::type_size(prop.type);
    }
  }
  // Welded vertices leave their top bit to a half-edge's direction, and half-edge ids
  // 3 f + k must fit 32 bits (as in welded_topology.cpp).
  if (ve.count >= (std::uint64_t{1} << 31) || fe.count == 0 ||
      fe.count > std::numeric_limits<std::uint32_t>::max() / 3)
    return std::nullopt;
  const auto* data = reinterpret_cast<const unsigned char*>(h.data);
  std::size_t left = static_cast<std::size_t>(bytes.data() + bytes.size() - h.data);
  if (ve.count > left / p.vertex_stride) return std::nullopt;
  left -= ve.count * p.vertex_stride;
  if (fe.count > left / p.face_stride) return std::nullopt;
  p.vertices = data;
  p.vertex_count = ve.count;
  p.faces = data + ve.count * p.vertex_stride;
  p.face_count = fe.count;
  p.swap = (h.format == MeshFormat::ply_binary_be) != (std::endian::native == std::endian::big);
  return p;
}

// The floating-point type whose bits are Bits.
template <class Bits>
using FloatOf = std::conditional_t<sizeof(Bits) == 4, float, double>;

template <class Bits>
inline Vec3d position(const CoordinateKey<Bits>& k) {
  return {std::bit_cast<FloatOf<Bits>>(k[0]), std::bit_cast<FloatOf<Bits>>(k[1]),
          std::bit_cast<FloatOf<Bits>>(k[2])};
}

// The vertices' coordinates: their bits (Bits = std::uint32_t for float32, std::uint64_t for
// float64) while the passes run, then turned into doubles in the same storage, which is reserved
// at 24 B per vertex from the start. For float32 only the first half is touched until the
// conversion, so only it is resident: the doubles never sit beside a second, float copy (which
// would be the pass's peak).
template <class Bits>
class VertexStore {
 public:
  using Key = CoordinateKey<Bits>;
  static_assert(sizeof(Key) <= sizeof(Vec3d));

  explicit VertexStore(std::size_t n)
      : storage_(detail::uninitialized_array<std::byte>(n * sizeof(Vec3d))), count_(n) {}

  Key* keys() { return std::launder(reinterpret_cast<Key*>(storage_.get())); }
  const Key& operator[](std::size_t v) const {
    return std::launder(reinterpret_cast<const Key*>(storage_.get()))[v];
  }
  std::size_t size() const { return count_; }
  void resize_down(std::size_t n) { count_ = n; }

  // The coordinates as doubles, converted in place from the last vertex down: double v covers
  // the bytes of keys 2v and 2v + 1 of float32 bits, which are converted already, or key v of
  // float64 bits (v itself, read first).
  std::span<const Vec3d> to_doubles() {
    const Key* k = keys();
    for (std::size_t v = count_; v-- > 0;) {
      const Key key = k[v];
      new (storage_.get() + v * sizeof(Vec3d)) Vec3d(position(key));
    }
    return {std::launder(reinterpret_cast<const Vec3d*>(storage_.get())), count_};
  }

 private:
  detail::UninitializedArray<std::byte> storage_;
  std::size_t count_;
};

// The input vertices' bits, or nullopt when one is NaN or infinite; `box` their bounding box as
// the doubles read_mesh_bytes() would hold (reference_point's box).
template <class Bits>
std::optional<VertexStore<Bits>> read_vertices(const PlainPly& ply, bool release_pages, Box3& box) {
  using Key = CoordinateKey<Bits>;
  // All exponent bits set (those of infinity): infinity or NaN.
  constexpr Bits exponent = std::bit_cast<Bits>(std::numeric_limits<FloatOf<Bits>>::infinity());
  VertexStore<Bits> store(ply.vertex_count);
  Key* keys = store.keys();
  detail::PageRelease release(ply.vertices, release_pages, release_step);
  for (std::size_t i = 0; i < ply.vertex_count; ++i) {
    release.passed(ply.vertices + i * ply.vertex_stride);
    for (int k = 0; k < 3; ++k) {
      const Bits u = ply.coordinate_bits<Bits>(i, k);
      if ((u & exponent) == exponent) return std::nullopt;
      keys[i][static_cast<std::size_t>(k)] = u;
    }
    box.add(position(keys[i]));
  }
  release.finish(ply.faces);
  return store;
}

// The exact weld of weld_map (weld.hpp) on the coordinates' bits: the same classes (bitwise equal
// coordinates, −0 = +0), numbering (by first vertex) and representatives (the first vertex).
template <class Bits>
struct CoordinateWeld {
  VertexStore<Bits> positions;                // welded vertex → coordinates
  std::vector<std::uint32_t> to_welded;       // input → welded vertex; empty: nothing merged
  std::vector<std::uint32_t> representative;  // welded → lowest input vertex; empty likewise

  std::uint32_t welded(std::int64_t input) const {
    const auto i = static_cast<std::uint32_t>(input);
    return to_welded.empty() ? i : to_welded[i];
  }
};

// Welds `keys` in place, or nullopt when a vertex welds to one whose bits differ (−0 and +0):
// the input coordinates of the mass sums would then not be the welded ones this pass keeps.
template <class Bits>
std::optional<CoordinateWeld<Bits>> weld_coordinates(VertexStore<Bits>&& store) {
  using Key = CoordinateKey<Bits>;
  using Traits = detail::CoordinateKeyTraits<Bits>;
  CoordinateWeld<Bits> w{std::move(store), {}, {}};
  const std::size_t n = w.positions.size();
  Key* keys = w.positions.keys();
  {
    // Sized for one class per vertex, as a PLY usually has: the table never grows (growing
    // holds the old and the new table at once).
    detail::WeldTable<Key, Traits> table(n);
    detail::KeysInPlace<Key> classes{keys};
    const bool same_bits = detail::visit_prefetched(
        table, n, [&](std::size_t i) { return Traits::hash(keys[i]); },
        [&](std::size_t i, std::uint64_t h) {
          const Key key = keys[i];
          bool inserted = false;
          const std::uint32_t id = table.find_or_insert(key, h, classes, inserted);
          if (!inserted && classes[id] != key) return false;
          // The input-to-welded map is made at the first merge: until then every vertex is its
          // own class (id = i), and a file without merges never needs it (2 B per triangle less
          // at the weld's peak).
          if (!w.to_welded.empty()) {
            w.to_welded[i] = id;
          } else if (id != i) {
            detail::reserve_huge(w.to_welded, n);
            w.to_welded.resize(n);
            std::iota(w.to_welded.begin(), w.to_welded.begin() + static_cast<std::ptrdiff_t>(i),
                      0u);
            w.to_welded[i] = id;
          }
          return true;
        });
    if (!same_bits) return std::nullopt;
    w.positions.resize_down(classes.count);
  }
  if (!w.to_welded.empty()) {
    // Classes are numbered in order of their first vertex: class `next` first appears where
    // to_welded reaches it.
    detail::reserve_huge(w.representative, w.positions.size());
    for (std::size_t i = 0; i < n; ++i)
      if (w.to_welded[i] == w.representative.size())
        w.representative.push_back(static_cast<std::uint32_t>(i));
  }
  return w;
}

// One half-edge of a range's pass, as judge_vertex_edges reads it: `first` its upper end,
// `second` its id h = 3 f + k, and the third vertex of its face with, in the top bit, whether it
// runs from the lower end.
struct HalfEdge {
  std::uint32_t first, second, third_and_direction;
};
constexpr std::uint32_t runs_from_lower = 0x80000000u;

// What judge_vertex_edges asks about a HalfEdge: TriangleLayout's answers (face_layout.hpp), with
// the third vertex and the direction taken from the record instead of a corner array.
struct HalfEdgeSides {
  static std::uint32_t half_edge(const HalfEdge& e) { return e.second; }
  static std::uint32_t face(const HalfEdge& e) { return detail::TriangleLayout::face_of(e.second); }
  static bool runs_from(const HalfEdge& e, std::uint32_t) {
    return (e.third_and_direction & runs_from_lower) != 0;  // v is the lower end
  }
  static bool first_side(const HalfEdge& e) { return detail::TriangleLayout::first_side(e.second); }
  // Two triangles on one edge with the same vertex off it.
  static bool same_vertices(const HalfEdge& a, const HalfEdge& b) {
    return ((a.third_and_direction ^ b.third_and_direction) & ~runs_from_lower) == 0;
  }
};

// The pass over one file: the steps of analyze_welded_triangles with the corners read from the
// face records.
template <class Bits>
class PlyPass {
 public:
  PlyPass(const PlainPly& ply, CoordinateWeld<Bits>& weld, bool release_pages)
      : ply_(ply), weld_(weld), release_pages_(release_pages) {}

  std::array<Vec3d, 3> corner_positions(const std::array<std::uint32_t, 3>& w) const {
    return {position(weld_.positions[w[0]]), position(weld_.positions[w[1]]),
            position(weld_.positions[w[2]])};
  }

  // Calls visit(f, corners) for every face not collapsed, in order, releasing the pages behind.
  // The face pass has checked every record, so the indices are read as their own type (the
  // switch on the type taken once per pass, not per index).
  template <class Visit>
  void each_face(const Visit& visit) const {
    switch (detail::type_size(ply_.index_type)) {
      case 1:
        return each_face_as<std::uint8_t>(visit);
      case 2:
        return each_face_as<std::uint16_t>(visit);
      default:
        return each_face_as<std::uint32_t>(visit);
    }
  }

  // each_face with indices of Index's size (non-negative, checked: their bits read unsigned).
  template <class Index, class Visit>
  void each_face_as(const Visit& visit) const {
    detail::PageRelease release(ply_.faces, release_pages_, release_step);
    for (std::size_t f = 0; f < ply_.face_count; ++f) {
      if (collapsed_[f]) continue;
      const unsigned char* r = ply_.face(f);
      release.passed(r);
      const unsigned char* index = r + ply_.index_offset;
      visit(f, std::array<std::uint32_t, 3>{
                   weld_.welded(detail::load_raw<Index>(index, ply_.swap)),
                   weld_.welded(detail::load_raw<Index>(index + sizeof(Index), ply_.swap)),
                   weld_.welded(detail::load_raw<Index>(index + 2 * sizeof(Index), ply_.swap))});
    }
    release.finish(ply_.faces_end());
  }

  // The face pass (welded_topology.cpp's face_pass, the faces read in order): the mass sums in
  // chunked_sums' chunks and each face's tally; the collapsed faces, the referenced vertices and
  // the half-edges per lower end. False when a face is not a triangle or names no vertex.
  bool face_pass(Vec3d reference, detail::TopologyTally& tally, BoundarySums& sums) {
    const std::size_t vertices = weld_.positions.size();
    const auto input_vertices = static_cast<std::int64_t>(ply_.vertex_count);
    StreamedChunkSums<> chunks;
    std::vector<bool> referenced(vertices);
    detail::reserve_huge(start_, vertices + 1);
    start_.assign(vertices + 1, 0);
    collapsed_.assign(ply_.face_count, false);
    detail::PageRelease release(ply_.faces, release_pages_, release_step);
    for (std::size_t f = 0; f < ply_.face_count; ++f) {
      const unsigned char* r = ply_.face(f);
      release.passed(r);
      if (ply_.list_length(r) != 3) return false;
      std::array<std::uint32_t, 3> w;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int64_t i = ply_.index(r, k);
        if (i < 0 || i >= input_vertices) return false;
        w[k] = weld_.welded(i);
      }
      const std::array<Vec3d, 3> v = corner_positions(w);
      double carrier_norm = 0;
      const pga3::Plane<double> carrier = add_triangle(
          chunks.current(), v[0] - reference, v[1] - reference, v[2] - reference, carrier_norm);
      chunks.next();
      const bool collapsed = w[0] == w[1] || w[1] == w[2] || w[2] == w[0];
      detail::tally_triangle(tally, static_cast<std::uint32_t>(f), collapsed, v, carrier,
                             carrier_norm);
      for (std::uint32_t c : w) referenced[c] = true;
      if (collapsed) {
        collapsed_[f] = true;
        ++collapsed_faces;
        continue;
      }
      for (std::size_t k = 0; k < 3; ++k) ++start_[std::min(w[k], w[(k + 1) % 3])];
    }
    release.finish(ply_.faces_end());
    sums = chunks.total();
    unreferenced_vertices =
        static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
    return true;
  }

  // The edge pass in ranges of lower ends holding at most `budget` half-edges each (one vertex's
  // more when it alone has more): per range, one read of the faces buckets the range's
  // half-edges by lower end (a counting sort, the buckets ascending as the faces are read in
  // order), then each vertex's bucket is grouped and judged as in welded_topology.cpp.
  void edge_pass(std::size_t budget) {
    const auto vertices = static_cast<std::uint32_t>(weld_.positions.size());
    std::uint32_t total = 0;
    for (std::uint32_t& s : start_) total += std::exchange(s, total);  // counts → starts
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;
    std::size_t largest = 0;
    for (std::uint32_t a = 0; a < vertices;) {
      std::uint32_t b = a + 1;
      while (b < vertices && start_[b + 1] - start_[a] <= budget) ++b;
      ranges.emplace_back(a, b);
      largest = std::max<std::size_t>(largest, start_[b] - start_[a]);
      a = b;
    }
    passes = ranges.size();
    parent_ = detail::uninitialized_array<std::uint32_t>(ply_.face_count);
    for (std::size_t f = 0; f < ply_.face_count; ++f) parent_[f] = static_cast<std::uint32_t>(f);
    const detail::UninitializedArray<HalfEdge> bucket =
        detail::uninitialized_array<HalfEdge>(largest);
    HalfEdgeSides sides;
    for (const auto& range : ranges) {
      const std::uint32_t a = range.first, b = range.second;  // a lambda cannot capture a binding
      const std::uint32_t base = start_[a], width = b - a;
      each_face([&](std::size_t f, const std::array<std::uint32_t, 3>& w) {
        for (std::uint32_t k = 0; k < 3; ++k) {
          const std::uint32_t tail = w[k], head = w[(k + 1) % 3];
          const std::uint32_t lower = std::min(tail, head);
          if (lower - a >= width) continue;
          bucket[start_[lower]++ - base] = {std::max(tail, head),
                                            static_cast<std::uint32_t>(3 * f + k),
                                            w[(k + 2) % 3] | (tail == lower ? runs_from_lower : 0)};
        }
      });
      // start_[v] has moved to the end of v's bucket, the start of the next one's.
      for (std::uint32_t v = a; v < b; ++v) {
        HalfEdge* begin = bucket.get() + ((v == a ? base : start_[v - 1]) - base);
        std::span<HalfEdge> group(begin, bucket.get() + (start_[v] - base));
        detail::sort_by_upper_end(group);
        detail::judge_vertex_edges(v, group, sides, parent_.get(), edges);
      }
    }
    std::vector<std::uint32_t>().swap(start_);
  }

  // Numbers the components (edge_group.hpp) into `components`; parent_ becomes face → component.
  void number_components(std::vector<ComponentSummary>& components) {
    detail::number_components(
        parent_.get(), ply_.face_count, [&](std::size_t f) { return collapsed_[f]; }, no_edge,
        [&](std::uint32_t first_face) {
          components.push_back({});
          components.back().first_face = first_face;
        },
        [&](std::uint32_t k) { ++components[k].faces; });
  }

  // tally_component_sums, the faces read once more when there are several components.
  void component_sums(detail::TopologyTally& tally) const {
    if (detail::start_component_sums(tally)) return;
    each_face([&](std::size_t f, const std::array<std::uint32_t, 3>& w) {
      detail::add_component_triangle(tally, parent_[f], corner_positions(w));
    });
  }

  std::uint32_t component(std::uint32_t f) const { return parent_[f]; }

  // Face → component, for the nesting of closed components (valid until free_faces).
  std::span<const std::uint32_t> face_components() const {
    return {parent_.get(), ply_.face_count};
  }

  void free_faces() {
    parent_.reset();
    std::vector<bool>().swap(collapsed_);
  }

  detail::EdgePart edges;
  std::size_t collapsed_faces = 0, unreferenced_vertices = 0, passes = 0;

 private:
  const PlainPly& ply_;
  CoordinateWeld<Bits>& weld_;
  bool release_pages_;
  std::vector<std::uint32_t> start_;  // half-edges per lower end, then the buckets' starts
  std::vector<bool> collapsed_;       // per face
  // Union–find of the faces, then their components.
  detail::UninitializedArray<std::uint32_t> parent_;
};

// Half-edges per range when the caller leaves it to the file's size: their records may take a
// twelfth of it (docs/topology.md), and never fewer than a few thousand.
std::size_t default_budget(std::size_t file_size) {
  return std::max<std::size_t>(file_size / 12 / sizeof(HalfEdge), std::size_t{1} << 12);
}

// ply_triangle_props of a file that plain_ply accepts, its coordinates read as Bits (the bits of
// float32 or float64).
template <class Bits>
std::optional<WeldedTriangleProps> plain_ply_props(std::span<const char> bytes,
                                                   const std::string& name, MeshFormat format,
                                                   const PlainPly* ply, MeshSource& source,
                                                   const MassOptions& mass_options,
                                                   const TopologyOptions& options,
                                                   bool release_pages, PlyPassBudget budget) {
  constexpr bool single_precision = sizeof(Bits) == 4;
  if (release_pages) detail::map_small_pages(bytes.data(), bytes.data() + bytes.size());
  Box3 box;
  auto keys = read_vertices<Bits>(*ply, release_pages, box);
  if (!keys) return std::nullopt;
  auto weld = weld_coordinates(std::move(*keys));
  if (!weld) return std::nullopt;
  const Vec3d reference = box.centre();  // reference_point() of the input vertices

  WeldedTriangleProps props;
  TopologyReport& r = props.topology;
  r.faces = ply->face_count;
  r.input_vertices = ply->vertex_count;
  r.vertices = weld->positions.size();
  r.merged_vertices = r.input_vertices - r.vertices;
  r.area_threshold = options.area_threshold;
  r.reference_point = reference;
  detail::WeldedFaces faces;  // the positions as doubles once the faces' arrays are gone
  detail::TopologyTally tally(r, faces, options);

  PlyPass<Bits> pass(*ply, *weld, release_pages);
  BoundarySums sums;
  if (!pass.face_pass(reference, tally, sums)) return std::nullopt;
  props.mass =
      mesh_mass_properties_from_sums(sums, reference, box, ply->vertex_count, ply->face_count,
                                     ply->face_count, mass_options, single_precision);
  pass.edge_pass(budget.half_edges ? budget.half_edges : default_budget(bytes.size()));
  r.edges = pass.edges.edges;
  r.collapsed_faces = pass.collapsed_faces;
  r.unreferenced_vertices = pass.unreferenced_vertices;
  pass.number_components(tally.components);
  pass.component_sums(tally);
  std::vector<detail::OddEdge>& odd = pass.edges.odd;
  std::vector<std::uint32_t> odd_component(odd.size());
  for (std::size_t i = 0; i < odd.size(); ++i) odd_component[i] = pass.component(odd[i].face);
  // One component has no nesting to find: free the faces' arrays now. With several, finish_report
  // reads face → component once more (4 bytes a face, docs/conventions.md §8).
  const bool several_components = tally.components.size() > 1;
  if (several_components)
    tally.face_component = pass.face_components();
  else
    pass.free_faces();

  // The rest of the report reads positions as doubles and the corners of a few faces (boundary
  // sides, duplicated faces) from the file.
  const std::span<const Vec3d> positions = weld->positions.to_doubles();
  faces.positions = positions;
  faces.representative = weld->representative;
  faces.corner_lookup = [&](std::uint32_t corner) {
    return weld->welded(ply->index(ply->face(corner / 3), corner % 3));
  };
  for (std::size_t i = 0; i < odd.size(); ++i)
    detail::tally_edge(tally, odd[i].v0, odd[i].v1, odd[i].face, odd[i].uses, odd[i].forward,
                       odd_component[i]);
  std::vector<std::uint32_t>& sides = pass.edges.sides;
  std::sort(sides.begin(), sides.end());
  std::vector<std::uint32_t> tails(sides.size()), heads(sides.size());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const std::uint32_t h = sides[i];
    tails[i] = faces.corner_lookup(h);
    heads[i] = faces.corner_lookup(h % 3 == 2 ? h - 2 : h + 1);
  }
  detail::finish_report(tally, detail::duplicated_faces(pass.edges.same_vertices),
                        trace_boundary_loops(sides, tails, heads, positions, reference));
  if (several_components) pass.free_faces();

  source = MeshSource{};
  source.path = name;
  source.format = format;
  source.single_precision = single_precision;
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  return props;
}

}  // namespace

std::optional<WeldedTriangleProps> ply_triangle_props(std::span<const char> bytes,
                                                      const std::string& name, MeshSource& source,
                                                      const MassOptions& mass_options,
                                                      const TopologyOptions& options,
                                                      bool release_pages, PlyPassBudget budget) {
  detail::check_topology_options(options);
  if (options.weld_tolerance != 0) return std::nullopt;
  detail::TextCursor c(bytes, name);
  const detail::Header h = detail::parse_header(c);
  const detail::Layout l = detail::find_layout(h, c);
  const std::optional<PlainPly> ply = plain_ply(bytes, h, l);
  if (!ply) return std::nullopt;
  if (ply->coordinate_type == PlyType::f32)
    return plain_ply_props<std::uint32_t>(bytes, name, h.format, &*ply, source, mass_options,
                                          options, release_pages, budget);
  return plain_ply_props<std::uint64_t>(bytes, name, h.format, &*ply, source, mass_options, options,
                                        release_pages, budget);
}

}  // namespace pgamesh
