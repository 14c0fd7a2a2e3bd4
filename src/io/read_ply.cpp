// PLY (Stanford polygon format): ASCII, binary little-endian and binary big-endian. The header
// declares elements and their properties; the vertex element may hold x, y, z among any other
// properties in any order and of any numeric type, the face element a list `vertex_indices` (or
// `vertex_index`) with any integer count and index types. Other elements and properties are
// skipped. Declared counts are checked against the bytes left before anything is reserved.
#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/page_release.hpp"
#include "geometry/chunked_sums.hpp"
#include "io/ply_header.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/geometry/face_sums.hpp"
#include "pgamesh/geometry/reference_point.hpp"

namespace pgamesh::detail {

Header parse_header(TextCursor& c) {
  Header h;
  if (c.word() != "ply") c.fail(c.begin, "expected 'ply' on the first line");
  auto end_statement = [&] {
    c.skip_blanks();
    if (!c.at_eol()) c.fail(c.p, "unexpected " + describe_at(c.p, c.end) + " in the header");
    if (!c.at_end()) ++c.p;
  };
  end_statement();
  for (;;) {
    c.skip_blanks();
    if (c.at_end()) c.fail(c.p, "header without 'end_header' (truncated file?)");
    if (c.at_eol()) {
      ++c.p;
      continue;
    }
    const char* at = c.p;
    const std::string_view w = c.word();
    if (w == "format") {
      c.skip_blanks();
      const char* eat = c.p;
      const std::string_view enc = c.word();
      if (enc == "ascii")
        h.format = MeshFormat::ply_ascii;
      else if (enc == "binary_little_endian")
        h.format = MeshFormat::ply_binary_le;
      else if (enc == "binary_big_endian")
        h.format = MeshFormat::ply_binary_be;
      else
        c.fail(eat, "unknown PLY encoding, found " + describe_at(eat, c.end));
      c.word();  // version, e.g. 1.0
      end_statement();
    } else if (w == "comment" || w == "obj_info") {
      c.skip_line();
    } else if (w == "element") {
      PlyElement e;
      e.at = at;
      e.name = std::string(c.word());
      c.skip_blanks();
      const char* nat = c.p;
      const std::int64_t n = c.integer("element count");
      if (n < 0) c.fail(nat, "negative element count");
      e.count = static_cast<std::uint64_t>(n);
      h.elements.push_back(std::move(e));
      end_statement();
    } else if (w == "property") {
      if (h.elements.empty()) c.fail(at, "property before any element");
      PlyProperty prop;
      c.skip_blanks();
      const char* tat = c.p;
      std::string_view t = c.word();
      if (t == "list") {
        c.skip_blanks();
        const char* cat = c.p;
        prop.count_type = ply_type(c.word());
        if (!is_integer(prop.count_type))
          c.fail(cat, "list count type must be an integer type, found " + describe_at(cat, c.end));
        c.skip_blanks();
        tat = c.p;
        t = c.word();
      }
      prop.type = ply_type(t);
      if (prop.type == PlyType::none)
        c.fail(tat, "unknown property type " + describe_at(tat, c.end));
      prop.name = std::string(c.word());
      if (prop.name.empty()) c.fail(c.p, "property without a name");
      h.elements.back().props.push_back(std::move(prop));
      end_statement();
    } else if (w == "end_header") {
      end_statement();
      h.data = c.p;
      break;
    } else {
      c.fail(at, "unknown PLY header line " + describe_at(at, c.end));
    }
  }
  if (h.format == MeshFormat::unknown) c.fail(c.begin, "PLY header without a 'format' line");
  return h;
}

Layout find_layout(const Header& h, const TextCursor& c) {
  static constexpr const char* axis_names[3] = {"x", "y", "z"};
  Layout l;
  for (std::size_t e = 0; e < h.elements.size(); ++e) {
    const PlyElement& el = h.elements[e];
    if (el.name == "vertex" && l.vertex_element < 0) {
      l.vertex_element = static_cast<int>(e);
      for (std::size_t p = 0; p < el.props.size(); ++p)
        for (int k = 0; k < 3; ++k)
          if (el.props[p].name == axis_names[k]) {
            if (el.props[p].is_list()) c.fail(el.at, "vertex coordinate declared as a list");
            l.coord[k] = static_cast<int>(p);
          }
      for (int k = 0; k < 3; ++k)
        if (l.coord[k] < 0)
          c.fail(el.at, std::string("vertex element without a '") + axis_names[k] + "' property");
      if (el.count > max_vertices) c.fail(el.at, "vertex count exceeds the 32-bit indices");
    } else if (el.name == "face" && l.face_element < 0) {
      l.face_element = static_cast<int>(e);
      for (std::size_t p = 0; p < el.props.size(); ++p)
        if (el.props[p].name == "vertex_indices" || el.props[p].name == "vertex_index")
          l.indices = static_cast<int>(p);
      if (l.indices < 0) c.fail(el.at, "face element without a 'vertex_indices' list");
      const PlyProperty& ip = el.props[static_cast<std::size_t>(l.indices)];
      if (!ip.is_list() || !is_integer(ip.type))
        c.fail(el.at, "'vertex_indices' must be a list of an integer type");
    }
  }
  if (l.face_element >= 0 && h.elements[static_cast<std::size_t>(l.face_element)].count > 0 &&
      l.vertex_element < 0)
    c.fail(c.begin, "PLY with faces but no 'vertex' element");
  return l;
}

namespace {

// Where the readers below put the faces: into the mesh (read_ply), or summed one by one and not
// kept (read_ply_summing_faces). start() is called once the vertices are read, when the face
// element begins; then, per face, add_corner() for each corner and end_face().
struct StoredFaces {
  Mesh& mesh;
  void start(const Mesh&) {}
  void reserve(std::size_t faces, std::size_t corners) {
    reserve_huge(mesh.face_offsets, faces + 1);
    reserve_huge(mesh.corners, corners);
  }
  void add_corner(std::uint32_t v) { mesh.corners.push_back(v); }
  std::size_t corner_count() const { return mesh.corners.size(); }
  void end_face() { mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size())); }
};

struct SummedFaces {
  explicit SummedFaces(PlyFaceSums& sums_out) : out(sums_out) {}
  PlyFaceSums& out;
  const Vec3d* vertices = nullptr;
  StreamedChunkSums<> sums;
  std::vector<std::uint32_t> face;  // the corners of the face being read
  std::size_t corners = 0;
  void start(const Mesh& mesh) {
    vertices = mesh.vertices.data();
    out.reference = reference_point(mesh.vertices);
  }
  void reserve(std::size_t, std::size_t) {}
  void add_corner(std::uint32_t v) {
    face.push_back(v);
    ++corners;
  }
  std::size_t corner_count() const { return corners; }
  // The face as mesh_boundary_sums adds it (face_sums.hpp), in the chunks of chunked_sums.
  void end_face() {
    add_mesh_face(sums.current(), vertices, face.data(), face.size(), out.reference);
    sums.next();
    ++out.faces;
    if (face.size() >= 3) out.triangles += face.size() - 2;
    face.clear();
  }
};

// ---- binary data
// ---------------------------------------------------------------------------------

// The element item a binary read is in ("face 12"), for its error messages. Kept as the element
// and index and spelled out only when a message needs it: formatting it for every face was a
// fifth of the reading of a binary PLY.
struct PlyItem {
  const PlyElement& element;
  std::uint64_t index;
  std::string name() const { return element.name + " " + std::to_string(index); }
};

class BinaryReader {
 public:
  BinaryReader(const char* file_begin, const char* data, const char* end, const std::string& name,
               bool swap)
      : begin_(reinterpret_cast<const unsigned char*>(file_begin)),
        p_(reinterpret_cast<const unsigned char*>(data)),
        end_(reinterpret_cast<const unsigned char*>(end)),
        name_(name),
        swap_(swap) {}

  [[noreturn]] void fail(const unsigned char* at, const std::string& problem) const {
    throw InputError(name_, byte_position(static_cast<std::uint64_t>(at - begin_)), problem);
  }
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  void need(std::uint64_t n, const PlyItem& what) const {
    if (n > remaining())
      fail(p_, "truncated PLY data: " + what.name() + " needs " + std::to_string(n) + " bytes, " +
                   std::to_string(remaining()) + " left");
  }
  // A list length: a non-negative integer whose entries fit in the bytes left.
  std::uint64_t list_count(const PlyProperty& prop, const PlyItem& what) {
    need(type_size(prop.count_type), what);
    const unsigned char* at = p_;
    const std::int64_t n = load_as<std::int64_t>(p_, prop.count_type, swap_);
    p_ += type_size(prop.count_type);
    if (n < 0) fail(at, "negative list length " + std::to_string(n) + " in " + what.name());
    const auto un = static_cast<std::uint64_t>(n);
    if (un > remaining() / type_size(prop.type))
      fail(at, "list length " + std::to_string(n) + " in " + what.name() +
                   " runs past the end of the file");
    return un;
  }
  void skip_property(const PlyProperty& prop, const PlyItem& what) {
    if (prop.is_list()) {
      const std::uint64_t n = list_count(prop, what);
      p_ += n * type_size(prop.type);
    } else {
      need(type_size(prop.type), what);
      p_ += type_size(prop.type);
    }
  }

  const unsigned char* begin_;
  const unsigned char* p_;
  const unsigned char* end_;
  const std::string& name_;
  bool swap_;
};

template <class Faces>
void read_binary(const Header& h, const Layout& l, const TextCursor& c, Mesh& mesh, Faces& faces,
                 PageRelease& release) {
  const bool data_big = h.format == MeshFormat::ply_binary_be;
  const bool swap = data_big != (std::endian::native == std::endian::big);
  BinaryReader r(c.begin, h.data, c.end, c.name, swap);
  const std::uint64_t nverts =
      l.vertex_element >= 0 ? h.elements[static_cast<std::size_t>(l.vertex_element)].count : 0;
  for (std::size_t e = 0; e < h.elements.size(); ++e) {
    const PlyElement& el = h.elements[e];
    if (el.props.empty()) continue;  // holds no bytes, whatever its count
    if (static_cast<int>(e) == l.vertex_element) {
      bool fixed = true;
      std::size_t stride = 0;
      std::size_t offset[3] = {};
      for (std::size_t p = 0; p < el.props.size(); ++p) {
        for (int k = 0; k < 3; ++k)
          if (static_cast<int>(p) == l.coord[k]) offset[k] = stride;
        fixed = fixed && !el.props[p].is_list();
        stride += type_size(el.props[p].type);
      }
      if (fixed && el.count > r.remaining() / stride)
        r.fail(r.p_, "truncated PLY data: " + std::to_string(el.count) + " vertices of " +
                         std::to_string(stride) + " bytes need " +
                         std::to_string(el.count * stride) + " bytes, " +
                         std::to_string(r.remaining()) + " left");
      reserve_huge(mesh.vertices, bounded_reserve(el.count, r.remaining(), fixed ? stride : 1));
      for (std::uint64_t i = 0; i < el.count; ++i) {
        release.passed(r.p_);
        Vec3d v;
        if (fixed) {
          for (int k = 0; k < 3; ++k) {
            const unsigned char* at = r.p_ + offset[k];
            const std::size_t ci = static_cast<std::size_t>(l.coord[k]);
            v[k] = load_as<double>(at, el.props[ci].type, swap);
            if (!std::isfinite(v[k]))
              r.fail(at, "non-finite coordinate (NaN or infinity) in vertex " + std::to_string(i));
          }
          r.p_ += stride;
        } else {
          for (std::size_t p = 0; p < el.props.size(); ++p) {
            const unsigned char* at = r.p_;
            r.skip_property(el.props[p], PlyItem{el, i});
            for (int k = 0; k < 3; ++k)
              if (static_cast<int>(p) == l.coord[k]) {
                v[k] = load_as<double>(at, el.props[p].type, swap);
                if (!std::isfinite(v[k]))
                  r.fail(at,
                         "non-finite coordinate (NaN or infinity) in vertex " + std::to_string(i));
              }
          }
        }
        mesh.vertices.push_back(v);
      }
    } else if (static_cast<int>(e) == l.face_element) {
      const PlyProperty& ip = el.props[static_cast<std::size_t>(l.indices)];
      const std::size_t isize = type_size(ip.type);
      const std::size_t min_face = type_size(ip.count_type) + 3 * isize;
      faces.start(mesh);
      faces.reserve(bounded_reserve(el.count, r.remaining(), min_face),
                    3 * bounded_reserve(el.count, r.remaining(), min_face));
      for (std::uint64_t i = 0; i < el.count; ++i) {
        release.passed(r.p_);
        for (std::size_t p = 0; p < el.props.size(); ++p) {
          if (static_cast<int>(p) != l.indices) {
            r.skip_property(el.props[p], PlyItem{el, i});
            continue;
          }
          const unsigned char* at = r.p_;
          const std::uint64_t n = r.list_count(ip, PlyItem{el, i});
          if (n < 3)
            r.fail(at, "face " + std::to_string(i) + " with " + std::to_string(n) +
                           " vertices (a face needs at least 3)");
          for (std::uint64_t k = 0; k < n; ++k) {
            const std::int64_t idx = load_as<std::int64_t>(r.p_, ip.type, swap);
            if (idx < 0 || static_cast<std::uint64_t>(idx) >= nverts)
              r.fail(r.p_, "vertex index " + std::to_string(idx) + " of face " + std::to_string(i) +
                               " is out of range (" + std::to_string(nverts) + " vertices)");
            faces.add_corner(static_cast<std::uint32_t>(idx));
            r.p_ += isize;
          }
          if (faces.corner_count() > max_vertices)
            r.fail(at, "too many face corners for 32-bit offsets");
          faces.end_face();
        }
      }
    } else {
      for (std::uint64_t i = 0; i < el.count; ++i)
        for (const PlyProperty& prop : el.props) r.skip_property(prop, PlyItem{el, i});
    }
  }
}

// ---- ASCII data
// ----------------------------------------------------------------------------------

// Values are whitespace-separated tokens; line breaks are not significant (some writers wrap).
double ascii_value(TextCursor& c, PlyType t, const char* what) {
  c.skip_space();
  if (c.at_end()) c.fail(c.p, std::string("unexpected end of file: expected ") + what);
  if (is_integer(t)) return static_cast<double>(c.integer(what));
  return c.number(what);
}

std::int64_t ascii_integer(TextCursor& c, const char* what) {
  c.skip_space();
  if (c.at_end()) c.fail(c.p, std::string("unexpected end of file: expected ") + what);
  return c.integer(what);
}

void ascii_skip_property(TextCursor& c, const PlyProperty& prop) {
  if (!prop.is_list()) {
    ascii_value(c, prop.type, "a property value");
    return;
  }
  c.skip_space();
  const char* at = c.p;
  const std::int64_t n = ascii_integer(c, "a list length");
  if (n < 0) c.fail(at, "negative list length");
  for (std::int64_t k = 0; k < n; ++k) ascii_value(c, prop.type, "a list entry");
}

template <class Faces>
void read_ascii(const Header& h, const Layout& l, TextCursor& c, Mesh& mesh, Faces& faces,
                PageRelease& release) {
  c.p = h.data;
  const std::uint64_t nverts =
      l.vertex_element >= 0 ? h.elements[static_cast<std::size_t>(l.vertex_element)].count : 0;
  const auto remaining = [&] { return static_cast<std::size_t>(c.end - c.p); };
  for (std::size_t e = 0; e < h.elements.size(); ++e) {
    const PlyElement& el = h.elements[e];
    if (el.props.empty()) continue;
    if (static_cast<int>(e) == l.vertex_element) {
      reserve_huge(mesh.vertices, bounded_reserve(el.count, remaining(), 2 * el.props.size()));
      for (std::uint64_t i = 0; i < el.count; ++i) {
        release.passed(c.p);
        Vec3d v;
        for (std::size_t p = 0; p < el.props.size(); ++p) {
          int role = -1;
          for (int k = 0; k < 3; ++k)
            if (static_cast<int>(p) == l.coord[k]) role = k;
          if (role < 0) {
            ascii_skip_property(c, el.props[p]);
            continue;
          }
          c.skip_space();
          if (c.at_end()) c.fail(c.p, "unexpected end of file in vertex " + std::to_string(i));
          v[role] = c.coordinate("coordinate");
        }
        mesh.vertices.push_back(v);
      }
    } else if (static_cast<int>(e) == l.face_element) {
      faces.start(mesh);
      faces.reserve(bounded_reserve(el.count, remaining(), 8),
                    3 * bounded_reserve(el.count, remaining(), 8));
      for (std::uint64_t i = 0; i < el.count; ++i) {
        release.passed(c.p);
        for (std::size_t p = 0; p < el.props.size(); ++p) {
          if (static_cast<int>(p) != l.indices) {
            ascii_skip_property(c, el.props[p]);
            continue;
          }
          c.skip_space();
          const char* at = c.p;
          const std::int64_t n = ascii_integer(c, "a face's vertex count");
          if (n < 3)
            c.fail(at, "face " + std::to_string(i) + " with " + std::to_string(n) +
                           " vertices (a face needs at least 3)");
          for (std::int64_t k = 0; k < n; ++k) {
            c.skip_space();
            const char* iat = c.p;
            const std::int64_t idx = ascii_integer(c, "a vertex index");
            if (idx < 0 || static_cast<std::uint64_t>(idx) >= nverts)
              c.fail(iat, "vertex index " + std::to_string(idx) + " of face " + std::to_string(i) +
                              " is out of range (" + std::to_string(nverts) + " vertices)");
            faces.add_corner(static_cast<std::uint32_t>(idx));
          }
          if (faces.corner_count() > max_vertices)
            c.fail(at, "too many face corners for 32-bit offsets");
          faces.end_face();
        }
      }
    } else {
      for (std::uint64_t i = 0; i < el.count; ++i)
        for (const PlyProperty& prop : el.props) ascii_skip_property(c, prop);
    }
  }
  c.skip_space();
  if (!c.at_end())
    c.fail(c.p, "unexpected " + describe_at(c.p, c.end) + " after the last declared element");
}

}  // namespace

namespace {

// The header, the source's fields and the data of a PLY file, its faces handed to `faces`. With
// `vertices_first`, returns false before reading any data when the face element comes before the
// vertex element.
template <class Faces>
bool read_ply_with(std::span<const char> bytes, const std::string& name, Mesh& mesh,
                   MeshSource& source, bool release_pages, Faces& faces, bool vertices_first) {
  TextCursor c(bytes, name);
  PageRelease release(bytes.data(), release_pages);
  const Header h = parse_header(c);
  const Layout l = find_layout(h, c);
  if (vertices_first && l.face_element >= 0 && l.face_element < l.vertex_element) return false;
  source.format = h.format;
  if (l.vertex_element >= 0) {
    const PlyElement& v = h.elements[static_cast<std::size_t>(l.vertex_element)];
    for (int k = 0; k < 3; ++k)
      if (v.props[static_cast<std::size_t>(l.coord[k])].type == PlyType::f32)
        source.single_precision = true;
  }
  for (const PlyElement& el : h.elements)
    if (el.name != "vertex" && el.name != "face" && el.count > 0 && !el.props.empty())
      source.warnings.push_back(name + ": PLY element '" + el.name + "' (" +
                                std::to_string(el.count) + " items) ignored");
  if (h.format == MeshFormat::ply_ascii)
    read_ascii(h, l, c, mesh, faces, release);
  else
    read_binary(h, l, c, mesh, faces, release);
  return true;
}

}  // namespace

void read_ply(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
              bool release_pages) {
  StoredFaces faces{mesh};
  read_ply_with(bytes, name, mesh, source, release_pages, faces, false);
}

std::optional<PlyFaceSums> read_ply_summing_faces(std::span<const char> bytes,
                                                  const std::string& name, Mesh& mesh,
                                                  MeshSource& source, bool release_pages) {
  PlyFaceSums out;
  SummedFaces faces(out);
  if (!read_ply_with(bytes, name, mesh, source, release_pages, faces, true)) return std::nullopt;
  if (!faces.vertices) out.reference = reference_point(mesh.vertices);  // no face element
  out.sums = faces.sums.total();
  return out;
}

}  // namespace pgamesh::detail
