#include "pgamesh/io/write_mesh.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "io/write_gltf.hpp"
#include "io/zip_package.hpp"
#include "pgamesh/io/write_file.hpp"

namespace pgamesh {

namespace {

void put_double(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest round-trip form
  out.append(buf, r.ptr);
}

void put_uint(std::string& out, std::uint64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void put_vec(std::string& out, const Vec3d& v) {
  put_double(out, v.x);
  out += ' ';
  put_double(out, v.y);
  out += ' ';
  put_double(out, v.z);
}

// Faces as text lines "n i0 i1 … i(n−1)" with 0-based indices (OFF and ASCII PLY).
void put_counted_faces(std::string& out, const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    put_uint(out, mesh.face_size(f));
    for (std::size_t k = 0; k < mesh.face_size(f); ++k) {
      out += ' ';
      put_uint(out, mesh.face(f)[k]);
    }
    out += '\n';
  }
}

template <class U>
void put_raw(std::string& out, U u, bool big_endian) {
  if (big_endian != (std::endian::native == std::endian::big)) {
    if constexpr (sizeof(U) == 4) u = __builtin_bswap32(u);
    if constexpr (sizeof(U) == 8) u = __builtin_bswap64(u);
  }
  char b[sizeof(U)];
  std::memcpy(b, &u, sizeof u);
  out.append(b, sizeof b);
}

// GCC 12.2 at -O2 and above vectorises (double)(float)x over neighbouring coordinates into plain
// x, dropping the float32 rounding (wrong code, reproduced in isolation); a scalar conversion the
// optimiser cannot merge keeps it.
[[gnu::noinline]] double float_rounded(double x) {
  return static_cast<float>(x);
}

void put_f32(std::string& out, float f, bool big_endian) {
  put_raw(out, std::bit_cast<std::uint32_t>(f), big_endian);
}

void validate(const Mesh& mesh) {
  for (std::uint32_t i : mesh.corners)
    if (i >= mesh.vertices.size())
      throw std::invalid_argument("write_mesh: corner index " + std::to_string(i) +
                                  " outside the " + std::to_string(mesh.vertices.size()) +
                                  " vertices");
}

// Calls emit(a, b, c) for each triangle of the fan decomposition of every face.
template <class F>
void for_each_triangle(const Mesh& mesh, F emit) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    for (std::size_t k = 1; k + 1 < mesh.face_size(f); ++k)
      emit(mesh.vertices[c[0]], mesh.vertices[c[k]], mesh.vertices[c[k + 1]]);
  }
}

std::uint64_t triangle_count(const Mesh& mesh) {
  std::uint64_t n = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) >= 3) n += mesh.face_size(f) - 2;
  return n;
}

// Informational only: readers ignore STL normals.
Vec3d unit_normal(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d n = cross(b - a, c - a);
  const double len = length(n);
  return len > 0 && std::isfinite(len) ? n / len : Vec3d{};
}

std::string stl_ascii(const Mesh& mesh, const WriteOptions& o) {
  std::string out = "solid " + o.solid_name + "\n";
  out.reserve(out.size() + triangle_count(mesh) * 260);
  for_each_triangle(mesh, [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    out += "facet normal ";
    put_vec(out, unit_normal(a, b, c));
    out += "\n outer loop\n  vertex ";
    put_vec(out, a);
    out += "\n  vertex ";
    put_vec(out, b);
    out += "\n  vertex ";
    put_vec(out, c);
    out += "\n endloop\nendfacet\n";
  });
  out += "endsolid " + o.solid_name + "\n";
  return out;
}

std::string stl_binary(const Mesh& mesh, const WriteOptions& o) {
  const std::uint64_t n = triangle_count(mesh);
  if (n > 0xFFFFFFFFull)
    throw std::invalid_argument("write_mesh: too many triangles for binary STL");
  std::string out(80, '\0');
  // A header beginning with "solid" would mislead readers that sniff the first word.
  std::string header =
      o.solid_name.rfind("solid", 0) == 0 ? "binary " + o.solid_name : o.solid_name;
  out.replace(0, std::min<std::size_t>(header.size(), 80), header, 0, 80);
  out.resize(80);
  put_raw(out, static_cast<std::uint32_t>(n), false);
  out.reserve(84 + 50 * n);
  for_each_triangle(mesh, [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d nrm = unit_normal(a, b, c);
    for (const Vec3d* v : {&nrm, &a, &b, &c})
      for (int k = 0; k < 3; ++k) put_f32(out, static_cast<float>((*v)[k]), false);
    out.append(2, '\0');
  });
  return out;
}

std::string obj(const Mesh& mesh) {
  std::string out = "# written by pgamesh\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.corners.size() * 8);
  for (const Vec3d& v : mesh.vertices) {
    out += "v ";
    put_vec(out, v);
    out += '\n';
  }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out += 'f';
    for (std::size_t k = 0; k < mesh.face_size(f); ++k) {
      out += ' ';
      put_uint(out, std::uint64_t{mesh.face(f)[k]} + 1);
    }
    out += '\n';
  }
  return out;
}

std::string off(const Mesh& mesh) {
  std::string out = "OFF\n";
  out.reserve(mesh.vertices.size() * 60 + mesh.corners.size() * 8);
  put_uint(out, mesh.vertices.size());
  out += ' ';
  put_uint(out, mesh.face_count());
  out += " 0\n";
  for (const Vec3d& v : mesh.vertices) {
    put_vec(out, v);
    out += '\n';
  }
  put_counted_faces(out, mesh);
  return out;
}

std::string ply(const Mesh& mesh, MeshFormat format, const WriteOptions& o) {
  std::size_t max_face = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    max_face = std::max(max_face, mesh.face_size(f));
  const char* count_type = max_face <= 255 ? "uchar" : "uint";
  const char* coord_type = o.single_precision ? "float" : "double";
  std::string out = "ply\nformat ";
  out += format == MeshFormat::ply_ascii       ? "ascii"
         : format == MeshFormat::ply_binary_le ? "binary_little_endian"
                                               : "binary_big_endian";
  out += " 1.0\ncomment written by pgamesh\nelement vertex ";
  put_uint(out, mesh.vertices.size());
  for (const char* axis : {"x", "y", "z"})
    out += std::string("\nproperty ") + coord_type + " " + axis;
  out += "\nelement face ";
  put_uint(out, mesh.face_count());
  out += std::string("\nproperty list ") + count_type + " uint vertex_indices\nend_header\n";
  if (format == MeshFormat::ply_ascii) {
    for (const Vec3d& v : mesh.vertices) {
      if (o.single_precision)
        put_vec(out, {float_rounded(v.x), float_rounded(v.y), float_rounded(v.z)});
      else
        put_vec(out, v);
      out += '\n';
    }
    put_counted_faces(out, mesh);
    return out;
  }
  const bool big = format == MeshFormat::ply_binary_be;
  for (const Vec3d& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      if (o.single_precision)
        put_f32(out, static_cast<float>(v[k]), big);
      else
        put_raw(out, std::bit_cast<std::uint64_t>(v[k]), big);
    }
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (max_face <= 255)
      out += static_cast<char>(mesh.face_size(f));
    else
      put_raw(out, static_cast<std::uint32_t>(mesh.face_size(f)), big);
    for (std::size_t k = 0; k < mesh.face_size(f); ++k) put_raw(out, mesh.face(f)[k], big);
  }
  return out;
}

// 3MF's spelled-out unit names (core specification §3.4.1); millimeter, its default, when the
// mesh's unit is not stated.
const char* threemf_unit(LengthUnit u) {
  switch (u) {
    case LengthUnit::micron:
      return "micron";
    case LengthUnit::centimeter:
      return "centimeter";
    case LengthUnit::inch:
      return "inch";
    case LengthUnit::foot:
      return "foot";
    case LengthUnit::meter:
      return "meter";
    case LengthUnit::millimeter:
    case LengthUnit::unspecified:
      break;
  }
  return "millimeter";
}

// A 3MF package of one object: polygons as fans (as for STL); 3MF forbids a triangle that repeats
// a vertex, so such a face is refused rather than written into a file no reader accepts.
std::string threemf(const Mesh& mesh, const WriteOptions& o) {
  std::string model =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<model unit=\"";
  model += threemf_unit(o.unit);
  model +=
      "\" xml:lang=\"en-US\" "
      "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n"
      " <resources>\n  <object id=\"1\" type=\"model\">\n   <mesh>\n    <vertices>\n";
  model.reserve(model.size() + mesh.vertices.size() * 90 + triangle_count(mesh) * 50 + 256);
  for (const Vec3d& v : mesh.vertices) {
    model += "     <vertex x=\"";
    put_double(model, v.x);
    model += "\" y=\"";
    put_double(model, v.y);
    model += "\" z=\"";
    put_double(model, v.z);
    model += "\"/>\n";
  }
  model += "    </vertices>\n    <triangles>\n";
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    for (std::size_t k = 1; k + 1 < mesh.face_size(f); ++k) {
      if (c[0] == c[k] || c[k] == c[k + 1] || c[0] == c[k + 1])
        throw std::invalid_argument("write_mesh: face " + std::to_string(f) +
                                    " repeats a vertex, which 3MF forbids");
      model += "     <triangle v1=\"";
      put_uint(model, c[0]);
      model += "\" v2=\"";
      put_uint(model, c[k]);
      model += "\" v3=\"";
      put_uint(model, c[k + 1]);
      model += "\"/>\n";
    }
  }
  model +=
      "    </triangles>\n   </mesh>\n  </object>\n </resources>\n"
      " <build>\n  <item objectid=\"1\"/>\n </build>\n</model>\n";
  const std::string content_types =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">\n"
      " <Default Extension=\"rels\" "
      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>\n"
      " <Default Extension=\"model\" "
      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>\n"
      "</Types>\n";
  const std::string rels =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">\n"
      " <Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
      "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/>\n"
      "</Relationships>\n";
  return detail::zip_archive(
      {{"[Content_Types].xml", content_types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

}  // namespace

std::string write_mesh_bytes(const Mesh& mesh, MeshFormat format, const WriteOptions& options) {
  validate(mesh);
  switch (format) {
    case MeshFormat::stl_ascii:
      return stl_ascii(mesh, options);
    case MeshFormat::stl_binary:
      return stl_binary(mesh, options);
    case MeshFormat::obj:
      return obj(mesh);
    case MeshFormat::ply_ascii:
    case MeshFormat::ply_binary_le:
    case MeshFormat::ply_binary_be:
      return ply(mesh, format, options);
    case MeshFormat::off:
      return off(mesh);
    case MeshFormat::threemf:
      return threemf(mesh, options);
    case MeshFormat::gltf:
    case MeshFormat::glb:
      return detail::write_gltf(mesh, format == MeshFormat::glb);
    case MeshFormat::slp:  // an SLP without colours is ASCII STL text
      return stl_ascii(mesh, options);
    case MeshFormat::unknown:
      break;
  }
  throw std::invalid_argument("write_mesh: no format given");
}

void write_mesh(const Mesh& mesh, const std::string& path, MeshFormat format,
                const WriteOptions& options) {
  write_file_atomically(path, write_mesh_bytes(mesh, format, options));
}

}  // namespace pgamesh
