// The glTF 2.0 reader on files written by hand here (JSON text and a buffer packed byte by byte,
// base64 by the test's own encoder): node transforms against closed forms, strips and fans by the
// specification's formulas, sparse accessors, every index type, and each kind of hostile file
// refused with an InputError naming the JSON path. The writer's files read back exactly.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using GltfJson = nlohmann::json;

std::string gltf_test_base64(const std::string& bytes) {
  const char* d = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (unsigned char c : bytes) {
    acc = (acc << 8) | c;
    bits += 8;
    while (bits >= 6) {
      bits -= 6;
      out += d[(acc >> bits) & 63];
    }
  }
  if (bits) out += d[(acc << (6 - bits)) & 63];
  while (out.size() % 4) out += '=';
  return out;
}

// Little-endian packing of values into a buffer.
struct GltfBlob {
  std::string bytes;
  template <class T>
  GltfBlob& put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof v);
    bytes.append(b, sizeof b);
    return *this;
  }
};

// A list of one mesh of one primitive.
GltfJson one_mesh(const GltfJson& primitive) {
  GltfJson mesh = GltfJson::object();
  mesh["primitives"] = GltfJson::array({primitive});
  return GltfJson::array({mesh});
}

// The unit cube [0,1]³: 8 corners, 12 outward triangles.
const float cube_corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::uint32_t cube_triangles[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                             {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                                             {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};

// A document with the cube's positions (bufferView 0, accessor 0) and its indices in the given
// component type (bufferView 1, accessor 1), one mesh, and `nodes` / `scene` as given.
GltfJson cube_document(int index_type, GltfJson nodes, GltfJson roots) {
  GltfBlob blob;
  for (const auto& c : cube_corners)
    for (float x : c) blob.put(x);
  const std::size_t positions = blob.bytes.size();
  for (const auto& t : cube_triangles)
    for (std::uint32_t i : t) {
      if (index_type == 5121) blob.put(static_cast<std::uint8_t>(i));
      if (index_type == 5123) blob.put(static_cast<std::uint16_t>(i));
      if (index_type == 5125) blob.put(i);
      if (index_type == 5122) blob.put(static_cast<std::int16_t>(i));
      if (index_type == 5126) blob.put(static_cast<float>(i));
    }
  GltfJson doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}};
  doc["scenes"] = {{{"nodes", roots}}};
  doc["nodes"] = nodes;
  doc["meshes"] = one_mesh({{"attributes", {{"POSITION", 0}}}, {"indices", 1}});
  doc["accessors"] = {
      {{"bufferView", 0},
       {"componentType", 5126},
       {"count", 8},
       {"type", "VEC3"},
       {"min", {0, 0, 0}},
       {"max", {1, 1, 1}}},
      {{"bufferView", 1}, {"componentType", index_type}, {"count", 36}, {"type", "SCALAR"}}};
  doc["bufferViews"] = {
      {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions}},
      {{"buffer", 0}, {"byteOffset", positions}, {"byteLength", blob.bytes.size() - positions}}};
  doc["buffers"] = {
      {{"byteLength", blob.bytes.size()},
       {"uri", "data:application/octet-stream;base64," + gltf_test_base64(blob.bytes)}}};
  return doc;
}

Mesh read_gltf_text(const GltfJson& doc, MeshSource* source = nullptr) {
  const std::string text = doc.dump();
  return read_mesh_bytes({text.data(), text.size()}, "test.gltf", source);
}

// The message of the InputError that reading `doc` throws ("" when none).
std::string gltf_error(const GltfJson& doc) {
  try {
    read_gltf_text(doc);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

MassProperties gltf_mass(const Mesh& m) {
  return mass_properties(m);
}

TEST(ReadGltf, NestedNodesPlaceTheCubeByClosedForm) {
  // Parent: scale 2 then translate (0,0,1); child: rotate 90° about z then translate (3,0,0).
  // Child: [0,1]³ → [−1,0]×[0,1]×[0,1] → centre (2.5, 0.5, 0.5); parent: centre (5, 1, 2),
  // volume 2³ = 8, inertia about the centre of a cube of side 2 and mass 8: 8·(4+4)/12.
  const double h = std::sqrt(0.5);
  const GltfJson nodes = {
      {{"children", {1}}, {"scale", {2, 2, 2}}, {"translation", {0, 0, 1}}},
      {{"mesh", 0}, {"rotation", {0, 0, h, h}}, {"translation", {3, 0, 0}}, {"name", "part"}}};
  MeshSource src;
  const Mesh m = read_gltf_text(cube_document(5125, nodes, {0}), &src);
  EXPECT_EQ(src.format, MeshFormat::gltf);
  EXPECT_EQ(src.unit, LengthUnit::meter);
  ASSERT_EQ(src.parts.size(), 1u);
  EXPECT_EQ(src.parts[0].name, "part");
  EXPECT_EQ(src.parts[0].face_count, 12u);
  const MassProperties p = gltf_mass(m);
  EXPECT_NEAR(p.volume, 8, 1e-12);
  EXPECT_NEAR(p.center_of_mass.x, 5, 1e-12);
  EXPECT_NEAR(p.center_of_mass.y, 1, 1e-12);
  EXPECT_NEAR(p.center_of_mass.z, 2, 1e-12);
  EXPECT_NEAR(p.inertia_com[0][0], 8 * 8 / 12.0, 1e-11);
  EXPECT_NEAR(p.inertia_com[2][2], 8 * 8 / 12.0, 1e-11);
}

TEST(ReadGltf, ColumnMajorMatrixAndRootsWithoutAScene) {
  // Translation (1, 2, 3) in the matrix's last column (elements 12, 13, 14); no "scene": every
  // root node is read.
  GltfJson doc = cube_document(
      5123,
      {{{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1}}}, {{"mesh", 0}}},
      {0});
  doc.erase("scene");
  doc.erase("scenes");
  MeshSource src;
  const MassProperties p = gltf_mass(read_gltf_text(doc, &src));
  EXPECT_EQ(src.parts.size(), 2u);
  EXPECT_DOUBLE_EQ(p.volume, 2);
  EXPECT_DOUBLE_EQ(p.center_of_mass.x, (1.5 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(p.center_of_mass.y, (2.5 + 0.5) / 2);
  EXPECT_DOUBLE_EQ(p.center_of_mass.z, (3.5 + 0.5) / 2);
}

TEST(ReadGltf, MirroredNodeKeepsTheVolumePositiveAndWarns) {
  MeshSource src;
  const Mesh m =
      read_gltf_text(cube_document(5125, {{{"mesh", 0}, {"scale", {-1, 1, 1}}}}, {0}), &src);
  const MassProperties p = gltf_mass(m);
  EXPECT_DOUBLE_EQ(p.volume, 1);
  EXPECT_DOUBLE_EQ(p.center_of_mass.x, -0.5);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("winding"), std::string::npos);
}

TEST(ReadGltf, EveryIndexTypeGivesTheSameMeshAndOthersAreRefused) {
  const GltfJson nodes = {{{"mesh", 0}}};
  const Mesh want = read_gltf_text(cube_document(5125, nodes, {0}));
  for (int type : {5121, 5123}) {
    const Mesh got = read_gltf_text(cube_document(type, nodes, {0}));
    EXPECT_EQ(got.corners, want.corners) << type;
    EXPECT_EQ(got.vertices.size(), want.vertices.size());
  }
  ASSERT_EQ(want.face_count(), 12u);
  for (std::size_t f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(want.face(f)[k], cube_triangles[f][k]);
  for (int type : {5122, 5126})
    EXPECT_NE(gltf_error(cube_document(type, nodes, {0})).find("accessors[1].componentType"),
              std::string::npos)
        << type;
}

// A unit square 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1) drawn with `mode` and `indices`.
GltfJson square_document(int mode, const std::vector<std::uint16_t>& indices) {
  GltfBlob blob;
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) blob.put(v);
  for (std::uint16_t i : indices) blob.put(i);
  GltfJson doc = {{"asset", {{"version", "2.0"}}}};
  doc["nodes"] = {{{"mesh", 0}}};
  doc["meshes"] = one_mesh({{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", mode}});
  doc["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                      {{"bufferView", 0},
                       {"byteOffset", 48},
                       {"componentType", 5123},
                       {"count", indices.size()},
                       {"type", "SCALAR"}}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", blob.bytes.size()}}};
  doc["buffers"] = {
      {{"byteLength", blob.bytes.size()},
       {"uri", "data:application/octet-stream;base64," + gltf_test_base64(blob.bytes)}}};
  return doc;
}

std::vector<std::vector<std::uint32_t>> faces_of(const Mesh& m) {
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t f = 0; f < m.face_count(); ++f)
    out.emplace_back(m.face(f), m.face(f) + m.face_size(f));
  return out;
}

TEST(ReadGltf, StripsAndFansFollowTheSpecificationsWinding) {
  // Strip [0 1 3 2]: triangles (0 1 3) and, odd, (1 2 3) — glTF 2.0 §3.7.2.1: both counter-
  // clockwise seen from +z, like the square. Fan [0 1 2 3]: (1 2 0), (2 3 0).
  using F = std::vector<std::vector<std::uint32_t>>;
  EXPECT_EQ(faces_of(read_gltf_text(square_document(5, {0, 1, 3, 2}))), (F{{0, 1, 3}, {1, 2, 3}}));
  EXPECT_EQ(faces_of(read_gltf_text(square_document(6, {0, 1, 2, 3}))), (F{{1, 2, 0}, {2, 3, 0}}));
  // A strip joined by a repeated index: the degenerate triangles are not faces.
  EXPECT_EQ(faces_of(read_gltf_text(square_document(5, {0, 1, 3, 3, 2}))).size(), 1u);
  // Points and lines: skipped, one warning.
  MeshSource src;
  GltfJson doc = square_document(4, {0, 1, 2});
  doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 1}});
  doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
  EXPECT_EQ(read_gltf_text(doc, &src).face_count(), 1u);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("2 primitives of points or lines"), std::string::npos);
}

TEST(ReadGltf, QuantizedPositionsNeedTheirExtension) {
  // The square's positions as int16 (5122): as integers, and normalized (c / 32767), under
  // KHR_mesh_quantization only.
  GltfJson doc = square_document(4, {0, 1, 2});
  GltfBlob blob;
  for (std::int16_t c : {0, 0, 0, 0, 32767, 0, 0, 0, -32767, 0, 32767, 0, 0, 0, 0, 0}) blob.put(c);
  doc["buffers"].push_back(
      {{"byteLength", blob.bytes.size()},
       {"uri", "data:application/octet-stream;base64," + gltf_test_base64(blob.bytes)}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 32}, {"byteStride", 8}});
  doc["accessors"][0] = {
      {"bufferView", 1}, {"componentType", 5122}, {"count", 4}, {"type", "VEC3"}};
  EXPECT_NE(gltf_error(doc).find("KHR_mesh_quantization"), std::string::npos);
  doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  Mesh m = read_gltf_text(doc);
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[1], (Vec3d{32767, 0, 0}));
  EXPECT_EQ(m.vertices[2], (Vec3d{-32767, 0, 32767}));
  doc["accessors"][0]["normalized"] = true;
  m = read_gltf_text(doc);
  EXPECT_EQ(m.vertices[1], (Vec3d{1, 0, 0}));
  EXPECT_EQ(m.vertices[2], (Vec3d{-1, 0, 1}));
}

TEST(ReadGltf, SparseAccessorReplacesTheListedElements) {
  GltfJson doc = square_document(4, {0, 1, 2});
  // Vertex 2 replaced by (2, 3, 4): indices (uint8 2) and values in a second buffer.
  GltfBlob blob;
  blob.put(std::uint8_t{2}).put(std::uint8_t{0}).put(std::uint8_t{0}).put(std::uint8_t{0});
  blob.put(2.f).put(3.f).put(4.f);
  doc["buffers"].push_back(
      {{"byteLength", blob.bytes.size()},
       {"uri", "data:application/octet-stream;base64," + gltf_test_base64(blob.bytes)}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 4}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", 12}});
  doc["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 1}, {"componentType", 5121}}},
                                   {"values", {{"bufferView", 2}}}};
  const Mesh m = read_gltf_text(doc);
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[2], (Vec3d{2, 3, 4}));
  EXPECT_EQ(m.vertices[1], (Vec3d{1, 0, 0}));
}

TEST(ReadGltf, HostileFilesAreInputErrorsNamingThePath) {
  const GltfJson nodes = {{{"mesh", 0}}};
  const GltfJson good = cube_document(5125, nodes, {0});
  auto expect_error = [&](GltfJson doc, const std::string& part) {
    const std::string e = gltf_error(doc);
    EXPECT_NE(e.find(part), std::string::npos) << "expected '" << part << "' in: " << e;
    EXPECT_NE(e.find("test.gltf"), std::string::npos) << e;
  };
  GltfJson d = good;
  d["accessors"][0]["count"] = 9;  // one element past its bufferView
  expect_error(d, "accessors[0].count");
  d = good;
  d["accessors"][0]["count"] = std::uint64_t{1} << 60;  // checked before any allocation
  expect_error(d, "accessors[0].count");
  d = good;
  d["accessors"][0]["byteOffset"] = std::uint64_t{1} << 63;
  expect_error(d, "accessors[0].count");
  d = good;
  d["bufferViews"][0]["byteOffset"] = std::uint64_t{0xFFFFFFFFFFFFFFF0ull};
  expect_error(d, "bufferViews[0]");
  d = good;
  d["bufferViews"][0]["byteStride"] = 8;  // shorter than a VEC3 of floats
  expect_error(d, "accessors[0]");
  d = good;
  d["bufferViews"][0]["byteStride"] = 252;  // (8 − 1) × 252 + 12 bytes are past the view
  expect_error(d, "accessors[0].count");
  d = good;
  d["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAA*";
  expect_error(d, "buffers[0].uri");
  d = good;
  d["buffers"][0]["byteLength"] = 10000;
  expect_error(d, "buffers[0].byteLength");
  d = good;
  d["nodes"] = {{{"children", {1}}}, {{"children", {0}}, {"mesh", 0}}};  // a cycle as the scene
  expect_error(d, "not a root");
  d = good;
  d["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};  // two parents
  d["scenes"][0]["nodes"] = {0, 1};
  expect_error(d, "nodes[1].children[0]");
  d = good;
  d["nodes"] = {{{"children", {0}}}};
  expect_error(d, "nodes[0].children[0]");
  d = good;
  d["scenes"][0]["nodes"] = {0, 0};
  expect_error(d, "nodes[0]");
  d = good;
  d["nodes"][0]["mesh"] = 3;
  expect_error(d, "nodes[0].mesh");
  d = good;
  d["accessors"][1]["count"] = 35;
  expect_error(d, "TRIANGLES");
  d = good;
  d["accessors"][0]["componentType"] = 5123;  // quantized positions without the extension
  d["accessors"][0]["count"] = 1;
  expect_error(d, "KHR_mesh_quantization");
  d = good;
  d["asset"]["version"] = "1.0";
  expect_error(d, "asset.version");
  d = good;
  d["buffers"][0]["uri"] = "cube.bin";  // bytes in memory: no folder to read it from
  expect_error(d, "buffers[0].uri");
}

TEST(ReadGltf, BadJsonIsReportedAtItsLine) {
  const std::string text = "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [,]\n}";
  try {
    read_mesh_bytes({text.data(), text.size()}, "bad.gltf");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(e.where().has_line);
    EXPECT_EQ(e.where().line, 3u) << e.what();
  }
}

TEST(ReadGltf, NumberBeyondADoubleIsAnInputError) {
  // nlohmann::json refuses 1e999 with out_of_range, not parse_error: still the reader's error.
  const std::string text =
      "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"scale\": [1e999, 1, 1]}]}";
  try {
    read_mesh_bytes({text.data(), text.size()}, "overflow.gltf");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "overflow.gltf");
    EXPECT_NE(std::string(e.what()).find("invalid JSON"), std::string::npos) << e.what();
  }
}

std::string glb_of(const GltfJson& doc, const std::string& bin) {
  std::string json = doc.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string b = bin;
  b.append((4 - b.size() % 4) % 4, '\0');
  GltfBlob out;
  out.bytes = "glTF";
  out.put(std::uint32_t{2}).put(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + b.size()));
  out.put(static_cast<std::uint32_t>(json.size())).put(std::uint32_t{0x4E4F534A});
  out.bytes += json;
  out.put(static_cast<std::uint32_t>(b.size())).put(std::uint32_t{0x004E4942});
  out.bytes += b;
  return out.bytes;
}

TEST(ReadGltf, GlbContainerAndItsHostileChunkLengths) {
  GltfJson doc = cube_document(5121, {{{"mesh", 0}}}, {0});
  GltfBlob blob;
  for (const auto& c : cube_corners)
    for (float x : c) blob.put(x);
  for (const auto& t : cube_triangles)
    for (std::uint32_t i : t) blob.put(static_cast<std::uint8_t>(i));
  doc["buffers"][0].erase("uri");
  const std::string glb = glb_of(doc, blob.bytes);
  MeshSource src;
  const Mesh m = read_mesh_bytes({glb.data(), glb.size()}, "cube.glb", &src);
  EXPECT_EQ(src.format, MeshFormat::glb);
  EXPECT_DOUBLE_EQ(gltf_mass(m).volume, 1);

  std::string broken = glb;
  const std::uint32_t huge = 0x7FFFFFF0;
  std::memcpy(broken.data() + 12, &huge, 4);  // the JSON chunk's length past the end
  try {
    read_mesh_bytes({broken.data(), broken.size()}, "cube.glb");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().byte_offset, 12u) << e.what();
  }
  broken = glb;
  std::memcpy(broken.data() + 8, &huge, 4);  // the file's length
  EXPECT_THROW(read_mesh_bytes({broken.data(), broken.size()}, "cube.glb"), InputError);
  EXPECT_THROW(read_mesh_bytes({glb.data(), 17}, "cube.glb"), InputError);
}

TEST(ReadGltf, ExternalBufferBesideTheFileAndNotOutsideIt) {
  GltfBlob blob;
  for (const auto& c : cube_corners)
    for (float x : c) blob.put(x);
  for (const auto& t : cube_triangles)
    for (std::uint32_t i : t) blob.put(i);
  const test::TempFile bin(".bin", blob.bytes);
  const std::string base = bin.path().substr(bin.path().find_last_of('/') + 1);
  GltfJson doc = cube_document(5125, {{{"mesh", 0}}}, {0});
  doc["buffers"][0]["uri"] = base;
  const test::TempFile gltf(".gltf", doc.dump());
  EXPECT_DOUBLE_EQ(gltf_mass(read_mesh(gltf.path())).volume, 1);
  EXPECT_DOUBLE_EQ(analyze_file(gltf.path()).mass.volume, 1);
  for (const std::string& bad : std::vector<std::string>{"../" + base, "/etc/passwd",
                                                         "sub/../../" + base, "file:///x.bin"}) {
    doc["buffers"][0]["uri"] = bad;
    const test::TempFile escaping(".gltf", doc.dump());
    try {
      read_mesh(escaping.path());
      ADD_FAILURE() << bad << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("buffers[0].uri"), std::string::npos) << e.what();
    }
  }
}

// Float32-representable coordinates (dyadic fractions) survive glTF's float32 storage exactly:
// the mesh read back has the same vertices and the fans of its faces, so the same mass properties
// bit for bit.
TEST(WriteGltf, RoundTripIsExactForFloat32Coordinates) {
  const Mesh m = test::box_mesh(2.5, 1.25, 0.75);  // quads: written as fans
  const Mesh fanned = test::triangulated(m);
  const MassProperties want = gltf_mass(fanned);
  for (MeshFormat format : {MeshFormat::gltf, MeshFormat::glb}) {
    const std::string bytes = write_mesh_bytes(m, format);
    MeshSource src;
    const Mesh back = read_mesh_bytes({bytes.data(), bytes.size()}, "w", &src);
    EXPECT_EQ(src.format, format);
    EXPECT_EQ(back.vertices, m.vertices);
    EXPECT_EQ(back.corners, fanned.corners);
    const MassProperties got = gltf_mass(back);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got.volume), std::bit_cast<std::uint64_t>(want.volume));
    EXPECT_DOUBLE_EQ(got.volume, 2.5 * 1.25 * 0.75);
    EXPECT_EQ(got.center_of_mass, want.center_of_mass);
  }
  // The POSITION accessor's min and max, which the specification requires.
  const std::string text = write_mesh_bytes(m, MeshFormat::gltf);
  const GltfJson doc = GltfJson::parse(text);
  EXPECT_EQ(doc["accessors"][0]["min"], GltfJson({0.0, 0.0, 0.0}));
  EXPECT_EQ(doc["accessors"][0]["max"], GltfJson({2.5, 1.25, 0.75}));
  EXPECT_EQ(doc["accessors"][1]["componentType"], 5125);
}

}  // namespace
}  // namespace pgamesh
