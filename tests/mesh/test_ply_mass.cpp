// ply_mass_properties, which sums a PLY's faces as it parses them and keeps no face list, against
// the Mesh path (read_mesh_bytes, then mass_properties) field by field and bit for bit: ASCII,
// binary little- and big-endian, float and double coordinates, uchar/int/uint list counts,
// int/uint indices, extra properties and elements, triangles and polygons, closed and open meshes,
// more faces than one chunk, the real meshes of ../shared/meshes written as PLY; the same
// InputError text for truncated files, bad indices and NaN; declined when faces precede vertices.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "pgamesh/core/input_error.hpp"
#include "pgamesh/geometry/chunked_sums.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/mass/ply_mass_properties.hpp"
#include "support/byte_order.hpp"
#include "support/solids.hpp"

namespace pgamesh {
namespace {

enum class Enc { ascii, le, be };

// How a test file lays out its data.
struct Layout {
  Enc enc = Enc::le;
  bool float_coords = false;  // float32 x, y, z (else double)
  std::string count_type = "uchar", index_type = "int";
  bool extras = false;  // a normal before x, a flag before the faces' list, an ignored element
};

using test::put;

void put_integer(std::string& out, const std::string& type, std::int64_t v, bool big) {
  if (type == "uchar") put<std::uint8_t>(out, static_cast<std::uint8_t>(v), big);
  if (type == "int") put<std::int32_t>(out, static_cast<std::int32_t>(v), big);
  if (type == "uint") put<std::uint32_t>(out, static_cast<std::uint32_t>(v), big);
  if (type == "ushort") put<std::uint16_t>(out, static_cast<std::uint16_t>(v), big);
}

// The mesh as a PLY file, written here independently of the library's writer. ASCII coordinates
// are printed with 17 significant digits, so they read back as the same doubles.
std::string ply_bytes(const Mesh& m, const Layout& l) {
  const char* enc = l.enc == Enc::ascii ? "ascii"
                    : l.enc == Enc::le  ? "binary_little_endian"
                                        : "binary_big_endian";
  const char* coord = l.float_coords ? "float" : "double";
  std::string out = std::string("ply\nformat ") + enc + " 1.0\ncomment test\n";
  out += "element vertex " + std::to_string(m.vertices.size()) + "\n";
  if (l.extras) out += std::string("property ") + coord + " nx\n";
  for (const char* axis : {"x", "y", "z"})
    out += std::string("property ") + coord + " " + axis + "\n";
  out += "element face " + std::to_string(m.face_count()) + "\n";
  if (l.extras) out += "property uchar flag\n";
  out += "property list " + l.count_type + " " + l.index_type + " vertex_indices\n";
  if (l.extras) out += "element material 1\nproperty int id\n";
  out += "end_header\n";
  const bool big = l.enc == Enc::be;
  char buf[64];
  for (const Vec3d& v : m.vertices) {
    if (l.enc == Enc::ascii) {
      if (l.extras) out += "0 ";
      for (int k = 0; k < 3; ++k) {
        std::snprintf(buf, sizeof buf, "%.17g ", v[k]);
        out += buf;
      }
      out += "\n";
      continue;
    }
    if (l.extras) l.float_coords ? put<float>(out, 0.f, big) : put<double>(out, 0.0, big);
    for (int k = 0; k < 3; ++k)
      l.float_coords ? put<float>(out, static_cast<float>(v[k]), big) : put<double>(out, v[k], big);
  }
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    if (l.enc == Enc::ascii) {
      if (l.extras) out += "1 ";
      out += std::to_string(m.face_size(f));
      for (std::size_t k = 0; k < m.face_size(f); ++k) {
        out += ' ';
        out += std::to_string(m.face(f)[k]);
      }
      out += "\n";
      continue;
    }
    if (l.extras) put<std::uint8_t>(out, 1, big);
    put_integer(out, l.count_type, static_cast<std::int64_t>(m.face_size(f)), big);
    for (std::size_t k = 0; k < m.face_size(f); ++k)
      put_integer(out, l.index_type, m.face(f)[k], big);
  }
  if (l.extras) {
    if (l.enc == Enc::ascii)
      out += "7\n";
    else
      put<std::int32_t>(out, 7, big);
  }
  return out;
}

// Doubles compared bit for bit (NaN included).
bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_same(const MassProperties& a, const MassProperties& b) {
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertices, b.vertices);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(same_bits(a.reference_point[k], b.reference_point[k]));
    EXPECT_TRUE(same_bits(a.center_of_mass[k], b.center_of_mass[k])) << k;
    EXPECT_TRUE(same_bits(a.principal.moments[k], b.principal.moments[k])) << k;
    for (int j = 0; j < 3; ++j) {
      EXPECT_TRUE(same_bits(a.inertia_com[k][j], b.inertia_com[k][j])) << k << j;
      EXPECT_TRUE(same_bits(a.inertia_origin[k][j], b.inertia_origin[k][j])) << k << j;
    }
  }
  EXPECT_TRUE(same_bits(a.area, b.area)) << a.area << " vs " << b.area;
  EXPECT_TRUE(same_bits(a.volume, b.volume)) << a.volume << " vs " << b.volume;
  EXPECT_TRUE(same_bits(a.mass, b.mass));
  EXPECT_TRUE(same_bits(a.density, b.density));
  EXPECT_TRUE(same_bits(a.gap_area, b.gap_area));
  EXPECT_TRUE(same_bits(a.carrier_sum.e0, b.carrier_sum.e0));
  EXPECT_TRUE(same_bits(a.carrier_sum.e1, b.carrier_sum.e1));
  EXPECT_TRUE(same_bits(a.carrier_sum.e2, b.carrier_sum.e2));
  EXPECT_TRUE(same_bits(a.carrier_sum.e3, b.carrier_sum.e3));
  EXPECT_EQ(a.warnings, b.warnings);
}

// The Mesh path's figures and source, on `threads` threads.
MassProperties careful(const std::string& bytes, MeshSource& source, unsigned threads = 0) {
  const Mesh m = read_mesh_bytes({bytes.data(), bytes.size()}, "mem.ply", &source);
  MassOptions o;
  o.threads = threads;
  return mass_properties(m, o, &source);
}

// Both paths on `bytes`: the same figures and the same source. Returns the figures.
MassProperties expect_paths_agree(const std::string& bytes) {
  MeshSource careful_source, summed_source;
  const MassProperties expected = careful(bytes, careful_source);
  const auto summed = ply_mass_properties({bytes.data(), bytes.size()}, "mem.ply", summed_source);
  EXPECT_TRUE(summed.has_value());
  if (!summed) return expected;
  expect_same(*summed, expected);
  EXPECT_EQ(summed_source.format, careful_source.format);
  EXPECT_EQ(summed_source.single_precision, careful_source.single_precision);
  EXPECT_EQ(summed_source.warnings, careful_source.warnings);
  EXPECT_EQ(summed_source.path, careful_source.path);
  return *summed;
}

std::vector<Layout> all_layouts() {
  std::vector<Layout> out;
  for (Enc enc : {Enc::ascii, Enc::le, Enc::be})
    for (bool fl : {false, true})
      for (const char* count : {"uchar", "int", "uint"})
        for (const char* index : {"int", "uint"})
          for (bool extras : {false, true}) out.push_back({enc, fl, count, index, extras});
  return out;
}

TEST(PlyMass, EveryEncodingTypeAndLayoutAgreesWithTheMeshPath) {
  // Quads and triangles (the sphere's caps), closed; a cube of quads; an open box.
  const Mesh sphere = test::uv_sphere(1.25, 6, 9);
  const Mesh box = test::box_mesh(1, 2, 3);
  Mesh open = box;
  open.face_offsets.pop_back();
  open.corners.resize(open.face_offsets.back());
  for (const Layout& l : all_layouts()) {
    SCOPED_TRACE(ply_bytes(Mesh{}, l));  // the header says the layout
    const MassProperties s = expect_paths_agree(ply_bytes(sphere, l));
    EXPECT_GT(s.faces, s.triangles / 2);
    const MassProperties b = expect_paths_agree(ply_bytes(box, l));
    EXPECT_NEAR(b.volume, 6.0, 1e-12);  // closed form: 1 × 2 × 3
    const MassProperties o = expect_paths_agree(ply_bytes(open, l));
    EXPECT_GT(o.gap_area, 0);
  }
}

TEST(PlyMass, ManyChunksAndAnyThreadCount) {
  // More faces than several chunks of chunked_sums, offset from the origin.
  const Mesh big = test::transformed(test::uv_sphere(3, 160, 320), [](Vec3d p) {
    return p + Vec3d{1e3, -2e3, 5e2};
  });
  ASSERT_GT(big.face_count(), 3 * faces_per_chunk);
  for (Enc enc : {Enc::ascii, Enc::le}) {
    const std::string bytes = ply_bytes(big, {enc, false, "uchar", "int", false});
    const MassProperties s = expect_paths_agree(bytes);
    for (unsigned threads : {1u, 2u, 5u}) {
      MeshSource source;
      expect_same(s, careful(bytes, source, threads));
    }
    // Closed form of the inscribed polyhedron is not simple; the sphere's volume bounds it.
    EXPECT_LT(s.volume, 4.0 / 3.0 * std::acos(-1.0) * 27);
    EXPECT_GT(s.volume, 0.99 * 4.0 / 3.0 * std::acos(-1.0) * 27);
  }
}

TEST(PlyMass, Float32WarningAndIgnoredElementsAsTheMeshPath) {
  // Far from the origin in float32: the precision warning; an extra element: its warning.
  const Mesh far = test::transformed(test::box_mesh(1, 1, 1), [](Vec3d p) {
    return p + Vec3d{3e5, 0, 0};
  });
  const MassProperties s =
      expect_paths_agree(ply_bytes(far, {Enc::le, true, "uchar", "int", true}));
  EXPECT_EQ(s.warnings.size(), 1u);
  MeshSource source;
  const std::string bytes = ply_bytes(far, {Enc::be, true, "uint", "uint", true});
  ASSERT_TRUE(ply_mass_properties({bytes.data(), bytes.size()}, "mem.ply", source));
  EXPECT_TRUE(source.single_precision);
  ASSERT_EQ(source.warnings.size(), 1u);
  EXPECT_NE(source.warnings[0].find("'material'"), std::string::npos);
}

TEST(PlyMass, NoFacesAndNoFaceElement) {
  const Mesh box = test::box_mesh(1, 1, 1);
  Mesh points;
  points.vertices = box.vertices;
  const MassProperties s =
      expect_paths_agree(ply_bytes(points, {Enc::ascii, false, "uchar", "int", false}));
  EXPECT_EQ(s.faces, 0u);
  EXPECT_EQ(s.volume, 0);
  const std::string no_face_element =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n1 2 3\n";
  expect_paths_agree(no_face_element);
}

TEST(PlyMass, DeclinesWhenFacesComeFirst) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
      "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n";
  MeshSource source;
  EXPECT_FALSE(ply_mass_properties({text.data(), text.size()}, "mem.ply", source));
  MeshSource careful_source;
  EXPECT_EQ(careful(text, careful_source).faces, 1u);  // the Mesh path reads it
}

// The error of each path; empty when none throws (a test failure then).
std::string careful_error(const std::string& bytes) {
  try {
    read_mesh_bytes({bytes.data(), bytes.size()}, "mem.ply");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the Mesh path accepted the file";
  return {};
}
std::string summed_error(const std::string& bytes) {
  try {
    MeshSource source;
    ply_mass_properties({bytes.data(), bytes.size()}, "mem.ply", source);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the summing path accepted the file";
  return {};
}

TEST(PlyMass, BadInputGivesTheSameErrors) {
  const Mesh box = test::box_mesh(1, 1, 1);
  for (const Layout& l : all_layouts()) {
    const std::string good = ply_bytes(box, l);
    std::vector<std::string> bad;
    bad.push_back(good.substr(0, good.size() - 3));                    // truncated in the last face
    bad.push_back(good.substr(0, good.find("end_header") + 11 + 20));  // in the vertices
    // An index out of range: the last face's last corner.
    std::string index = good;
    if (l.enc == Enc::ascii) {
      index = good.substr(0, good.find_last_of(' ', good.size() - 2) + 1) + "9\n";
      if (l.extras) index = good;  // the ignored element comes last: patched below
    } else if (!l.extras) {
      put_integer(index, l.index_type, 0, l.enc == Enc::be);  // size of one index
      const std::size_t width = index.size() - good.size();
      index = good;
      index.resize(good.size() - width);
      put_integer(index, l.index_type, 99, l.enc == Enc::be);
    }
    if (index != good) bad.push_back(index);
    for (const std::string& b : bad) {
      const std::string expected = careful_error(b);
      EXPECT_FALSE(expected.empty());
      EXPECT_EQ(summed_error(b), expected);
    }
  }
  // NaN coordinates, ASCII and binary; a face of two corners; a negative index.
  Mesh nan_box = box;
  nan_box.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  for (Enc enc : {Enc::ascii, Enc::le}) {
    const std::string b = ply_bytes(nan_box, {enc, enc == Enc::le, "uchar", "int", false});
    EXPECT_EQ(summed_error(b), careful_error(b));
    EXPECT_NE(careful_error(b).find("mem.ply"), std::string::npos);
  }
  const std::string two =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n2 0 1\n";
  EXPECT_EQ(summed_error(two), careful_error(two));
  const std::string negative = two.substr(0, two.size() - 6) + "3 0 -1 2\n";
  EXPECT_EQ(summed_error(negative), careful_error(negative));
}

TEST(PlyMass, RealMeshesWrittenAsPly) {
  const std::filesystem::path dir = PGAMESH_SHARED_MESHES_DIR;
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no " << dir;
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file() || entry.file_size() > (std::uintmax_t{2} << 20)) continue;
    const std::string path = entry.path().string();
    Mesh m;
    try {
      m = read_mesh(path);
    } catch (const std::exception&) {
      continue;  // defective on purpose: the readers' tests cover it
    }
    if (m.face_count() == 0) continue;
    SCOPED_TRACE(path);
    if (entry.path().extension() == ".ply") {
      // The file itself, as it is.
      const MappedFile file = MappedFile::open(path);
      expect_paths_agree(std::string(file.bytes().data(), file.bytes().size()));
    }
    expect_paths_agree(ply_bytes(m, {Enc::le, false, "uchar", "uint", false}));
    expect_paths_agree(ply_bytes(m, {Enc::ascii, false, "int", "int", true}));
    if (++compared >= 40) break;
  }
  EXPECT_GE(compared, 5u);
}

}  // namespace
}  // namespace pgamesh
