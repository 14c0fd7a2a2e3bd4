#include "pgamesh/mesh/weld/weld.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesh/weld/weld_table.hpp"

namespace pgamesh {

namespace {

// The table's keys are the classes' first vertices: hashed and compared by their coordinates'
// bits with −0 folded to +0 (CoordinateKeyTraits of weld_table.hpp, as the binary STL and PLY
// welds hash theirs), so that the two zeros weld while every other value welds only with itself.
struct ExactTraits {
  using Bits = detail::CoordinateKeyTraits<std::uint64_t>;
  static detail::CoordinateKey<std::uint64_t> bits(const Vec3d& v) {
    return {std::bit_cast<std::uint64_t>(v.x), std::bit_cast<std::uint64_t>(v.y),
            std::bit_cast<std::uint64_t>(v.z)};
  }
  static std::uint64_t hash(const Vec3d& v) { return Bits::hash(bits(v)); }
  static bool same(const Vec3d& a, const Vec3d& b) { return Bits::same(bits(a), bits(b)); }
};
using ExactTable = detail::WeldTable<Vec3d, ExactTraits>;

// The exact weld of `v`, the classes' first vertices appended to `keys` (a std::vector<Vec3d> or
// KeysInPlace over v itself).
template <class Keys>
WeldMap weld_exact(std::span<const Vec3d> v, Keys& keys) {
  WeldMap out;
  const std::size_t n = v.size();
  detail::reserve_huge(out.to_welded, n);
  out.to_welded.resize(n);
  // Meshes read from STL share each vertex among about six corners: start the table for n / 4
  // classes and let it grow, so the common case touches a table that is 4× smaller.
  ExactTable table(n / 4 + 16);
  detail::reserve_huge(out.representative, n / 4 + 16);

  detail::visit_prefetched(
      table, n, [&](std::size_t i) { return ExactTraits::hash(v[i]); },
      [&](std::size_t i, std::uint64_t h) {
        bool inserted = false;
        out.to_welded[i] = table.find_or_insert(v[i], h, keys, inserted);
        if (inserted) out.representative.push_back(static_cast<std::uint32_t>(i));
        return true;
      });
  out.merged = n - out.representative.size();
  return out;
}

struct Cell {
  std::int64_t x, y, z;
  friend bool operator==(const Cell&, const Cell&) = default;
};
struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return detail::mix64(std::uint64_t(c.x) ^
                         detail::mix64(std::uint64_t(c.y) ^ detail::mix64(std::uint64_t(c.z))));
  }
};

// floor(x / tolerance) as an integer, clamped so that the conversion is always defined.
inline std::int64_t cell_coordinate(double x, double tolerance) {
  constexpr double limit = 4.0e18;
  const double q = std::floor(x / tolerance);
  if (!(q > -limit)) return static_cast<std::int64_t>(-limit);  // also NaN
  if (!(q < limit)) return static_cast<std::int64_t>(limit);
  return static_cast<std::int64_t>(q);
}

WeldMap weld_tolerance(std::span<const Vec3d> v, double tolerance) {
  WeldMap out;
  out.tolerance = tolerance;
  const std::size_t n = v.size();
  out.to_welded.resize(n);
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::unordered_map<Cell, std::uint32_t, CellHash> head;  // cell → its latest leader
  head.reserve(n / 4 + 16);
  std::vector<std::uint32_t> next_in_cell;  // welded id → previous leader of the same cell
  const double tolerance2 = tolerance * tolerance;
  for (std::size_t i = 0; i < n; ++i) {
    const Cell c{cell_coordinate(v[i].x, tolerance), cell_coordinate(v[i].y, tolerance),
                 cell_coordinate(v[i].z, tolerance)};
    std::uint32_t best = none;
    double best_d2 = 0;
    // A leader within the tolerance lies in one of the 27 cells around c (cell size = tolerance).
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = head.find(Cell{c.x + dx, c.y + dy, c.z + dz});
          if (it == head.end()) continue;
          for (std::uint32_t id = it->second; id != none; id = next_in_cell[id]) {
            const Vec3d d = v[out.representative[id]] - v[i];
            const double d2 = dot(d, d);
            if (d2 <= tolerance2 && id < best) {
              best = id;
              best_d2 = d2;
            }
          }
        }
    if (best == none) {
      const auto id = static_cast<std::uint32_t>(out.representative.size());
      out.representative.push_back(static_cast<std::uint32_t>(i));
      auto [it, fresh] = head.try_emplace(c, id);
      next_in_cell.push_back(fresh ? none : it->second);
      it->second = id;
      out.to_welded[i] = id;
    } else {
      out.to_welded[i] = best;
      out.max_moved = std::max(out.max_moved, std::sqrt(best_d2));
    }
  }
  out.merged = n - out.representative.size();
  return out;
}

}  // namespace

WeldMap weld_map(std::span<const Vec3d> vertices, double tolerance) {
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("weld tolerance must be a finite number >= 0");
  if (vertices.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("weld: more than 2^32 - 2 vertices");
  if (tolerance != 0) return weld_tolerance(vertices, tolerance);
  std::vector<Vec3d> keys;
  detail::reserve_huge(keys, vertices.size() / 4 + 16);
  return weld_exact(vertices, keys);
}

WeldMap weld_map_compacting(std::vector<Vec3d>& vertices, double tolerance) {
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    throw std::invalid_argument("weld tolerance must be a finite number >= 0");
  if (vertices.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("weld: more than 2^32 - 2 vertices");
  WeldMap map;
  if (tolerance == 0) {
    detail::KeysInPlace<Vec3d> keys{vertices.data()};
    map = weld_exact(vertices, keys);  // leaves the first vertex of every class at its id
  } else {
    map = weld_tolerance(vertices, tolerance);
    // representative[id] ≥ id (numbered in order of first vertex): no move overwrites a source.
    for (std::size_t id = 0; id < map.welded_count(); ++id)
      vertices[id] = vertices[map.representative[id]];
  }
  if (map.welded_count() < vertices.size()) {
    vertices.resize(map.welded_count());
    vertices.shrink_to_fit();
  }
  return map;
}

namespace {

void check_corner_range(const Mesh& mesh) {
  for (std::uint32_t c : mesh.corners)
    if (c >= mesh.vertices.size())
      throw std::out_of_range("weld: corner index " + std::to_string(c) + " out of range (" +
                              std::to_string(mesh.vertices.size()) + " vertices)");
}

}  // namespace

WeldResult weld(const Mesh& mesh, double tolerance) {
  check_corner_range(mesh);
  WeldResult r;
  r.map = weld_map(mesh.vertices, tolerance);
  r.mesh.vertices.reserve(r.map.welded_count());
  for (std::uint32_t rep : r.map.representative) r.mesh.vertices.push_back(mesh.vertices[rep]);
  r.mesh.corners.resize(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    r.mesh.corners[c] = r.map.to_welded[mesh.corners[c]];
  r.mesh.face_offsets = mesh.face_offsets;
  return r;
}

WeldResult weld(Mesh&& mesh, double tolerance) {
  check_corner_range(mesh);
  WeldResult r;
  r.map = weld_map_compacting(mesh.vertices, tolerance);
  for (std::uint32_t& c : mesh.corners) c = r.map.to_welded[c];
  r.mesh = std::move(mesh);
  mesh = Mesh{};
  return r;
}

}  // namespace pgamesh
