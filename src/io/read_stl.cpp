// STL, both encodings. Binary is recognised by size arithmetic only; ASCII is parsed in place.
#include <cmath>
#include <cstring>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/stl_record_blocks.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/stl_binary.hpp"

namespace pgamesh {

std::optional<BinaryStlView> binary_stl_view(std::span<const char> bytes, const std::string& name) {
  const auto* u = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint64_t size = bytes.size();
  if (size >= stl_header_bytes) {
    const std::uint64_t count = std::uint64_t{u[80]} | std::uint64_t{u[81]} << 8 |
                                std::uint64_t{u[82]} << 16 | std::uint64_t{u[83]} << 24;
    if (stl_header_bytes + stl_record_bytes * count == size)
      return BinaryStlView{u + stl_header_bytes, count};
    if (detect_format(bytes) != MeshFormat::stl_binary) return std::nullopt;
    const std::uint64_t whole = (size - stl_header_bytes) / stl_record_bytes;
    const std::uint64_t extra = (size - stl_header_bytes) % stl_record_bytes;
    std::string problem = "binary STL header declares " + std::to_string(count) +
                          " triangles (84 + 50 x " + std::to_string(count) + " = " +
                          std::to_string(stl_header_bytes + stl_record_bytes * count) +
                          " bytes) but the file has " + std::to_string(size) + " bytes (" +
                          std::to_string(whole) + " whole triangles";
    if (extra) problem += " and " + std::to_string(extra) + " bytes more";
    problem += "): truncated or corrupt";
    throw InputError(name, detail::byte_position(80), problem);
  }
  if (detect_format(bytes) != MeshFormat::stl_binary) return std::nullopt;
  throw InputError(name, detail::byte_position(size),
                   "truncated binary STL: " + std::to_string(size) +
                       " bytes, shorter than the 84-byte header and triangle count");
}

void check_binary_stl_finite(const BinaryStlView& view, const std::string& name) {
  detail::for_record_blocks(
      view, 0, view.count, name, [&](const unsigned char* r, std::uint64_t b, std::uint64_t e) {
        for (std::uint64_t i = b; i < e; ++i, r += stl_record_bytes) {
          Vec3d v[3];
          stl_triangle(r, v);
          for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j)
              if (!std::isfinite(v[k][j]))
                throw InputError(name,
                                 detail::byte_position(stl_header_bytes + stl_record_bytes * i +
                                                       12 + 12 * static_cast<unsigned>(k) +
                                                       4 * static_cast<unsigned>(j)),
                                 "non-finite coordinate (NaN or infinity) in triangle " +
                                     std::to_string(i + 1) + ", vertex " + std::to_string(k + 1));
        }
      });
}

namespace detail {

void read_stl_binary(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                     MeshSource& source, bool release_pages) {
  const BinaryStlView view = *binary_stl_view(bytes, name);
  if (3 * view.count > max_vertices)
    throw InputError(name, byte_position(80),
                     std::to_string(view.count) + " triangles exceed the 32-bit vertex indices");
  check_binary_stl_finite(view, name);
  source.format = MeshFormat::stl_binary;
  source.single_precision = true;
  const auto n = static_cast<std::size_t>(view.count);
  reserve_huge(mesh.vertices, 3 * n);  // the file size has proven the count
  reserve_huge(mesh.corners, 3 * n);
  reserve_huge(mesh.face_offsets, n + 1);
  mesh.vertices.resize(3 * n);
  mesh.corners.resize(3 * n);
  mesh.face_offsets.resize(n + 1);
  PageRelease release(view.records, release_pages);
  for (std::size_t i = 0; i < n; ++i) {
    release.passed(view.records + stl_record_bytes * i);
    stl_triangle(view.records + stl_record_bytes * i, &mesh.vertices[3 * i]);
    for (std::size_t k = 0; k < 3; ++k)
      mesh.corners[3 * i + k] = static_cast<std::uint32_t>(3 * i + k);
    mesh.face_offsets[i + 1] = static_cast<std::uint32_t>(3 * i + 3);
  }
}

// solid NAME / { facet normal N / outer loop / vertex X Y Z (3 or more) / endloop / endfacet }
// / endsolid NAME, keywords case-insensitive, several solids in a row allowed. Normals are skipped
// unread (NaN normals of degenerate facets are common and harmless).
void read_stl_ascii(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                    MeshSource& source, bool release_pages) {
  TextCursor c(bytes, name);
  PageRelease release(bytes.data(), release_pages);
  source.format = MeshFormat::stl_ascii;
  // Typical exporters write 180-250 bytes a facet; reserve for 120 so that the arrays are never
  // reallocated (a copy that would double the peak). Unused reserve is untouched virtual memory.
  reserve_huge(mesh.vertices, bytes.size() / 40);
  reserve_huge(mesh.corners, bytes.size() / 40);
  reserve_huge(mesh.face_offsets, bytes.size() / 120 + 1);

  auto expect = [&](const char* keyword) {
    c.skip_space();
    const char* at = c.p;
    if (!same_word(c.word(), keyword))
      c.fail(at, std::string("expected '") + keyword + "', found " + describe_at(at, c.end));
  };

  if (bytes.size() >= 3 && std::memcmp(bytes.data(), "\xEF\xBB\xBF", 3) == 0) c.p += 3;
  expect("solid");
  c.skip_line();  // the solid's name: any bytes
  bool in_solid = true;
  std::uint64_t polygons = 0;
  const char* first_polygon = nullptr;
  for (;;) {
    release.passed(c.p);
    c.skip_space();
    if (c.at_end()) break;
    const char* at = c.p;
    const std::string_view w = c.word();
    if (in_solid && same_word(w, "facet")) {
      c.skip_line();  // "normal nx ny nz" is ignored: the vertex order is the truth
      expect("outer");
      expect("loop");
      std::size_t n = 0;
      for (;;) {
        c.skip_space();
        const char* vat = c.p;
        const std::string_view vw = c.word();
        if (same_word(vw, "vertex")) {
          Vec3d v;
          v.x = c.coordinate("x coordinate");
          v.y = c.coordinate("y coordinate");
          v.z = c.coordinate("z coordinate");
          c.skip_blanks();
          if (!c.at_eol()) c.fail(c.p, "unexpected " + describe_at(c.p, c.end) + " after vertex");
          if (mesh.vertices.size() >= max_vertices)
            c.fail(vat, "too many vertices for 32-bit indices");
          mesh.corners.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
          mesh.vertices.push_back(v);
          ++n;
        } else if (same_word(vw, "endloop")) {
          break;
        } else {
          c.fail(vat, "expected 'vertex' or 'endloop', found " + describe_at(vat, c.end));
        }
      }
      if (n < 3)
        c.fail(at, "facet with " + std::to_string(n) + " vertices (a face needs at least 3)");
      if (n > 3 && polygons++ == 0) first_polygon = at;
      mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
      expect("endfacet");
    } else if (in_solid && same_word(w, "endsolid")) {
      c.skip_line();
      in_solid = false;
    } else if (!in_solid && same_word(w, "solid")) {
      c.skip_line();
      in_solid = true;
    } else {
      c.fail(at, std::string("expected ") + (in_solid ? "'facet' or 'endsolid'" : "'solid'") +
                     ", found " + describe_at(at, c.end));
    }
  }
  if (in_solid)
    source.warnings.push_back(name + ": missing 'endsolid' at the end (file truncated?)");
  if (polygons) {
    const InputPosition pos = text_position(c.begin, first_polygon);
    source.warnings.push_back(name + ":" + std::to_string(pos.line) + ": " +
                              std::to_string(polygons) +
                              " facet(s) with more than 3 vertices kept as polygons");
  }
}

}  // namespace detail

}  // namespace pgamesh
