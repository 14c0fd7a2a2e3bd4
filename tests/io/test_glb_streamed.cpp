// A GLB of one untransformed, non-indexed float32 triangle list is analysed through the binary
// STL's streamed passes (docs/formats.md, "glTF 2.0"): the figures of the same triangles written
// as a binary STL bit for bit, and those of the GLB read into a Mesh to rounding, with the Mesh
// path's counts, unit and part. Every other GLB still takes the Mesh path, errors included.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using StreamJson = nlohmann::json;

// The triangles of `m` (its polygons fanned) as a soup: three fresh vertices a triangle, corners
// 0, 1, 2, … in order — what reading a binary STL gives, and what the glTF writer writes without
// indices.
Mesh stream_soup(const Mesh& m) {
  const Mesh t = test::triangulated(m);
  Mesh soup;
  for (std::size_t f = 0; f < t.face_count(); ++f) {
    const auto v = static_cast<std::uint32_t>(soup.vertices.size());
    for (int k = 0; k < 3; ++k) soup.vertices.push_back(t.vertices[t.face(f)[k]]);
    soup.add_face({v, v + 1, v + 2});
  }
  return soup;
}

// The JSON chunk and the BIN chunk of a GLB, and the GLB of them again (glTF 2.0 §4.4: chunks
// padded to 4 bytes, JSON with spaces, BIN with zeros).
struct StreamGlb {
  StreamJson doc;
  std::string bin;
};

std::uint32_t stream_le32(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);  // the test machines are little-endian, as GLB is
  return v;
}

StreamGlb stream_glb_pieces(const std::string& glb) {
  const std::uint32_t json_length = stream_le32(glb.data() + 12);
  StreamGlb out;
  out.doc = StreamJson::parse(glb.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  out.bin = glb.substr(bin_at + 8, stream_le32(glb.data() + bin_at));
  return out;
}

std::string stream_glb_bytes(const StreamGlb& g) {
  std::string json = g.doc.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string bin = g.bin;
  bin.append((4 - bin.size() % 4) % 4, '\0');
  const auto put = [](std::string& out, std::size_t v) {
    const auto u = static_cast<std::uint32_t>(v);
    out.append(reinterpret_cast<const char*>(&u), 4);
  };
  std::string out = "glTF";
  put(out, 2);
  put(out, 12 + 8 + json.size() + 8 + bin.size());
  put(out, json.size());
  put(out, 0x4E4F534A);
  out += json;
  put(out, bin.size());
  put(out, 0x004E4942);
  return out + bin;
}

AnalysisOptions stream_options(bool topology) {
  AnalysisOptions o;
  o.topology = topology;
  o.topology_options.self_intersections = false;  // its own tests; not a streamed figure
  return o;
}

Analysis stream_analyze(const std::string& bytes, const std::string& name, bool topology) {
  return analyze_bytes({bytes.data(), bytes.size()}, name, stream_options(topology));
}

// The GLB's analysis through the Mesh path: read, then analyze_mesh().
Analysis mesh_path_analysis(const std::string& glb, bool topology) {
  MeshSource source;
  const Mesh mesh = read_mesh_bytes({glb.data(), glb.size()}, "m.glb", &source);
  return analyze_mesh(mesh, source, stream_options(topology));
}

// Equal to rounding: the streamed sums are taken about the centre of a sample of the triangles,
// the Mesh path's about the centre of all vertices.
void expect_near_analysis(const Analysis& a, const Analysis& b) {
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.unit, b.unit);
  EXPECT_EQ(a.single_precision, b.single_precision);
  EXPECT_EQ(a.mass.faces, b.mass.faces);
  EXPECT_EQ(a.mass.triangles, b.mass.triangles);
  EXPECT_EQ(a.mass.vertices, b.mass.vertices);
  EXPECT_EQ(a.warnings, b.warnings);
  EXPECT_EQ(a.volume_valid, b.volume_valid);
  const double scale = std::abs(a.mass.area);
  EXPECT_NEAR(a.mass.area, b.mass.area, 1e-12 * scale);
  EXPECT_NEAR(a.mass.volume, b.mass.volume, 1e-12 * scale);
  EXPECT_NEAR(a.mass.gap_area, b.mass.gap_area, 1e-12 * scale);
  const double far = 1 + length(a.mass.center_of_mass);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(a.mass.center_of_mass[k], b.mass.center_of_mass[k], 1e-12 * far);
  const double inertia = test::max_abs(a.mass.inertia_com);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(a.mass.inertia_com[i][j], b.mass.inertia_com[i][j], 1e-9 * inertia);
  ASSERT_EQ(a.topology.has_value(), b.topology.has_value());
  if (a.topology) {
    EXPECT_EQ(a.topology->vertices, b.topology->vertices);
    EXPECT_EQ(a.topology->merged_vertices, b.topology->merged_vertices);
    EXPECT_EQ(a.topology->edges, b.topology->edges);
    EXPECT_EQ(a.topology->boundary_edges, b.topology->boundary_edges);
    EXPECT_EQ(a.topology->closed, b.topology->closed);
    EXPECT_EQ(a.topology->boundary_loops.size(), b.topology->boundary_loops.size());
  }
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (std::size_t p = 0; p < a.parts.size(); ++p) {
    EXPECT_EQ(a.parts[p].part.name, b.parts[p].part.name);
    EXPECT_EQ(a.parts[p].part.first_face, b.parts[p].part.first_face);
    EXPECT_EQ(a.parts[p].part.face_count, b.parts[p].part.face_count);
  }
}

// The soup written as binary STL and as GLB (by the project's writers) analysed from memory and
// from a file (whose records are read with pread), with and without topology: the GLB's figures
// are the STL's bit for bit, and the Mesh path's to rounding (bit for bit with the weld).
void expect_glb_streams_as_stl(const Mesh& soup, const char* what) {
  SCOPED_TRACE(what);
  const std::string stl = write_mesh_bytes(soup, MeshFormat::stl_binary);
  const std::string glb = write_mesh_bytes(soup, MeshFormat::glb);
  // The writer writes a soup without indices: the case that is streamed.
  EXPECT_FALSE(stream_glb_pieces(glb).doc["meshes"][0]["primitives"][0].contains("indices"));
  const test::TempFile stl_file(".stl", stl), glb_file(".glb", glb);
  for (bool topology : {false, true}) {
    SCOPED_TRACE(topology ? "topology" : "no topology");
    const Analysis s = stream_analyze(stl, "m.stl", topology);
    const Analysis from_file = analyze_file(glb_file.path(), stream_options(topology));
    for (const Analysis& g : {stream_analyze(glb, "m.glb", topology), from_file}) {
      EXPECT_EQ(g.format, MeshFormat::glb);
      EXPECT_EQ(g.unit, LengthUnit::meter);
      EXPECT_TRUE(g.single_precision);
      EXPECT_EQ(g.streamed, !topology);  // as the binary STL's
      test::expect_same_mass(g.mass, s.mass);
      EXPECT_EQ(g.warnings, s.warnings);
      EXPECT_EQ(g.reasons, s.reasons);
      EXPECT_EQ(g.volume_valid, s.volume_valid);
      ASSERT_EQ(g.topology.has_value(), topology);
      if (topology) test::expect_same_report(*g.topology, *s.topology);
      const Analysis mesh_path = mesh_path_analysis(glb, topology);
      expect_near_analysis(g, mesh_path);
      // The weld's figures are the read mesh's, bit for bit (welded_triangles.hpp).
      if (topology) test::expect_same_mass(g.mass, mesh_path.mass);
    }
    const Analysis stl_from_file = analyze_file(stl_file.path(), stream_options(topology));
    test::expect_same_mass(from_file.mass, stl_from_file.mass);
  }
}

TEST(GlbStreamed, ClosedSoupGivesTheBinaryStlFiguresBitForBit) {
  const Mesh sphere = stream_soup(test::uv_sphere(1.5, 12, 25));
  expect_glb_streams_as_stl(sphere, "sphere");
  // 67 600 triangles: many blocks of records, the weld split between two threads, and a last
  // record that ends the file (the four-record gather must stay inside it).
  const Mesh large = stream_soup(test::uv_sphere(1, 131, 260));
  ASSERT_GT(large.face_count(), 65536u);
  expect_glb_streams_as_stl(large, "large sphere");
}

TEST(GlbStreamed, OpenSoupGivesTheBinaryStlFiguresBitForBit) {
  Mesh open = stream_soup(test::uv_sphere(2, 10, 17));
  // Drop the last five triangles (their vertices too): a hole of boundary edges.
  open.vertices.resize(open.vertices.size() - 15);
  open.corners.resize(open.corners.size() - 15);
  open.face_offsets.resize(open.face_offsets.size() - 5);
  const Analysis a = stream_analyze(write_mesh_bytes(open, MeshFormat::glb), "open.glb", true);
  ASSERT_TRUE(a.topology);
  EXPECT_FALSE(a.topology->closed);
  EXPECT_GT(a.topology->boundary_edges, 0u);
  expect_glb_streams_as_stl(open, "open sphere");
}

TEST(GlbStreamed, Float32WarningIsTheBinaryStlsOne) {
  // A sphere of radius 1 at 100 m from the origin: float32 spacing 7.6e-6 > 1e-6 of its size.
  const Mesh far = stream_soup(test::transformed(test::uv_sphere(1, 9, 14), [](Vec3d p) {
    return p + Vec3d{100, 50, 0};
  }));
  const Analysis a = stream_analyze(write_mesh_bytes(far, MeshFormat::glb), "far.glb", false);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("float32 coordinates reach"), std::string::npos) << a.warnings[0];
  expect_glb_streams_as_stl(far, "far sphere");
}

// An identity matrix, a zero translation, a unit rotation and scale move nothing: streamed, with
// the figures of the node without them.
TEST(GlbStreamed, IdentityTransformsAreStreamed) {
  const std::string glb = write_mesh_bytes(stream_soup(test::uv_sphere(1, 8, 12)), MeshFormat::glb);
  StreamGlb g = stream_glb_pieces(glb);
  g.doc["nodes"] = {
      {{"children", {1}}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}},
      {{"mesh", 0},
       {"name", "shell"},
       {"translation", {0, 0, 0}},
       {"rotation", {0, 0, 0, 1}},
       {"scale", {1, 1, 1}}}};
  g.doc["bufferViews"][0]["byteStride"] = 12;
  const std::string moved = stream_glb_bytes(g);
  for (bool topology : {false, true}) {
    const Analysis plain = stream_analyze(glb, "a.glb", topology);
    const Analysis a = stream_analyze(moved, "b.glb", topology);
    EXPECT_EQ(a.streamed, !topology);
    test::expect_same_mass(a.mass, plain.mass);
    if (topology) test::expect_same_report(*a.topology, *plain.topology);
    ASSERT_EQ(a.parts.size(), 1u);
    EXPECT_EQ(a.parts[0].part.name, "shell");  // the Mesh path's name for the node
    expect_near_analysis(a, mesh_path_analysis(moved, topology));
  }
}

// --format glb or gltf (either reads both) streams it as detection does.
TEST(GlbStreamed, ForcedGltfFormatsStreamIt) {
  const std::string glb = write_mesh_bytes(stream_soup(test::uv_sphere(1, 5, 7)), MeshFormat::glb);
  for (MeshFormat format : {MeshFormat::glb, MeshFormat::gltf}) {
    AnalysisOptions o = stream_options(false);
    o.format = format;
    const Analysis a = analyze_bytes({glb.data(), glb.size()}, "m.glb", o);
    EXPECT_TRUE(a.streamed);
    test::expect_same_mass(a.mass, stream_analyze(glb, "m.glb", false).mass);
  }
}

// Indexed, a translated node, two primitives: not the streamed case; the Mesh path's figures bit
// for bit.
TEST(GlbStreamed, OtherGlbsTakeTheMeshPath) {
  const Mesh sphere = test::uv_sphere(1, 8, 12);
  const std::string soup = write_mesh_bytes(stream_soup(sphere), MeshFormat::glb);
  std::vector<std::pair<std::string, std::string>> cases;
  cases.push_back({"indexed", write_mesh_bytes(sphere, MeshFormat::glb)});
  StreamGlb translated = stream_glb_pieces(soup);
  translated.doc["nodes"][0]["translation"] = {0.5, 0, 0};
  cases.push_back({"translated", stream_glb_bytes(translated)});
  // The soup's triangles as two primitives of one mesh: accessors of the first and the rest.
  StreamGlb two = stream_glb_pieces(soup);
  const std::uint64_t count = two.doc["accessors"][0]["count"];
  const std::uint64_t first = 3 * (count / 6);
  two.doc["accessors"][0]["count"] = first;
  two.doc["accessors"][0].erase("min");
  two.doc["accessors"][0].erase("max");
  two.doc["accessors"].push_back({{"bufferView", 0},
                                  {"byteOffset", 12 * first},
                                  {"componentType", 5126},
                                  {"count", count - first},
                                  {"type", "VEC3"}});
  two.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 1}}}});
  cases.push_back({"two primitives", stream_glb_bytes(two)});
  for (const auto& [what, glb] : cases) {
    SCOPED_TRACE(what);
    for (bool topology : {false, true}) {
      const Analysis a = stream_analyze(glb, "m.glb", topology);
      const Analysis want = mesh_path_analysis(glb, topology);
      EXPECT_FALSE(a.streamed);
      test::expect_same_mass(a.mass, want.mass);
      if (topology) test::expect_same_report(*a.topology, *want.topology);
      EXPECT_EQ(a.parts.size(), want.parts.size());
    }
  }
}

// The message of the InputError that `run` throws ("" when none).
template <class Run>
std::string stream_error(Run&& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A file laid out as the streamed case but broken is the reader's to report, word for word.
TEST(GlbStreamed, HostileFilesGiveTheReadersErrors) {
  const std::string glb = write_mesh_bytes(stream_soup(test::uv_sphere(1, 6, 9)), MeshFormat::glb);
  std::vector<std::pair<std::string, std::string>> cases;
  StreamGlb past = stream_glb_pieces(glb);  // three elements past the end of the bufferView
  past.doc["accessors"][0]["count"] = past.doc["accessors"][0]["count"].get<std::uint64_t>() + 3;
  cases.push_back({"accessors[0].count", stream_glb_bytes(past)});
  StreamGlb long_view = stream_glb_pieces(glb);  // a bufferView past the end of the buffer
  long_view.doc["bufferViews"][0]["byteLength"] = long_view.bin.size() + 36;
  cases.push_back({"bufferViews[0]", stream_glb_bytes(long_view)});
  StreamGlb nan = stream_glb_pieces(glb);  // a NaN coordinate in the last triangle
  const float q = std::nanf("");
  std::memcpy(nan.bin.data() + nan.bin.size() - 4, &q, 4);
  cases.push_back({"not finite", stream_glb_bytes(nan)});
  const std::string truncated = glb.substr(0, glb.size() - 40);  // BIN chunk past the file
  cases.push_back({"past the end", truncated});
  for (const auto& hostile : cases) {
    const std::string& expected = hostile.first;
    const std::string& bytes = hostile.second;  // a name lambdas can capture (clang 14)
    SCOPED_TRACE(expected);
    const std::string reader = stream_error([&] {
      read_mesh_bytes({bytes.data(), bytes.size()}, "h.glb");
    });
    EXPECT_NE(reader.find(expected), std::string::npos) << reader;
    for (bool topology : {false, true})
      EXPECT_EQ(stream_error([&] { stream_analyze(bytes, "h.glb", topology); }), reader);
  }
}

}  // namespace
}  // namespace pgamesh
