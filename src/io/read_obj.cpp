// Wavefront OBJ: `v` positions (an optional w and/or colour are read and ignored) and `f`
// polygons of any size with 1-based or negative (relative) indices, `i`, `i/t`, `i//n`, `i/t/n`.
// Groups and objects (`g`, `o`) are counted; materials, smoothing groups, texture coordinates and
// normals are skipped; free-form geometry and `l`/`p` elements are skipped with a warning.
#include <algorithm>
#include <string>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh::detail {

namespace {

// Statements that carry nothing this library measures.
bool is_skipped_statement(std::string_view w) {
  static constexpr std::string_view keys[] = {
      "vt",       "vn",    "s",          "mtllib",    "usemtl", "maplib",
      "usemap",   "lod",   "shadow_obj", "trace_obj", "bevel",  "c_interp",
      "d_interp", "ctech", "stech",      "mg",        "vc"};
  return std::find(std::begin(keys), std::end(keys), w) != std::end(keys);
}

// Free-form curves and surfaces, lines and points: geometry we do not use, reported once.
bool is_unsupported_statement(std::string_view w) {
  static constexpr std::string_view keys[] = {
      "vp",   "l",    "p",    "cstype", "deg", "bmat", "step", "curv", "curv2", "surf",
      "parm", "trim", "hole", "scrv",   "sp",  "end",  "con",  "call", "csh"};
  return std::find(std::begin(keys), std::end(keys), w) != std::end(keys);
}

}  // namespace

void read_obj(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages) {
  TextCursor c(bytes, name);
  PageRelease release(bytes.data(), release_pages);
  source.format = MeshFormat::obj;
  // Estimates only (vectors grow past them), generous because growing copies the array (a peak of
  // old and new side by side) while untouched reserve is virtual memory only: a corner takes at
  // least 2 bytes ("1 "), a typical one 7 or more; a face at least 8 ("f 1 2 3\n"), typically 20.
  reserve_huge(mesh.vertices, bytes.size() / 64);
  reserve_huge(mesh.corners, bytes.size() / 6);
  reserve_huge(mesh.face_offsets, bytes.size() / 16 + 1);

  // Positive indices may refer to vertices defined later in the file; the largest one is checked
  // against the final vertex count, reported at its own position.
  std::uint64_t max_index = 0;
  const char* max_index_at = nullptr;
  std::uint64_t unsupported = 0;
  const char* first_unsupported = nullptr;

  while (!c.at_end()) {
    release.passed(c.p);
    c.skip_blanks();
    if (c.at_eol()) {
      if (!c.at_end()) ++c.p;
      continue;
    }
    const char* at = c.p;
    const char k = *c.p;
    if (k == '#') {
      c.skip_line();
      continue;
    }
    if (k == 'v' && (c.p + 1 == c.end || is_space(c.p[1]))) {
      ++c.p;
      Vec3d v;
      v.x = c.coordinate("x coordinate");
      v.y = c.coordinate("y coordinate");
      v.z = c.coordinate("z coordinate");
      // Optional w (rational weight, unused for polygons) and/or an r g b colour.
      int extra = 0;
      for (;;) {
        c.skip_blanks();
        if (c.at_eol()) break;
        if (++extra > 4) c.fail(c.p, "too many values on a vertex line (at most x y z w r g b)");
        c.number("vertex weight or colour value");
      }
      if (mesh.vertices.size() >= max_vertices) c.fail(at, "too many vertices for 32-bit indices");
      mesh.vertices.push_back(v);
      continue;
    }
    if (k == 'f' && (c.p + 1 == c.end || is_space(c.p[1]))) {
      ++c.p;
      std::size_t n = 0;
      for (;;) {
        c.skip_blanks();
        if (c.at_eol()) break;
        const char* iat = c.p;
        const std::int64_t i = c.integer("vertex index", '/');
        // The texture/normal references after '/' are not used.
        while (c.p != c.end && !is_space(*c.p)) ++c.p;
        std::uint64_t idx;
        if (i > 0) {
          idx = static_cast<std::uint64_t>(i - 1);
          if (idx >= mesh.vertices.size() && (!max_index_at || idx > max_index)) {
            if (idx >= max_vertices)
              c.fail(iat, "vertex index " + std::to_string(i) + " is out of range");
            max_index = idx;
            max_index_at = iat;
          }
        } else if (i < 0) {
          const auto back = static_cast<std::uint64_t>(-(i + 1)) + 1;  // no overflow at INT64_MIN
          if (back > mesh.vertices.size())
            c.fail(iat, "relative vertex index " + std::to_string(i) +
                            " reaches before the first vertex (" +
                            std::to_string(mesh.vertices.size()) + " vertices so far)");
          idx = mesh.vertices.size() - back;
        } else {
          c.fail(iat, "vertex index 0 (OBJ indices start at 1; negative ones count back)");
        }
        mesh.corners.push_back(static_cast<std::uint32_t>(idx));
        ++n;
      }
      if (n < 3) {
        c.fail(at, "face with " + std::to_string(n) + " vertices (a face needs at least 3)");
      }
      mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
      if (mesh.corners.size() > max_vertices)
        c.fail(at, "too many face corners for 32-bit offsets");
      continue;
    }
    const std::string_view w = c.word();
    if (w == "g" || w == "o") {
      ++source.groups;
    } else if (is_unsupported_statement(w)) {
      if (unsupported++ == 0) first_unsupported = at;
    } else if (!is_skipped_statement(w)) {
      c.fail(at, "unknown OBJ statement " + describe_at(at, c.end));
    }
    c.skip_line();
  }
  if (max_index_at && max_index >= mesh.vertices.size())
    c.fail(max_index_at, "vertex index " + std::to_string(max_index + 1) +
                             " is out of range (the file has " +
                             std::to_string(mesh.vertices.size()) + " vertices)");
  if (unsupported) {
    const InputPosition pos = text_position(c.begin, first_unsupported);
    source.warnings.push_back(name + ":" + std::to_string(pos.line) + ": " +
                              std::to_string(unsupported) +
                              " statement(s) with free-form, line or point geometry ignored");
  }
}

}  // namespace pgamesh::detail
