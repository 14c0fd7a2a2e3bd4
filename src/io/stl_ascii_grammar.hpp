// Internal: the one grammar of ASCII STL. The parser hands every facet to a consumer — the Mesh
// builder of read_stl_ascii (read_stl.cpp) or the summing consumer of `props --no-topology`
// (mesh/mass/stl_ascii_sums.hpp) — so both read exactly the same files with the same repairs,
// warnings and errors (message and line:column).
//
//   solid NAME / { facet normal N / outer loop / vertex X Y Z (3 or more) / endloop / endfacet }
//   / endsolid NAME
//
// Keywords in any letter case, several solids in a row allowed. The rest of the 'solid',
// 'endsolid' and 'facet' lines is skipped unread (names may hold any bytes; NaN normals of
// degenerate facets are common and harmless: the vertex order is the truth).
//
// The same grammar reads SLP (Pro/ENGINEER render files, docs/formats.md): 'color R G B' lines
// between facets and inside them, and 'normal N' lines (vertex normals) between 'facet' and
// 'outer loop', are skipped unread; they never occur in an STL that would be read otherwise.
// 'end solid' in two words closes a solid as 'endsolid' does.
//
// A consumer has two members:
//   void vertex(const Vec3d& v);    // the next vertex of the current facet, in file order
//   void end_facet(std::size_t n);  // the current facet is complete: its last n ≥ 3 vertices
//
// parse_ascii_stl() parses the whole text on the calling thread. parse_ascii_stl_pieces() cuts the
// text into pieces at 'facet' lines and parses them on several threads, one consumer per piece;
// when the pieces do not join up into the text's one reading (which, in a file the grammar
// accepts, they always do) or one fails, the whole text is parsed again on one thread, so that
// every error is reported exactly as parse_ascii_stl() reports it.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "detail/memory/page_release.hpp"
#include "geometry/chunked_sums.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::detail {

// Bytes of text per piece: large enough that a piece costs far more than handing it out, small
// enough that two threads share a file of a few MB evenly. Pieces after the first start at a line
// whose first word is 'facet'.
inline constexpr std::size_t stl_ascii_piece_bytes = std::size_t{1} << 19;

// What the grammar has read besides the facets: the state between statements and the repairs it
// made, from which the reader's warnings come (add_stl_ascii_warnings).
struct StlAsciiState {
  bool in_solid = true;                 // between 'solid' and 'endsolid'
  std::uint64_t vertices = 0;           // vertex lines
  std::uint64_t facets = 0;             // complete facets
  std::uint64_t triangles = 0;          // Σ (vertices − 2) over the facets
  std::uint64_t polygons = 0;           // facets with more than 3 vertices, kept as polygons
  const char* first_polygon = nullptr;  // the 'facet' keyword of the first of them
};

// The opening of the text: an optional UTF-8 byte order mark, 'solid' and the rest of its line.
void parse_stl_ascii_header(TextCursor& c);

// The reader's warnings for what `s` (the state after the whole text) repaired: a missing final
// 'endsolid', facets kept as polygons (at the line of the first). `begin` is the text's start.
void add_stl_ascii_warnings(const StlAsciiState& s, const char* begin, const std::string& name,
                            std::vector<std::string>& warnings);

// Vertex lines sampled to place the reference point of a streamed sum (docs/conventions.md §13):
// the box of at most this many, evenly spaced through the text, as the binary STL samples records.
inline constexpr std::size_t stl_ascii_reference_samples = 4096;

// The bounding box of the finite vertices of up to `samples` vertex lines evenly spaced through
// the text: from each k-th fraction of it, the first line (within a few KiB) whose first word is
// 'vertex' and that three numbers follow. It depends on the bytes only and reads no more than
// samples × 4 KiB of them; lines that do not read as a vertex are passed over, since the grammar,
// not the sample, judges the text. With `release_pages`, the pages the samples pass are given back
// as they go.
Box3 stl_ascii_sampled_box(std::span<const char> bytes, const std::string& name, bool release_pages,
                           std::size_t samples = stl_ascii_reference_samples);

// Piece boundaries for parse_ascii_stl_pieces: [starts[k], starts[k + 1]) is piece k; piece 0
// starts at the text's first byte, every later one at a 'facet' line at or after the k-th
// multiple of `piece_bytes`. They depend on the bytes only, never on the thread count. With
// `release_pages`, the pages the search passes are given back as it goes.
std::vector<const char*> stl_ascii_piece_starts(std::span<const char> bytes,
                                                std::size_t piece_bytes, bool release_pages);

// Whether the keyword `k` (lower-case letters) is at c.p in any letter case as a whole word,
// followed by whitespace or the end: same_word(c.word(), k) at a word's start (for a letter,
// b | 0x20 is its lower case, and no other byte maps onto a lower-case letter) without scanning the
// word first. Moves c.p past the keyword when it is there.
inline bool keyword(TextCursor& c, std::string_view k) {
  if (static_cast<std::size_t>(c.end - c.p) < k.size()) return false;
  for (std::size_t i = 0; i < k.size(); ++i)
    if ((c.p[i] | 0x20) != k[i]) return false;
  const char* q = c.p + k.size();
  if (q != c.end && !is_space(*q)) return false;
  c.p = q;
  return true;
}

// 'end solid': 'endsolid' written as two words on one line, as an SLP exporter writes it. Leaves
// the cursor where it was when the line says something else.
inline bool end_solid_two_words(TextCursor& c) {
  const char* start = c.p;
  if (!keyword(c, "end")) return false;
  c.skip_blanks();
  if (keyword(c, "solid")) return true;
  c.p = start;
  return false;
}

// c.coordinate(what) with its common case inline: a plain decimal that simple_decimal reads, ending
// at whitespace or the end, is what TextCursor::number returns for it; anything else (from_chars,
// errors and their positions) is left to c.coordinate from the same position.
inline double coordinate(TextCursor& c, const char* what) {
  const char* s = c.p;
  while (s != c.end && is_blank(*s)) ++s;
  if (s != c.end && *s == '+' && s + 1 != c.end && s[1] != '-') ++s;  // as TextCursor::number
  double v;
  const char* q = simple_decimal(s, c.end, v);
  if (q && (q == c.end || is_space(*q))) {
    c.p = q;
    return v;
  }
  return c.coordinate(what);
}

// The statements from c.p to c.end, starting in the solid state s.in_solid, each facet handed to
// `out`; `release` is told how far the parser has got. Throws InputError at the first thing that
// is not ASCII STL, with its line:column within [c.begin, c.end).
template <class Consumer>
void parse_stl_ascii_statements(TextCursor& c, StlAsciiState& s, Consumer& out,
                                PageRelease& release) {
  auto expect = [&](std::string_view k) {
    c.skip_space();
    if (!keyword(c, k))
      c.fail(c.p, "expected '" + std::string(k) + "', found " + describe_at(c.p, c.end));
  };
  for (;;) {
    release.passed(c.p);
    c.skip_space();
    if (c.at_end()) break;
    const char* at = c.p;
    if (s.in_solid && keyword(c, "facet")) {
      c.skip_line();  // "normal nx ny nz" is ignored: the vertex order is the truth
      for (;;) {      // SLP's vertex normals and colours
        c.skip_space();
        if (!keyword(c, "normal") && !keyword(c, "color")) break;
        c.skip_line();
      }
      expect("outer");
      expect("loop");
      std::size_t n = 0;
      for (;;) {
        c.skip_space();
        const char* vat = c.p;
        if (keyword(c, "vertex")) {
          Vec3d v;
          v.x = coordinate(c, "x coordinate");
          v.y = coordinate(c, "y coordinate");
          v.z = coordinate(c, "z coordinate");
          c.skip_blanks();
          if (!c.at_eol()) c.fail(c.p, "unexpected " + describe_at(c.p, c.end) + " after vertex");
          if (s.vertices >= max_vertices) c.fail(vat, "too many vertices for 32-bit indices");
          ++s.vertices;
          out.vertex(v);
          ++n;
        } else if (keyword(c, "endloop")) {
          break;
        } else if (keyword(c, "color")) {  // SLP
          c.skip_line();
        } else {
          c.fail(vat, "expected 'vertex' or 'endloop', found " + describe_at(vat, c.end));
        }
      }
      if (n < 3)
        c.fail(at, "facet with " + std::to_string(n) + " vertices (a face needs at least 3)");
      if (n > 3 && s.polygons++ == 0) s.first_polygon = at;
      ++s.facets;
      s.triangles += n - 2;
      out.end_facet(n);
      expect("endfacet");
    } else if (s.in_solid && keyword(c, "color")) {  // SLP: the colour of the next facets
      c.skip_line();
    } else if (s.in_solid && (keyword(c, "endsolid") || end_solid_two_words(c))) {
      c.skip_line();
      s.in_solid = false;
    } else if (!s.in_solid && keyword(c, "solid")) {
      c.skip_line();
      s.in_solid = true;
    } else {
      c.fail(at, std::string("expected ") + (s.in_solid ? "'facet' or 'endsolid'" : "'solid'") +
                     ", found " + describe_at(at, c.end));
    }
  }
}

// The whole text on the calling thread, each facet handed to `out`. With `release_pages` (the
// bytes of a read-only file mapping only) the pages passed are given back as the parser goes.
// Returns the state after the text; throws InputError as parse_stl_ascii_statements.
template <class Consumer>
StlAsciiState parse_ascii_stl(std::span<const char> bytes, const std::string& name, Consumer& out,
                              bool release_pages = false) {
  TextCursor c(bytes, name);
  PageRelease release(bytes.data(), release_pages);
  StlAsciiState s;
  parse_stl_ascii_header(c);
  parse_stl_ascii_statements(c, s, out, release);
  return s;
}

// One piece of the text and what its consumer was handed.
template <class Consumer>
struct StlAsciiPiece {
  Consumer out;
  StlAsciiState state;
};

// The state after all the pieces, as parse_ascii_stl would return it for the whole text.
template <class Consumer>
StlAsciiState joined_state(const std::vector<StlAsciiPiece<Consumer>>& pieces) {
  StlAsciiState s;
  for (const auto& p : pieces) {
    s.in_solid = p.state.in_solid;
    s.vertices += p.state.vertices;
    s.facets += p.state.facets;
    s.triangles += p.state.triangles;
    if (p.state.polygons && !s.polygons) s.first_polygon = p.state.first_polygon;
    s.polygons += p.state.polygons;
  }
  return s;
}

// The text parsed in pieces of about `piece_bytes` (stl_ascii_piece_starts) on up to `threads`
// threads (0: all), piece k handed to a consumer of its own, make_consumer(size of piece k in
// bytes). The pieces come back in file order: their consumers together were handed the facets of
// the text in order, and joined_state(pieces) is parse_ascii_stl's state. When the pieces do not
// join up (a piece fails, a piece starts where the text's one reading is not between statements,
// more vertices than 32-bit indices), the whole text is parsed again by parse_ascii_stl into one
// piece: it throws the error, if any, at its exact position. With `release_pages`, as
// parse_ascii_stl, each piece's pages are given back once it is parsed.
template <class Consumer, class MakeConsumer>
std::vector<StlAsciiPiece<Consumer>> parse_ascii_stl_pieces(
    std::span<const char> bytes, const std::string& name, unsigned threads, bool release_pages,
    const MakeConsumer& make_consumer, std::size_t piece_bytes = stl_ascii_piece_bytes) {
  std::vector<StlAsciiPiece<Consumer>> pieces;
  auto whole = [&] {
    pieces.clear();
    pieces.push_back({make_consumer(bytes.size()), {}});
    pieces[0].state = parse_ascii_stl(bytes, name, pieces[0].out, release_pages);
    return std::move(pieces);
  };
  const std::vector<const char*> starts = stl_ascii_piece_starts(bytes, piece_bytes, release_pages);
  const std::size_t count = starts.size() - 1;
  if (count <= 1) return whole();
  for (std::size_t k = 0; k < count; ++k)
    pieces.push_back({make_consumer(static_cast<std::size_t>(starts[k + 1] - starts[k])), {}});
  std::vector<char> failed(count, 0);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  auto work = [&] {
    for (std::size_t k; !stop.load(std::memory_order_relaxed) &&
                        (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      try {
        // A cursor over the piece alone: an error's line:column (discarded) costs the piece only.
        TextCursor c({starts[k], starts[k + 1]}, name);
        if (k == 0) parse_stl_ascii_header(c);  // later pieces start inside a solid, at a facet
        PageRelease none;
        // The piece's state and consumer work on this thread's stack and are moved back after:
        // written in place, neighbouring pieces (parsed at the same time by other threads) would
        // share cache lines at their edges, and every vertex would pass them between cores.
        StlAsciiPiece<Consumer> piece{std::move(pieces[k].out), {}};
        parse_stl_ascii_statements(c, piece.state, piece.out, none);
        pieces[k] = std::move(piece);
      } catch (...) {  // reported, if it is the text's error, by the parse of the whole text
        failed[k] = 1;
        stop.store(true, std::memory_order_relaxed);
      }
      if (release_pages) detail::release_pages(starts[k], starts[k + 1]);
    }
  };
  const std::size_t workers = std::min<std::size_t>(resolve_threads(threads), count);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (release_pages)
    detail::release_pages(bytes.data(), bytes.data() + bytes.size());  // shared edges
  // Every later piece starts at a facet inside a solid: the one before must end inside a solid.
  for (std::size_t k = 0; k < count; ++k)
    if (failed[k] || (k + 1 < count && !pieces[k].state.in_solid)) return whole();
  if (joined_state(pieces).vertices > max_vertices) return whole();
  return pieces;
}

}  // namespace pgamesh::detail
