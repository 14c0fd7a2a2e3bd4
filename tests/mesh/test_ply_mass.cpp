// The PLY reader's two consumers against each other, and the front door against the Mesh path:
// one parametrised test. Each case is a set of PLY files — test meshes (closed, open, with defects,
// repaired) in every encoding and type layout, real meshes, and malformed files — and for each
// file
//   * the summing consumer (read_ply_summing_faces: each face summed as it is parsed, no face
//     list) gives mass_properties() of the Mesh consumer's mesh (read_ply) bit for bit, on any
//     thread count, with the same source fields — or the same InputError text;
//   * `props --no-topology` through the front door (analyze_bytes) gives mass_properties() of
//     read_mesh_bytes() bit for bit — or the same InputError text.
// The summing consumer declines (nullopt) only a file whose faces come before its vertices; the
// front door then reads it into a Mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry/chunked_sums.hpp"
#include "io/readers.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "support/byte_order.hpp"
#include "support/file_bytes.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "topology_test_meshes.hpp"

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

std::vector<Layout> all_layouts() {
  std::vector<Layout> out;
  for (Enc enc : {Enc::ascii, Enc::le, Enc::be})
    for (bool fl : {false, true})
      for (const char* count : {"uchar", "int", "uint"})
        for (const char* index : {"int", "uint"})
          for (bool extras : {false, true}) out.push_back({enc, fl, count, index, extras});
  return out;
}

// The mesh in every layout.
std::vector<std::string> in_every_layout(const Mesh& m) {
  std::vector<std::string> out;
  for (const Layout& l : all_layouts()) out.push_back(ply_bytes(m, l));
  return out;
}

// The malformed variants of the mesh's file in every layout: truncated in the last face and in
// the vertices, and the last face's last index out of range.
std::vector<std::string> damaged_in_every_layout(const Mesh& m) {
  std::vector<std::string> bad;
  for (const Layout& l : all_layouts()) {
    const std::string good = ply_bytes(m, l);
    bad.push_back(good.substr(0, good.size() - 3));
    bad.push_back(good.substr(0, good.find("end_header") + 11 + 20));
    if (l.extras) continue;  // the ignored element comes last
    std::string index;
    if (l.enc == Enc::ascii) {
      index = good.substr(0, good.find_last_of(' ', good.size() - 2) + 1) + "9\n";
    } else {
      put_integer(index, l.index_type, 0, false);  // the size of one index
      const std::size_t width = index.size();
      index = good.substr(0, good.size() - width);
      put_integer(index, l.index_type, 99, l.enc == Enc::be);
    }
    bad.push_back(index);
  }
  return bad;
}

const std::string kTriangleHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n";

// A case: its name, the format the front door is told (unknown: detected) and its files.
struct PlyCase {
  std::string name;
  std::function<std::vector<std::string>()> files;
  MeshFormat format = MeshFormat::unknown;
};

void PrintTo(const PlyCase& c, std::ostream* os) {
  *os << c.name;
}

// The figures of a path, or the text of its InputError.
struct Outcome {
  std::optional<MassProperties> mass;
  MeshSource source;
  std::string error;
  bool declined = false;  // the summing consumer only: faces before vertices
};

template <class Run>
Outcome outcome(const Run& run) {
  Outcome o;
  try {
    run(o);
  } catch (const InputError& e) {
    o.error = e.what();
  }
  return o;
}

void expect_same_outcome(const Outcome& a, const Outcome& b) {
  EXPECT_EQ(a.error, b.error);
  ASSERT_EQ(a.mass.has_value(), b.mass.has_value());
  if (!a.mass) return;
  test::expect_same_mass(*a.mass, *b.mass);
  EXPECT_EQ(a.source.format, b.source.format);
  EXPECT_EQ(a.source.single_precision, b.source.single_precision);
  EXPECT_EQ(a.source.warnings, b.source.warnings);
}

class PlyConsumers : public testing::TestWithParam<PlyCase> {};

TEST_P(PlyConsumers, SummingConsumerAndFrontDoorEqualMassPropertiesOfTheReadMesh) {
  const std::vector<std::string> files = GetParam().files();
  if (files.empty()) GTEST_SKIP() << "no files (../shared/meshes not found)";
  for (std::size_t i = 0; i < files.size(); ++i) {
    SCOPED_TRACE("file " + std::to_string(i) + ": " + files[i].substr(0, 300));
    const std::span<const char> bytes(files[i].data(), files[i].size());

    // The consumers: the Mesh (its mass properties on 0 = all, 1 and 3 threads) and the sums.
    Mesh mesh;
    const Outcome stored = outcome([&](Outcome& o) {
      detail::read_ply(bytes, "mem.ply", mesh, o.source);
      o.mass = mass_properties(mesh, {}, &o.source);
    });
    const Outcome summed = outcome([&](Outcome& o) {
      Mesh vertices;
      const auto sums = detail::read_ply_summing_faces(bytes, "mem.ply", vertices, o.source);
      o.declined = !sums;
      if (sums)
        o.mass = mesh_mass_properties_from_sums(sums->sums, sums->reference, vertices.vertices,
                                                sums->faces, sums->triangles, {},
                                                o.source.single_precision);
    });
    if (summed.declined) {
      EXPECT_TRUE(stored.mass.has_value()) << "declined a file the Mesh consumer rejects";
      EXPECT_EQ(GetParam().name, "FacesBeforeVertices");
    } else {
      expect_same_outcome(summed, stored);
    }
    if (stored.mass)
      for (unsigned threads : {1u, 3u}) {
        MassOptions o;
        o.threads = threads;
        test::expect_same_mass(mass_properties(mesh, o, &stored.source), *stored.mass);
      }

    // The front door without topology against the Mesh path.
    const Outcome mesh_path = outcome([&](Outcome& o) {
      const Mesh m = read_mesh_bytes(bytes, "mem.ply", &o.source, GetParam().format);
      o.mass = mass_properties(m, {}, &o.source);
    });
    const Outcome front_door = outcome([&](Outcome& o) {
      AnalysisOptions options;
      options.topology = false;
      options.format = GetParam().format;
      const Analysis a = analyze_bytes(bytes, "mem.ply", options);
      o.mass = a.mass;
      o.source.format = a.format;
      o.source.single_precision = a.single_precision;
      o.source.warnings = a.warnings;  // the reader's, then the figures'
      o.source.warnings.resize(o.source.warnings.size() - a.mass.warnings.size());
      EXPECT_FALSE(a.streamed);
    });
    expect_same_outcome(front_door, mesh_path);
  }
}

Mesh sphere_far_away() {
  // More faces than three chunks of chunked_sums, offset from the origin.
  return test::transformed(test::uv_sphere(3, 160, 320), [](Vec3d p) {
    return p + Vec3d{1e3, -2e3, 5e2};
  });
}

Mesh open_box() {
  Mesh m = test::box_mesh(1, 2, 3);
  m.face_offsets.pop_back();
  m.corners.resize(m.face_offsets.back());
  return m;
}

Mesh non_manifold_cube() {
  Mesh m = test::unit_cube();
  m.vertices.push_back({0.5, 0.5, 3});
  m.add_face({0, 2, 8});            // a third face on the edge (0, 2)
  m.vertices.push_back({9, 9, 9});  // unreferenced
  m.add_face({1, 1, 5});            // collapsed
  return m;
}

// Faces flipped, then repaired by fix_orientation (check --fix-orientation).
Mesh repaired_sphere() {
  Mesh m = test::with_flipped(test::triangulated(test::uv_sphere(1, 8, 16)), {3, 4, 40, 41});
  fix_orientation(m);
  return m;
}

std::vector<std::string> one(std::string s) {
  return {std::move(s)};
}

std::vector<PlyCase> ply_cases() {
  std::vector<PlyCase> c;
  const auto mesh_case = [&](std::string name, std::function<Mesh()> make) {
    c.push_back({name, [make] { return in_every_layout(make()); }});
  };
  // Quads and triangles (the sphere's caps), closed; a box of quads, closed and open.
  mesh_case("SphereOfQuadsAndTriangles", [] { return test::uv_sphere(1.25, 6, 9); });
  mesh_case("Box", [] { return test::box_mesh(1, 2, 3); });
  mesh_case("OpenBox", open_box);
  mesh_case("CubeWithFlippedFaces", [] { return test::with_flipped(test::unit_cube(), {2, 7}); });
  mesh_case("NonManifoldCollapsedUnreferenced", non_manifold_cube);
  mesh_case("RepairedOrientation", repaired_sphere);
  mesh_case("VerticesOnly", [] {
    Mesh m;
    m.vertices = test::box_mesh(1, 1, 1).vertices;
    return m;
  });
  c.push_back({"ManyChunks", [] {
                 const Mesh m = sphere_far_away();
                 return std::vector<std::string>{
                     ply_bytes(m, {Enc::ascii, false, "uchar", "int", false}),
                     ply_bytes(m, {Enc::le, false, "uchar", "int", false}),
                     ply_bytes(m, {Enc::be, true, "int", "uint", true})};
               }});
  // Far from the origin in float32: the precision warning; the extra element: its warning.
  c.push_back({"Float32WarningAndIgnoredElement", [] {
                 const Mesh far = test::transformed(test::box_mesh(1, 1, 1), [](Vec3d p) {
                   return p + Vec3d{3e5, 0, 0};
                 });
                 return std::vector<std::string>{
                     ply_bytes(far, {Enc::le, true, "uchar", "int", true}),
                     ply_bytes(far, {Enc::be, true, "uint", "uint", true})};
               }});
  c.push_back({"NoFaceElement", [] {
                 return one(
                     "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                     "property float y\nproperty float z\nend_header\n0 0 0\n1 2 3\n");
               }});
  c.push_back({"FacesBeforeVertices", [] {
                 return one(
                     "ply\nformat ascii 1.0\nelement face 1\n"
                     "property list uchar int vertex_indices\nelement vertex 3\n"
                     "property float x\nproperty float y\nproperty float z\nend_header\n"
                     "3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n");
               }});
  // Errors: the same text and position from every path.
  c.push_back({"TruncatedOrIndexOutOfRange",
               [] { return damaged_in_every_layout(test::box_mesh(1, 1, 1)); }});
  c.push_back({"NonFiniteCoordinate", [] {
                 Mesh m = test::box_mesh(1, 1, 1);
                 m.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
                 return std::vector<std::string>{
                     ply_bytes(m, {Enc::ascii, false, "uchar", "int", false}),
                     ply_bytes(m, {Enc::le, true, "uchar", "int", false}),
                     ply_bytes(m, {Enc::be, false, "uchar", "int", true})};
               }});
  c.push_back(
      {"FaceOfTwoCornersOrNegativeIndex", [] {
         return std::vector<std::string>{kTriangleHead + "2 0 1\n", kTriangleHead + "3 0 -1 2\n"};
       }});
  c.push_back({"MalformedHeader", [] {
                 return std::vector<std::string>{
                     "ply\nformat", "ply\nformat ascii 1.0\nelement vertex 0\n",
                     "ply\nend_header\n", "ply\nformat ascii 1.0\nbogus\nend_header\n",
                     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                     "property float y\nend_header\n0 0\n"};
               }});
  // Told the format: the front door's error for an empty file is read_mesh_bytes' own.
  c.push_back({"EmptyFileToldPly",
               [] {
                 return std::vector<std::string>{"", " \n "};
               },
               MeshFormat::ply_binary_le});
  // The real meshes of ../shared/meshes: the PLY files as they are, every mesh written as PLY.
  c.push_back({"RealMeshes", [] {
                 std::vector<std::string> out;
                 const std::filesystem::path dir = PGAMESH_SHARED_MESHES_DIR;
                 if (!std::filesystem::is_directory(dir)) return out;
                 std::size_t meshes = 0;
                 for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
                   if (!entry.is_regular_file() || entry.file_size() > (std::uintmax_t{2} << 20))
                     continue;
                   const std::string path = entry.path().string();
                   if (entry.path().extension() == ".ply") out.push_back(test::file_bytes(path));
                   Mesh m;
                   try {
                     m = read_mesh(path);
                   } catch (const std::exception&) {
                     continue;  // defective on purpose: the readers' tests cover it
                   }
                   if (m.face_count() == 0 || ++meshes > 40) continue;
                   out.push_back(ply_bytes(m, {Enc::le, false, "uchar", "uint", false}));
                   out.push_back(ply_bytes(m, {Enc::ascii, false, "int", "int", true}));
                 }
                 return out;
               }});
  return c;
}

INSTANTIATE_TEST_SUITE_P(Ply, PlyConsumers, testing::ValuesIn(ply_cases()),
                         [](const testing::TestParamInfo<PlyCase>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace pgamesh
