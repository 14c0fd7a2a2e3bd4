#include "pgamesh/io/read_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "io/readers.hpp"
#include "io/stl_binary.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"

namespace pgamesh {

namespace {

std::uint32_t le32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t{u[0]} | std::uint32_t{u[1]} << 8 | std::uint32_t{u[2]} << 16 |
         std::uint32_t{u[3]} << 24;
}

// No control bytes other than whitespace in the first KiB: text formats may hold non-UTF-8 bytes
// (>= 0x80) in names and comments, binary STL headers and records almost always hold NUL bytes.
bool looks_like_text(std::span<const char> bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 1024);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') return false;
    if (c == 0x7f) return false;
  }
  return true;
}

// [ST][C][N][4][n]OFF: the header keywords of the OFF family (geomview).
bool is_off_keyword(std::string_view w) {
  auto eat = [&](std::string_view prefix) {
    if (w.substr(0, prefix.size()) == prefix) w.remove_prefix(prefix.size());
  };
  eat("ST");
  eat("C");
  eat("N");
  eat("4");
  eat("n");
  return w == "OFF";
}

bool is_obj_keyword(std::string_view w) {
  static constexpr std::string_view keys[] = {
      "v",    "vt",   "vn",     "vp",     "f",      "g",      "o",    "s",
      "l",    "p",    "mtllib", "usemtl", "cstype", "deg",    "curv", "curv2",
      "surf", "bmat", "step",   "lod",    "maplib", "usemap", "mg"};
  return std::find(std::begin(keys), std::end(keys), w) != std::end(keys);
}

bool is_stl_family(MeshFormat f) {
  return f == MeshFormat::stl_ascii || f == MeshFormat::stl_binary;
}

// Whether a 'color' statement starts a line in the first 64 KiB: an SLP file (Pro/ENGINEER render
// output) rather than a plain ASCII STL.
bool has_color_line(std::span<const char> bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 65536);
  const std::string_view text(bytes.data(), n);
  for (std::size_t at = text.find("color"); at != std::string_view::npos;
       at = text.find("color", at + 1)) {
    std::size_t b = at;
    while (b > 0 && detail::is_blank(text[b - 1])) --b;
    if ((b == 0 || text[b - 1] == '\n') && at + 5 < n && detail::is_blank(text[at + 5]))
      return true;
  }
  return false;
}

bool is_ply_family(MeshFormat f) {
  return f == MeshFormat::ply_ascii || f == MeshFormat::ply_binary_le ||
         f == MeshFormat::ply_binary_be;
}

}  // namespace

MeshFormat detect_format(std::span<const char> bytes) {
  if (bytes.empty()) return MeshFormat::unknown;
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "PK\x03\x04", 4) == 0)
    return MeshFormat::threemf;  // a zip archive: the only zip-packaged format read
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) return MeshFormat::glb;
  if (bytes.size() >= stl_header_bytes &&
      stl_header_bytes + stl_record_bytes * std::uint64_t{le32(bytes.data() + 80)} == bytes.size())
    return MeshFormat::stl_binary;

  const std::string name;
  detail::TextCursor c(bytes, name);
  if (bytes.size() >= 3 && std::memcmp(bytes.data(), "\xEF\xBB\xBF", 3) == 0) c.p += 3;  // BOM
  c.skip_space();
  const bool text = looks_like_text(bytes);
  // Leading comment lines are allowed in OBJ and OFF; look at the first statement.
  for (int lines = 0; lines < 10000 && !c.at_end() && *c.p == '#'; ++lines) {
    c.skip_line();
    c.skip_space();
  }
  const std::string_view w = c.word();
  if (w == "ply") {
    c.skip_line();
    c.skip_space();
    if (c.word() == "format") {
      const std::string_view enc = c.word();
      if (enc == "binary_little_endian") return MeshFormat::ply_binary_le;
      if (enc == "binary_big_endian") return MeshFormat::ply_binary_be;
    }
    return MeshFormat::ply_ascii;  // the PLY reader reports a bad format line
  }
  if (is_off_keyword(w)) return MeshFormat::off;
  if (text && detail::same_word(w, "solid"))
    return has_color_line(bytes) ? MeshFormat::slp : MeshFormat::stl_ascii;
  if (text && !w.empty() && w[0] == '{') return MeshFormat::gltf;  // a JSON object
  if (text && is_obj_keyword(w)) return MeshFormat::obj;
  if (!text) return MeshFormat::stl_binary;  // its reader explains the size mismatch
  return MeshFormat::unknown;
}

Mesh detail::read_mesh_bytes(std::span<const char> bytes, const std::string& name,
                             MeshSource* source, MeshFormat format, bool release_pages,
                             bool name_is_path) {
  MeshSource local;
  MeshSource& src = source ? *source : local;
  src = MeshSource{};
  src.path = name;
  Mesh mesh;
  if (std::all_of(bytes.begin(), bytes.end(), detail::is_space))  // stops at the first data byte
    throw InputError(name, detail::byte_position(0), "empty file: no mesh data");

  MeshFormat f = format == MeshFormat::unknown ? detect_format(bytes) : format;
  // An ASCII STL named .slp is an SLP file without colours (the same grammar, read as such).
  if (f == MeshFormat::stl_ascii && format == MeshFormat::unknown &&
      format_for_extension(name) == MeshFormat::slp)
    f = MeshFormat::slp;
  if (f == MeshFormat::slp) {
    detail::read_stl_ascii(bytes, name, mesh, src, release_pages);
    src.format = MeshFormat::slp;
  } else if (f == MeshFormat::gltf || f == MeshFormat::glb) {
    detail::read_gltf(bytes, name, mesh, src, name_is_path);
  } else if (is_stl_family(f)) {
    if (binary_stl_view(bytes, name))
      detail::read_stl_binary(bytes, name, mesh, src, release_pages);
    else
      detail::read_stl_ascii(bytes, name, mesh, src, release_pages);
  } else if (is_ply_family(f)) {
    detail::read_ply(bytes, name, mesh, src, release_pages);
  } else if (f == MeshFormat::obj) {
    detail::read_obj(bytes, name, mesh, src, release_pages);
  } else if (f == MeshFormat::off) {
    detail::read_off(bytes, name, mesh, src, release_pages);
  } else if (f == MeshFormat::threemf) {
    detail::read_3mf(bytes, name, mesh, src);
  } else {
    throw InputError(
        name, detail::text_position(bytes.data(), bytes.data()),
        "unrecognised mesh format (expected STL, OBJ, PLY, OFF, 3MF, glTF or SLP content)");
  }
  // The readers release in steps as they go; the last step and the first page (detection) too.
  if (release_pages) detail::release_pages(bytes.data(), bytes.data() + bytes.size());
  // And the untouched rest of the huge pages their reserved arrays ended in.
  detail::release_unused_capacity(mesh.vertices);
  detail::release_unused_capacity(mesh.corners);
  detail::release_unused_capacity(mesh.face_offsets);
  return mesh;
}

Mesh read_mesh_bytes(std::span<const char> bytes, const std::string& name, MeshSource* source,
                     MeshFormat format) {
  return detail::read_mesh_bytes(bytes, name, source, format, false);
}

Mesh read_mesh(const MappedFile& file, MeshSource* source, MeshFormat format) {
  return detail::read_mesh_bytes(file.bytes(), file.path(), source, format, file.mapped(),
                                 file.path() != "-");
}

Mesh read_mesh(const std::string& path, MeshSource* source, MeshFormat format) {
  return read_mesh(MappedFile::open(path), source, format);
}

}  // namespace pgamesh
