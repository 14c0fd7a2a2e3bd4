// OFF (geomview Object File Format): a header keyword [ST][C][N]OFF, the counts "nv nf ne", nv
// vertex lines "x y z [...]" and nf face lines "n i1 ... in [colour]". Everything after the
// coordinates or indices on a line (normals, texture coordinates, colours) is ignored; '#' starts
// a comment. 4OFF / nOFF (other dimensions) and binary OFF are rejected with an error.
#include <string>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh::detail {

namespace {

// Skips blank lines and comment lines, stopping at the first byte of the next record.
void skip_to_record(TextCursor& c) {
  for (;;) {
    c.skip_space();
    if (c.at_end() || *c.p != '#') return;
    c.skip_line();
  }
}

// The rest of a record line may hold colours or a comment; it is not read.
void end_record(TextCursor& c) {
  c.skip_line();
}

std::uint64_t off_count(TextCursor& c, const char* what) {
  skip_to_record(c);
  const char* at = c.p;
  if (c.at_end()) c.fail(at, std::string("unexpected end of file: expected ") + what);
  const std::int64_t n = c.integer(what);
  if (n < 0) c.fail(at, std::string("negative ") + what);
  return static_cast<std::uint64_t>(n);
}

}  // namespace

void read_off(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages) {
  TextCursor c(bytes, name);
  PageRelease release(bytes.data(), release_pages);
  source.format = MeshFormat::off;
  skip_to_record(c);
  const char* kat = c.p;
  std::string_view k = c.word();
  if (k.size() < 3 || k.substr(k.size() - 3) != "OFF")
    c.fail(kat, "expected an OFF header keyword, found " + describe_at(kat, c.end));
  if (k.find('4') != std::string_view::npos || k.find('n') != std::string_view::npos)
    c.fail(kat, "only 3-D OFF is supported, found " + describe_at(kat, c.end));
  c.skip_blanks();
  if (!c.at_eol() && *c.p != '#') {
    const char* bat = c.p;
    if (c.word() == "BINARY") c.fail(bat, "binary OFF is not supported");
    c.p = bat;  // the counts may follow the keyword on its line
  }
  skip_to_record(c);
  const char* nat = c.p;
  const std::uint64_t nv = off_count(c, "vertex count");
  const std::uint64_t nf = off_count(c, "face count");
  c.skip_blanks();
  if (!c.at_eol() && *c.p != '#') off_count(c, "edge count");  // present in every file we know
  end_record(c);
  if (nv > max_vertices)
    c.fail(nat, "vertex count " + std::to_string(nv) + " exceeds the 32-bit indices");

  const auto remaining = [&] { return static_cast<std::size_t>(c.end - c.p); };
  reserve_huge(mesh.vertices,
               bounded_reserve(nv, remaining(), 6));  // "0 0 0\n" is the shortest vertex
  for (std::uint64_t i = 0; i < nv; ++i) {
    release.passed(c.p);
    skip_to_record(c);
    if (c.at_end())
      c.fail(c.p, "unexpected end of file: " + std::to_string(i) + " of " + std::to_string(nv) +
                      " vertices read");
    Vec3d v;
    v.x = c.coordinate("x coordinate");
    v.y = c.coordinate("y coordinate");
    v.z = c.coordinate("z coordinate");
    mesh.vertices.push_back(v);
    end_record(c);
  }
  reserve_huge(mesh.face_offsets, bounded_reserve(nf, remaining(), 8) + 1);  // "3 0 1 2\n"
  reserve_huge(mesh.corners, 3 * bounded_reserve(nf, remaining(), 8));
  for (std::uint64_t f = 0; f < nf; ++f) {
    release.passed(c.p);
    skip_to_record(c);
    const char* at = c.p;
    if (c.at_end())
      c.fail(at, "unexpected end of file: " + std::to_string(f) + " of " + std::to_string(nf) +
                     " faces read");
    const std::int64_t n = c.integer("face vertex count");
    if (n < 3) c.fail(at, "face with " + std::to_string(n) + " vertices (a face needs at least 3)");
    for (std::int64_t k = 0; k < n; ++k) {
      c.skip_blanks();
      const char* iat = c.p;
      if (c.at_eol())
        c.fail(iat, "face line ends after " + std::to_string(k) + " of its " + std::to_string(n) +
                        " indices");
      const std::int64_t idx = c.integer("vertex index");
      if (idx < 0 || static_cast<std::uint64_t>(idx) >= nv)
        c.fail(iat, "vertex index " + std::to_string(idx) + " is out of range (" +
                        std::to_string(nv) + " vertices)");
      mesh.corners.push_back(static_cast<std::uint32_t>(idx));
    }
    if (mesh.corners.size() > max_vertices) c.fail(at, "too many face corners for 32-bit offsets");
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
    end_record(c);
  }
  skip_to_record(c);
  if (!c.at_end())
    source.warnings.push_back(name + ":" + std::to_string(text_position(c.begin, c.p).line) +
                              ": data after the declared " + std::to_string(nf) + " faces ignored");
}

}  // namespace pgamesh::detail
