#include "pgamesh/mesh/mass/stl_ascii_mass_properties.hpp"

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>
#include <thread>
#include <vector>

#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/geometry/chunked_sums.hpp"
#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh {

namespace {

using detail::is_blank;
using detail::is_space;

// Vertices sampled to place the reference point (ERRATA §6): evenly spaced lines of a large file.
constexpr std::size_t reference_samples = 4096;

void skip_blanks(const char*& p, const char* end) {
  while (p != end && is_blank(*p)) ++p;
}
void skip_space(const char*& p, const char* end) {
  while (p != end && is_space(*p)) ++p;
}
void skip_line(const char*& p, const char* end) {
  const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  p = nl ? static_cast<const char*>(nl) + 1 : end;
}

// The keyword `k` (lower-case letters) at p in any letter case, as a whole word: followed by
// whitespace or the end. For a letter, c | 0x20 is its lower case, and no other byte maps onto a
// lower-case letter, so this is detail::same_word with fixed byte compares. Moves p past it.
bool keyword(const char*& p, const char* end, std::string_view k) {
  if (static_cast<std::size_t>(end - p) < k.size()) return false;
  for (std::size_t i = 0; i < k.size(); ++i)
    if ((p[i] | 0x20) != k[i]) return false;
  const char* q = p + k.size();
  if (q != end && !is_space(*q)) return false;
  p = q;
  return true;
}

// One finite number ending at whitespace or the end, read exactly as TextCursor::coordinate reads
// it (the exact fast path, else std::from_chars); false for anything that would be an error there.
bool coordinate(const char*& p, const char* end, double& v) {
  skip_blanks(p, end);
  const char* s = p;
  if (s != end && *s == '+' && s + 1 != end && s[1] != '-') ++s;  // as TextCursor::number
  const char* q = detail::simple_decimal(s, end, v);
  if (!q) {
    const auto r = std::from_chars(s, end, v);
    if (r.ec != std::errc{}) return false;
    q = r.ptr;
  }
  if ((q != end && !is_space(*q)) || !std::isfinite(v)) return false;
  p = q;
  return true;
}

// "vertex x y z" and the end of its line, as read_stl_ascii requires.
bool vertex_line(const char*& p, const char* end, Vec3d& v) {
  skip_space(p, end);
  if (!keyword(p, end, "vertex") || !coordinate(p, end, v.x) || !coordinate(p, end, v.y) ||
      !coordinate(p, end, v.z))
    return false;
  skip_blanks(p, end);
  return p == end || *p == '\n';
}

// What one piece of the file adds up to.
struct PieceSums {
  BoundarySums sums;
  std::uint64_t facets = 0;
  bool plain = true;     // the piece was read in full by the fast grammar
  bool in_solid = true;  // state at the end of the piece (between 'solid' and 'endsolid')
};

// Parses [p, end) with the statement grammar of read_stl_ascii — 'facet' … 'endfacet' inside a
// solid, 'endsolid' and 'solid' lines between them — starting in the given solid state. Stops at
// the first thing read_stl_ascii would read differently or reject (plain = false).
void sum_piece(const char* p, const char* end, bool in_solid, Vec3d ref, PieceSums& out) {
  LanedSums<> s;  // the lanes of chunked_sums, so that a one-piece file sums as one chunk
  std::uint64_t facets = 0;
  out.plain = false;
  for (;;) {
    skip_space(p, end);
    if (p == end) break;
    if (in_solid && keyword(p, end, "facet")) {
      skip_line(p, end);  // "normal nx ny nz" is ignored: the vertex order is the truth
      skip_space(p, end);
      if (!keyword(p, end, "outer")) return;
      skip_space(p, end);
      if (!keyword(p, end, "loop")) return;
      Vec3d a, b, c;
      if (!vertex_line(p, end, a) || !vertex_line(p, end, b) || !vertex_line(p, end, c)) return;
      skip_space(p, end);
      if (!keyword(p, end, "endloop")) return;  // a fourth vertex: a polygon for the careful path
      skip_space(p, end);
      if (!keyword(p, end, "endfacet")) return;
      add_triangle(s[facets], a - ref, b - ref, c - ref);
      ++facets;
    } else if (in_solid && keyword(p, end, "endsolid")) {
      skip_line(p, end);
      in_solid = false;
    } else if (!in_solid && keyword(p, end, "solid")) {
      skip_line(p, end);  // the solid's name: any bytes
      in_solid = true;
    } else {
      return;
    }
  }
  out.sums = s.total();
  out.facets = facets;
  out.plain = true;
  out.in_solid = in_solid;
}

// The start of the first line at or after `from` (a line start) whose first word is 'facet', or
// `end`.
const char* next_facet_line(const char* from, const char* end) {
  for (const char* line = from; line != end;) {
    const char* q = line;
    skip_blanks(q, end);
    if (keyword(q, end, "facet")) return line;
    skip_line(line, end);
  }
  return end;
}

// Piece boundaries: every piece but the first starts at a 'facet' line, the first at or after
// (first + k × piece bytes). They depend on the bytes only, never on the thread count. With
// `release_pages`, the pages looked at are given back as the search passes them (as in
// vertex_box).
std::vector<const char*> piece_starts(const char* first, const char* end, bool release_pages) {
  std::vector<const char*> starts{first};
  const char* scan = first;
  detail::PageRelease release(first, release_pages);
  for (std::size_t k = 1;; ++k) {
    release.passed(scan);
    const auto offset = k * stl_ascii_piece_bytes;
    if (offset >= static_cast<std::size_t>(end - first)) break;
    const char* target = first + offset;
    if (target < scan) target = scan;
    skip_line(target, end);  // to the next line start
    const char* start = next_facet_line(target, end);
    if (start == end) break;
    starts.push_back(start);
    scan = start + 1;
  }
  starts.push_back(end);
  return starts;
}

// The bounding box of the vertex lines of the text: of all of them in a file of at most one piece
// (so that a small file is summed about the same point as reference_point() of its mesh), else of
// those starting the lines after evenly spaced offsets. Lines that do not parse are skipped here;
// the summing pass judges them. With `release_pages`, the pages sampled are given back as the
// samples pass (a fault maps a whole folio of the page cache around the sampled line, so the
// samples of a large file would otherwise map all of it).
Box3 vertex_box(const char* begin, const char* end, bool release_pages) {
  Box3 box;
  auto add_line = [&](const char* p) {
    Vec3d v;
    if (vertex_line(p, end, v)) box.add(v);
  };
  const auto size = static_cast<std::size_t>(end - begin);
  if (size <= stl_ascii_piece_bytes) {
    for (const char* line = begin; line != end; skip_line(line, end)) add_line(line);
  } else {
    // Each sample looks for its line start before the next sample's offset only: a file without
    // newlines costs one pass, not one per sample.
    const std::size_t step = size / reference_samples;
    detail::PageRelease release(begin, release_pages);
    for (std::size_t i = 0; i < reference_samples; ++i) {
      const char* p = begin + step * i;
      release.passed(p);
      const void* nl = std::memchr(p, '\n', step);
      if (nl) add_line(static_cast<const char*>(nl) + 1);
    }
  }
  return box;
}

}  // namespace

std::optional<MassProperties> ascii_stl_mass_properties(std::span<const char> bytes,
                                                        const std::string& name,
                                                        const MassOptions& options,
                                                        bool release_pages) {
  // What read_mesh_bytes() would not read as ASCII STL — e.g. text with a control byte in its
  // first KiB, which it takes for a broken binary STL — is not ours to read either.
  if (detect_format(bytes) != MeshFormat::stl_ascii) return std::nullopt;
  const char* first = bytes.data();
  const char* end = first + bytes.size();
  if (bytes.size() >= 3 && std::memcmp(first, "\xEF\xBB\xBF", 3) == 0) first += 3;  // BOM
  const Vec3d ref = vertex_box(first, end, release_pages).centre();

  const std::vector<const char*> starts = piece_starts(first, end, release_pages);
  const std::size_t pieces = starts.size() - 1;
  if (release_pages) detail::release_pages(bytes.data(), end);  // the last samples and searches
  std::vector<PieceSums> piece(pieces);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < pieces;) {
      sum_piece(starts[k], starts[k + 1], k > 0, ref, piece[k]);  // the header opens piece 0
      if (release_pages) detail::release_pages(starts[k], starts[k + 1]);
    }
  };
  const std::size_t workers = std::min<std::size_t>(resolve_threads(options.threads), pieces);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (release_pages) detail::release_pages(bytes.data(), end);  // the pieces' shared edge pages

  // In file order: every later piece starts at a facet, so the one before must end inside a solid.
  BoundarySums total;
  std::uint64_t facets = 0;
  for (std::size_t k = 0; k < pieces; ++k) {
    if (!piece[k].plain || (k + 1 < pieces && !piece[k].in_solid)) return std::nullopt;
    total += piece[k].sums;
    facets += piece[k].facets;
  }
  // No facets (an empty solid, an empty file) or more vertices than read_stl_ascii indexes: the
  // careful path decides.
  if (facets == 0 || 3 * facets > detail::max_vertices) return std::nullopt;

  MassProperties p = mass_properties_from_sums(total, ref, options);
  p.faces = p.triangles = facets;
  p.vertices = 3 * facets;
  if (piece.back().in_solid)
    p.warnings.push_back(name + ": missing 'endsolid' at the end (file truncated?)");
  return p;
}

}  // namespace pgamesh
