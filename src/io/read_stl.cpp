// STL, both encodings. Binary is recognised by size arithmetic only; ASCII is parsed in place.
#include <cmath>
#include <cstring>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/stl_ascii_grammar.hpp"
#include "io/stl_binary.hpp"
#include "io/stl_record_blocks.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"

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
  with_record_layout(view.layout, [&](auto layout) {
    constexpr TriangleRecordLayout L = decltype(layout)::layout;
    detail::for_record_blocks(
        view, 0, view.count, name, [&](const unsigned char* r, std::uint64_t b, std::uint64_t e) {
          for (std::uint64_t i = b; i < e; ++i, r += L.stride) {
            Vec3d v[3];
            stl_triangle<L>(r, v);
            for (int k = 0; k < 3; ++k)
              for (int j = 0; j < 3; ++j)
                if (!std::isfinite(v[k][j]))
                  throw InputError(name,
                                   detail::byte_position(view.first_record_offset + L.stride * i +
                                                         L.coords + 12 * static_cast<unsigned>(k) +
                                                         4 * static_cast<unsigned>(j)),
                                   "non-finite coordinate (NaN or infinity) in triangle " +
                                       std::to_string(i + 1) + ", vertex " + std::to_string(k + 1));
          }
        });
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

namespace {

// The consumer of the ASCII STL grammar that builds the Mesh: three (or more) fresh vertices a
// facet, in file order.
struct MeshFacets {
  Mesh& mesh;
  void vertex(const Vec3d& v) {
    mesh.corners.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
    mesh.vertices.push_back(v);
  }
  void end_facet(std::size_t) {
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
  }
};

}  // namespace

// The grammar and its repairs are in stl_ascii_grammar.hpp.
void read_stl_ascii(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                    MeshSource& source, bool release_pages) {
  source.format = MeshFormat::stl_ascii;
  // Typical exporters write 180-250 bytes a facet; reserve for 120 so that the arrays are never
  // reallocated (a copy that would double the peak). Unused reserve is untouched virtual memory.
  reserve_huge(mesh.vertices, bytes.size() / 40);
  reserve_huge(mesh.corners, bytes.size() / 40);
  reserve_huge(mesh.face_offsets, bytes.size() / 120 + 1);
  MeshFacets out{mesh};
  const StlAsciiState s = parse_ascii_stl(bytes, name, out, release_pages);
  add_stl_ascii_warnings(s, bytes.data(), name, source.warnings);
}

}  // namespace detail

}  // namespace pgamesh
