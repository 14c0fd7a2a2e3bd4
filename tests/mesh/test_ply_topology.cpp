// The PLY topology pass that re-reads the faces from the file (ply_topology.hpp) against the Mesh
// path (read_mesh_bytes, mass_properties, analyze_topology): every field, doubles bit for bit, on
// meshes with each defect, real meshes, one pass and many, little- and big-endian; and the files
// it declines, whose errors the CLI then reports as before.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mesh/topology/ply_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/cli_run.hpp"
#include "support/file_bytes.hpp"
#include "support/read_helpers.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::CliRun;
using test::expect_same_mass;
using test::expect_same_report;
using test::run_cli;
using test::TempFile;

std::string ply_bytes(const Mesh& m, MeshFormat format = MeshFormat::ply_binary_le,
                      bool single_precision = true) {
  WriteOptions o;
  o.single_precision = single_precision;
  return write_mesh_bytes(m, format, o);
}

TopologyOptions every_location(bool self_intersections = true) {
  TopologyOptions t;
  t.list_cap = 1000;
  t.self_intersections = self_intersections;
  return t;
}

std::optional<WeldedTriangleProps> new_path(const std::string& bytes, std::size_t budget = 0,
                                            MeshSource* source_out = nullptr,
                                            const TopologyOptions& t = every_location()) {
  MeshSource source;
  auto props = ply_triangle_props({bytes.data(), bytes.size()}, "mem.ply", source, {}, t, false,
                                  PlyPassBudget{budget});
  if (source_out) *source_out = source;
  return props;
}

// The new pass gives what the Mesh path gives, with the default budget and with budgets that
// force several passes (1 half-edge: one range per vertex).
void expect_same_as_mesh_path(const std::string& bytes,
                              std::initializer_list<std::size_t> budgets = {0, 1, 5, 64}) {
  MeshSource careful_source;
  const Mesh mesh = read_mesh_bytes({bytes.data(), bytes.size()}, "mem.ply", &careful_source);
  const MassProperties mass = mass_properties(mesh, {}, &careful_source);
  // The search for intersecting faces runs after the passes, whatever the budget: it is compared
  // once, at the first budget.
  const TopologyReport report = analyze_topology(mesh, every_location());
  const TopologyReport edges_report = analyze_topology(mesh, every_location(false));
  bool first = true;
  for (std::size_t budget : budgets) {
    SCOPED_TRACE("budget " + std::to_string(budget));
    MeshSource source;
    const auto props = new_path(bytes, budget, &source, every_location(first));
    ASSERT_TRUE(props.has_value());
    expect_same_mass(props->mass, mass);
    expect_same_report(props->topology, first ? report : edges_report);
    first = false;
    EXPECT_EQ(source.format, careful_source.format);
    EXPECT_EQ(source.single_precision, careful_source.single_precision);
    EXPECT_EQ(source.warnings, careful_source.warnings);
  }
}

// A triangulated UV sphere (uv_sphere has quads).
Mesh sphere(double r, int stacks, int slices) {
  return test::triangulated(test::uv_sphere(r, stacks, slices));
}

// Little- and big-endian, float32 and float64 coordinates.
void expect_same_both_endians(const Mesh& m) {
  for (bool single : {true, false}) {
    SCOPED_TRACE(single ? "float32" : "float64");
    {
      SCOPED_TRACE("little-endian");
      expect_same_as_mesh_path(ply_bytes(m, MeshFormat::ply_binary_le, single));
    }
    {
      SCOPED_TRACE("big-endian");
      expect_same_as_mesh_path(ply_bytes(m, MeshFormat::ply_binary_be, single));
    }
  }
}

TEST(PlyTopology, ClosedCubeAndSphere) {
  expect_same_both_endians(test::unit_cube());
  expect_same_both_endians(test::translated(sphere(2.5, 12, 24), {1e3, -7, 0.25}));
}

TEST(PlyTopology, LargerOpenMeshInManyRanges) {
  // 19 600 + 9 440 triangles with holes, flipped faces and a second component; ranges of 2 000
  // half-edges (about 45 reads of the faces) and the default.
  Mesh m = test::with_flipped(test::without_faces(sphere(1, 100, 100), {5, 700, 701, 9000}),
                              {12, 13000});
  m = test::merged(m, test::translated(sphere(0.25, 60, 80), {3, 0, 0}));
  expect_same_as_mesh_path(ply_bytes(m), {0, 2000});
}

TEST(PlyTopology, ClosedMeshFindsWhatTheMeshPathFinds) {
  // Independent of the comparison: a closed cube's own figures.
  const std::string bytes = ply_bytes(test::unit_cube());
  const auto props = new_path(bytes, 1);
  ASSERT_TRUE(props.has_value());
  EXPECT_TRUE(props->topology.closed);
  EXPECT_EQ(props->topology.edges, 18u);
  EXPECT_EQ(props->topology.components, 1u);
  EXPECT_EQ(props->mass.volume, 1.0);
  EXPECT_EQ(props->mass.area, 6.0);
}

TEST(PlyTopology, OpenMesh) {
  expect_same_both_endians(test::without_faces(sphere(1, 8, 16), {3, 4, 40}));
}

TEST(PlyTopology, InconsistentOrientation) {
  expect_same_both_endians(test::with_flipped(test::unit_cube(), {2, 7}));
}

TEST(PlyTopology, NonManifoldEdge) {
  Mesh m = test::unit_cube();
  m.vertices.push_back({0.5, 0.5, 3});
  m.add_face({0, 2, 8});  // a third face on the edge (0, 2)
  expect_same_both_endians(m);
}

TEST(PlyTopology, DuplicatedAndCollapsedFaces) {
  Mesh m = test::unit_cube();
  m.add_face({0, 2, 3});  // a copy of face 0
  m.add_face({3, 0, 2});  // the same vertices, rotated
  m.add_face({1, 1, 5});  // collapsed: one vertex twice
  m.vertices.push_back(m.vertices[4]);
  m.add_face({4, 8, 6});  // collapsed once welded: vertex 8 = vertex 4
  m.add_face({0, 1, 2});  // zero area? no: a real triangle inside the cube
  expect_same_both_endians(m);
}

TEST(PlyTopology, CoincidentVerticesAndComponents) {
  // Unshared vertices (every face its own three) weld; two cubes and a sphere are three components.
  const Mesh m = test::merged(test::merged(test::unshared(test::unit_cube()),
                                           test::translated(test::unit_cube(), {3, 0, 0})),
                              test::flipped(test::translated(sphere(0.5, 6, 10), {0, 4, 0})));
  expect_same_both_endians(m);
}

TEST(PlyTopology, UnreferencedVerticesAndDegenerateFaces) {
  Mesh m = test::unit_cube();
  m.vertices.push_back({9, 9, 9});        // unreferenced
  m.vertices.push_back({0.5, 0, 0});      // on the edge (0, 1)
  m.add_face({0, 9, 1});                  // zero area, not collapsed
  m.vertices.push_back({0.5, 1e-12, 0});  // nearly on it
  m.add_face({0, 1, 10});                 // small area
  expect_same_both_endians(m);
}

TEST(PlyTopology, RealMeshesAsBinaryPly) {
  const std::string dir = PGAMESH_SHARED_MESHES_DIR;
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not found: skipped";
  int compared = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || entry.file_size() > (std::size_t{1} << 20) ||
        (ext != ".stl" && ext != ".obj" && ext != ".off" && ext != ".ply"))
      continue;
    Mesh m;
    try {
      m = read_mesh(entry.path().string());
    } catch (const std::exception&) {
      continue;  // the folder holds files that are meant to fail
    }
    if (!all_triangles(m)) m = test::triangulated(m);
    SCOPED_TRACE(entry.path().string());
    expect_same_as_mesh_path(ply_bytes(m));
    expect_same_as_mesh_path(ply_bytes(m, MeshFormat::ply_binary_le, false), {0, 5});
    ++compared;
  }
  EXPECT_GT(compared, 5);
}

TEST(PlyTopology, RealPlyFilesAsGiven) {
  // A binary float32 triangle mesh is taken and equal to the Mesh path; an ASCII one declined.
  const std::string binary = test::shared_mesh("assimp-testmodels/cube_binary.ply");
  const std::string ascii = test::shared_mesh("octave-matgeom/dodecahedron.ply");
  if (binary.empty() || ascii.empty()) GTEST_SKIP() << "../shared/meshes not found: skipped";
  const std::string bytes = test::file_bytes(binary);
  EXPECT_TRUE(new_path(bytes).has_value());
  expect_same_as_mesh_path(bytes);
  EXPECT_FALSE(new_path(test::file_bytes(ascii)).has_value());
}

// A binary little-endian PLY with a header of our own: `vertex` and `face` lines and raw data.
std::string ply_with_header(const std::string& elements, const std::string& data) {
  return "ply\nformat binary_little_endian 1.0\n" + elements + "end_header\n" + data;
}

template <class T>
void put(std::string& s, T v) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  s.append(b, sizeof v);
}

// Three vertices and one face (i, j, k), float coordinates, uchar count, int indices.
std::string one_triangle(std::int32_t i, std::int32_t j, std::int32_t k, std::uint8_t count = 3) {
  std::string d;
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(d, x);
  put(d, count);
  for (std::int32_t v : {i, j, k}) put(d, v);
  return d;
}

const char* const vertex_then_face =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";

TEST(PlyTopology, TakesAPlainTriangle) {
  const std::string bytes = ply_with_header(vertex_then_face, one_triangle(0, 1, 2));
  const auto props = new_path(bytes);
  ASSERT_TRUE(props.has_value());
  EXPECT_EQ(props->topology.boundary_edges, 3u);
  EXPECT_EQ(props->mass.area, 0.5);
  expect_same_as_mesh_path(bytes);
}

TEST(PlyTopology, Declines) {
  // Each of these goes to the careful reader.
  EXPECT_FALSE(new_path(ply_with_header(vertex_then_face, one_triangle(0, 1, 3))));     // index
  EXPECT_FALSE(new_path(ply_with_header(vertex_then_face, one_triangle(0, 1, -1))));    // index
  EXPECT_FALSE(new_path(ply_with_header(vertex_then_face, one_triangle(0, 1, 2, 4))));  // quad
  EXPECT_FALSE(new_path(ply_with_header(vertex_then_face, one_triangle(0, 1, 2).substr(0, 40))));
  EXPECT_FALSE(new_path(ply_bytes(test::unit_cube_quads())));
  EXPECT_FALSE(new_path(ply_bytes(test::unit_cube(), MeshFormat::ply_ascii)));
  // x, y, z of different types.
  std::string mixed;
  for (int v = 0; v < 3; ++v) {
    put(mixed, float(v == 1));
    put(mixed, double(v == 2));
    put(mixed, 0.f);
  }
  put(mixed, std::uint8_t{3});
  for (std::int32_t v : {0, 1, 2}) put(mixed, v);
  EXPECT_FALSE(new_path(
      ply_with_header("element vertex 3\nproperty float x\nproperty double y\nproperty float z\n"
                      "element face 1\nproperty list uchar int vertex_indices\n",
                      mixed)));
  // Faces before vertices.
  std::string faces_first;
  put(faces_first, std::uint8_t{3});
  for (std::int32_t v : {0, 1, 2}) put(faces_first, v);
  for (float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(faces_first, x);
  EXPECT_FALSE(new_path(
      ply_with_header("element face 1\nproperty list uchar int vertex_indices\n"
                      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n",
                      faces_first)));
  // −0 and +0 weld, but the mass sums would see the input's bits: the Mesh path keeps them.
  Mesh zeros = test::unit_cube();
  zeros.vertices.push_back({-0.0, 0, 0});
  zeros.add_face({8, 2, 3});
  EXPECT_FALSE(new_path(ply_bytes(zeros)));
  EXPECT_FALSE(new_path(ply_bytes(zeros, MeshFormat::ply_binary_le, false)));
  // A non-finite coordinate, float32 and float64: the careful reader names it.
  Mesh infinite = test::unit_cube();
  infinite.vertices[5].y = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(new_path(ply_bytes(infinite)));
  EXPECT_FALSE(new_path(ply_bytes(infinite, MeshFormat::ply_binary_le, false)));
  TopologyOptions tolerant;
  tolerant.weld_tolerance = 1e-3;
  MeshSource source;
  const std::string cube = ply_bytes(test::unit_cube());
  EXPECT_FALSE(ply_triangle_props({cube.data(), cube.size()}, "mem.ply", source, {}, tolerant));
}

// Runs `pgamesh props` on `bytes` written to a PLY file.
CliRun run_props(const std::string& bytes) {
  const TempFile ply(".ply", bytes);
  return run_cli("props \"" + ply.path() + "\"");
}

TEST(PlyTopology, CliReportsTheCarefulReadersErrors) {
  const CliRun index = run_props(ply_with_header(vertex_then_face, one_triangle(0, 1, 7)));
  EXPECT_NE(index.status, 0);
  EXPECT_NE(index.err.find("vertex index 7 of face 0 is out of range (3 vertices)"),
            std::string::npos)
      << index.err;
  const CliRun truncated =
      run_props(ply_with_header(vertex_then_face, one_triangle(0, 1, 2).substr(0, 40)));
  EXPECT_NE(truncated.status, 0);
  EXPECT_NE(truncated.err.find("list length 3 in face 0 runs past the end of the file"),
            std::string::npos)
      << truncated.err;
  const CliRun good = run_props(ply_with_header(vertex_then_face, one_triangle(0, 1, 2)));
  EXPECT_EQ(good.status, 0) << good.err;
  EXPECT_NE(good.out.find("open"), std::string::npos) << good.out;
}

}  // namespace
}  // namespace pgamesh
