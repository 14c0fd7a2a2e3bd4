#include "io/stl_ascii_grammar.hpp"

#include <algorithm>

namespace pgamesh::detail {

namespace {

// Whether the line starting at `line` has 'facet' (any letter case) as its first word.
bool facet_line(const char* line, const char* end) {
  while (line != end && is_blank(*line)) ++line;
  const char* word = line;
  while (line != end && !is_space(*line)) ++line;
  return same_word({word, static_cast<std::size_t>(line - word)}, "facet");
}

const char* after_line(const char* p, const char* end) {
  const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  return nl ? static_cast<const char*>(nl) + 1 : end;
}

// The start of the first line at or after `from` (a line start) whose first word is 'facet', or
// `end`.
const char* next_facet_line(const char* from, const char* end) {
  for (const char* line = from; line != end; line = after_line(line, end))
    if (facet_line(line, end)) return line;
  return end;
}

}  // namespace

void parse_stl_ascii_header(TextCursor& c) {
  if (c.end - c.p >= 3 && std::memcmp(c.p, "\xEF\xBB\xBF", 3) == 0) c.p += 3;
  c.skip_space();
  const char* at = c.p;
  if (!same_word(c.word(), "solid"))
    c.fail(at, std::string("expected 'solid', found ") + describe_at(at, c.end));
  c.skip_line();  // the solid's name: any bytes
}

void add_stl_ascii_warnings(const StlAsciiState& s, const char* begin, const std::string& name,
                            std::vector<std::string>& warnings) {
  if (s.in_solid) warnings.push_back(name + ": missing 'endsolid' at the end (file truncated?)");
  if (s.polygons) {
    const InputPosition pos = text_position(begin, s.first_polygon);
    warnings.push_back(name + ":" + std::to_string(pos.line) + ": " + std::to_string(s.polygons) +
                       " facet(s) with more than 3 vertices kept as polygons");
  }
}

Box3 stl_ascii_sampled_box(std::span<const char> bytes, const std::string& name, bool release_pages,
                           std::size_t samples) {
  // A facet is about 250 bytes: a vertex line is found within a few of them.
  constexpr std::size_t scan_bytes = 4096;
  const char* first = bytes.data();
  const char* end = first + bytes.size();
  Box3 box;
  const char* scan = first;  // the samples move forward only
  PageRelease release(first, release_pages);
  for (std::size_t k = 0; k < samples && scan != end; ++k) {
    release.passed(scan);
    const char* target = first + bytes.size() / samples * k;
    const char* line = k == 0 ? first : after_line(std::max(target, scan), end);
    const char* limit =
        end - line > static_cast<std::ptrdiff_t>(scan_bytes) ? line + scan_bytes : end;
    for (; line < limit; line = after_line(line, end)) {
      TextCursor c({line, end}, name);
      c.skip_blanks();
      if (!keyword(c, "vertex")) continue;
      try {
        Vec3d v;
        v.x = coordinate(c, "x coordinate");
        v.y = coordinate(c, "y coordinate");
        v.z = coordinate(c, "z coordinate");
        if (is_finite(v)) box.add(v);
      } catch (const InputError&) {  // not a vertex the grammar would read: not a sample
      }
      break;
    }
    scan = line;
  }
  return box;
}

std::vector<const char*> stl_ascii_piece_starts(std::span<const char> bytes,
                                                std::size_t piece_bytes, bool release_pages) {
  const char* first = bytes.data();
  const char* end = first + bytes.size();
  std::vector<const char*> starts{first};
  const char* scan = first;
  PageRelease release(first, release_pages);
  for (std::size_t k = 1;; ++k) {
    release.passed(scan);
    const std::size_t offset = k * piece_bytes;
    if (offset >= bytes.size()) break;
    const char* target = first + offset;
    if (target < scan) target = scan;  // a search never goes over bytes an earlier one passed
    const char* start = next_facet_line(after_line(target, end), end);
    if (start == end) break;
    starts.push_back(start);
    scan = start + 1;
  }
  starts.push_back(end);
  return starts;
}

}  // namespace pgamesh::detail
