// The topology pass on triangle meshes (welded_topology.hpp) on meshes full of defects — random
// triangles on a 3×3×3 grid (collapsed, duplicated, non-manifold, open, inconsistent), the defect
// meshes of the other topology tests and the shared real meshes: against the brute-force reference
// (support/reference_topology.hpp), and field by field, bit for bit, against the same pass walking
// the triangles as polygons (face_layout.hpp: the triangle layout's arithmetic and fused face sums
// against the polygon layout's lookups and tally_face). Then the fused mass and topology pass, and
// the weld of binary STL records against the weld of the read mesh (classes, numbering,
// representatives, −0, NaN, released pages).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>

#include "mesh/topology/welded_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/geometry/reference_point.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"
#include "support/golden.hpp"
#include "support/read_helpers.hpp"
#include "support/reference_topology.hpp"
#include "support/same_topology.hpp"
#include "support/stl_bytes.hpp"
#include "support/temp_file.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::expect_matches_reference;
using test::expect_same_report;
using test::same_bits;

// The report of triangle mesh m, checked against the reference and against the polygon layout;
// returned for further checks.
TopologyReport expect_triangle_pass(const Mesh& m, const TopologyOptions& options = {}) {
  const TopologyReport triangles = analyze_topology(m, options);
  expect_matches_reference(triangles, m, options);
  const TopologyReport polygons =
      analyze_welded_mesh(weld(m, options.weld_tolerance), reference_point(m), options);
  expect_same_report(triangles, polygons);
  return triangles;
}

// `faces` random triangles on the 3×3×3 grid, some vertices listed twice: every defect at once.
Mesh grid_soup(std::uint32_t seed, std::size_t faces) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, 2), pick(0, 26 + 8);
  Mesh m;
  for (int i = 0; i < 27; ++i)
    m.vertices.push_back({double(i % 3), double(i / 3 % 3), double(i / 9) + 0.25 * (i % 2)});
  for (int i = 0; i < 8; ++i) m.vertices.push_back(m.vertices[static_cast<std::size_t>(3 * i)]);
  for (std::size_t f = 0; f < faces; ++f)
    m.add_face({static_cast<std::uint32_t>(pick(rng)), static_cast<std::uint32_t>(pick(rng)),
                static_cast<std::uint32_t>(pick(rng))});
  return m;
}

TEST(TopologyTriangles, RandomGridSoups) {
  TopologyOptions small_lists;
  small_lists.list_cap = 5;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh m = grid_soup(seed, 4 + seed % 40);
    const TopologyReport r = expect_triangle_pass(m);
    expect_triangle_pass(m, small_lists);
    if (seed == 40) {  // the soup does exercise the defects
      EXPECT_GT(r.nonmanifold_edges + r.boundary_edges + r.inconsistent_edges, 0u);
    }
  }
}

TEST(TopologyTriangles, SoupsCoverEveryDefect) {
  std::size_t collapsed = 0, duplicated = 0, nonmanifold = 0, open_chains = 0, inconsistent = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    const TopologyReport r = analyze_topology(grid_soup(seed, 4 + seed % 40));
    collapsed += r.collapsed_faces;
    duplicated += r.duplicated_faces;
    nonmanifold += r.nonmanifold_edges;
    inconsistent += r.inconsistent_edges;
    for (const BoundaryLoop& loop : r.boundary_loops) open_chains += loop.closed ? 0 : 1;
  }
  EXPECT_GT(collapsed, 0u);
  EXPECT_GT(duplicated, 0u);
  EXPECT_GT(nonmanifold, 0u);
  EXPECT_GT(inconsistent, 0u);
  EXPECT_GT(open_chains, 0u);
}

TEST(TopologyTriangles, DefectMeshes) {
  using namespace test;
  const Mesh cube = unit_cube();
  expect_triangle_pass(cube);
  expect_triangle_pass(unshared(cube));
  expect_triangle_pass(without_faces(cube, {1, 5}));
  expect_triangle_pass(with_flipped(cube, {0, 7}));
  expect_triangle_pass(merged(cube, translated(cube, {3, 0, 0})));
  expect_triangle_pass(merged(cube, translated(cube, {1, 1, 0})));
  expect_triangle_pass(translated(icosphere(3, 2.0), {1e6, -1e6, 1e6}));
  Mesh weld_me = unshared(icosphere(2, 1.0));
  for (std::size_t i = 0; i < weld_me.vertices.size(); i += 3) weld_me.vertices[i].x += 1e-9;
  TopologyOptions tolerant;
  tolerant.weld_tolerance = 1e-6;
  const TopologyReport r = expect_triangle_pass(weld_me, tolerant);
  EXPECT_TRUE(r.closed);
  EXPECT_GT(r.weld_max_moved, 0.0);
}

TEST(TopologyTriangles, LargeMeshesTakeTheTwoThreadPath) {
  // 81 920 triangles per sphere: the face tally runs on its own thread. Two spheres (one with
  // holes and flipped faces) make two components, whose sums take the second face pass. The search
  // for intersecting faces, which has its own tests, runs on the first sphere only.
  using namespace test;
  const Mesh sphere = icosphere(6, 1.0);
  const TopologyReport one = expect_triangle_pass(unshared(sphere));
  EXPECT_TRUE(one.self_intersections_checked);
  EXPECT_EQ(one.self_intersecting_pairs, 0u);
  TopologyOptions edges_only;
  edges_only.self_intersections = false;
  EXPECT_TRUE(one.closed);
  EXPECT_EQ(one.components, 1u);
  Mesh damaged = with_flipped(without_faces(sphere, {10, 11, 500, 70000}), {3, 4000, 9000});
  const TopologyReport two =
      expect_triangle_pass(merged(damaged, translated(sphere, {3, 0, 0})), edges_only);
  EXPECT_EQ(two.components, 2u);
  EXPECT_GT(two.boundary_edges, 0u);
  EXPECT_GT(two.inconsistent_edges, 0u);
}

TEST(TopologyTriangles, LargeSoupsTakeTheParallelEdgePass) {
  // 20 000 random triangles on 35 vertices: two threads count, fill and group the half-edges
  // (every vertex a large fan, the split between the threads inside the vertex range) and share
  // one union–find; the report must be the sequential reference's. Without the search for
  // intersecting faces: most pairs of these triangles meet (some 10^8).
  TopologyOptions edges_only;
  edges_only.self_intersections = false;
  for (std::uint32_t seed = 1; seed <= 2; ++seed) {
    SCOPED_TRACE(seed);
    const TopologyReport r = expect_triangle_pass(grid_soup(seed, 20000), edges_only);
    EXPECT_GT(r.nonmanifold_edges, 0u);
    EXPECT_GT(r.duplicated_faces, 0u);
    EXPECT_GT(r.collapsed_faces, 0u);
  }
}

// The one-pass mass properties and topology against mass_properties and analyze_welded_triangles
// called apart: the same bits, on soups (one thread, one chunk) and on a large damaged mesh far
// from the origin (the face pass on its own thread, many chunks of chunked_sums).
void expect_one_pass_agrees(const Mesh& m, bool self_intersections = true) {
  const WeldedTriangles w = weld_triangles(m);
  const Vec3d ref = bounding_box(w.positions).centre();
  MassOptions mass_options;
  mass_options.density = 2.5;
  mass_options.threads = 2;
  TopologyOptions small_lists;
  small_lists.list_cap = 3;
  small_lists.self_intersections = self_intersections;
  const WeldedTriangleProps both =
      analyze_welded_triangles(w, ref, mass_options, small_lists, true);
  expect_same_report(both.topology, analyze_welded_triangles(w, ref, small_lists));
  const MassProperties apart = mass_properties(w, ref, mass_options, true);
  const MassProperties& one = both.mass;
  test::expect_same_mass(one, apart);
}

TEST(TopologyTriangles, MassAndTopologyInOnePassMatchTheSeparatePasses) {
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    expect_one_pass_agrees(grid_soup(seed, 4 + 3 * seed));
  }
  using namespace test;
  const Mesh sphere = icosphere(6, 1.0);
  const Mesh damaged = with_flipped(without_faces(sphere, {10, 500}), {3, 9000});
  expect_one_pass_agrees(translated(merged(damaged, translated(sphere, {3, 0, 0})), {1e5, 0, -1e5}),
                         false);
}

TEST(TopologyTriangles, SharedRealMeshes) {
  if (test::shared_meshes_dir().empty())
    GTEST_SKIP() << "../shared/meshes not found (" PGAMESH_SHARED_MESHES_DIR "): skipped";
  std::size_t compared = 0;
  for (const char* name : {"npm/bunny.stl", "npm/teapot.obj", "stl-models/gearwheel.bin.stl",
                           "stl-models/tetrahedronIrregular.bin.stl",
                           "openscad-testing-data/issue1580-back-to-back.stl"}) {
    const std::string path = test::shared_meshes_dir() + "/" + name;
    if (!std::filesystem::exists(path)) continue;
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(path);
    if (!all_triangles(m)) continue;
    const TopologyReport r = expect_triangle_pass(m);
    // A binary STL welded from its records gives the same report.
    const MappedFile file = MappedFile::open(path);
    if (const auto view = binary_stl_view(file.bytes(), path)) {
      const WeldedTriangles w = weld_binary_stl(*view, path);
      expect_same_report(analyze_welded_triangles(w, r.reference_point), r);
    }
    ++compared;
  }
  EXPECT_GE(compared, 2u);  // the bundled bunny and teapot at least
}

// The weld of STL records against weld_triangles of the read mesh: same everything.
void expect_same_weld(const WeldedTriangles& a, const WeldedTriangles& b) {
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.input_vertices, b.input_vertices);
  EXPECT_EQ(a.merged, b.merged);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (std::uint32_t w = 0; w < a.positions.size(); ++w)
    ASSERT_EQ(a.input_vertex(w), b.input_vertex(w)) << "welded vertex " << w;
  for (std::size_t i = 0; i < a.positions.size(); ++i)
    EXPECT_SAME_VEC(a.positions[i], b.positions[i]);
}

TEST(TopologyTriangles, StlRecordWeldMatchesTheReadMesh) {
  Mesh m = test::merged(icosphere(3, 1.5), test::without_faces(test::unit_cube(), {2}));
  m.vertices[0] = {-0.0, 0.0, -0.0};  // a signed zero as the representative
  m.vertices[5] = {0.0, -0.0, 0.0};   // welds with it
  const std::vector<char> bytes = test::binary_stl_bytes(m);
  const auto view = binary_stl_view(bytes, "soup.stl");
  ASSERT_TRUE(view.has_value());
  MeshSource source;
  const Mesh read = read_mesh_bytes(bytes, "soup.stl", &source);
  const WeldedTriangles from_records = weld_binary_stl(*view, "soup.stl");
  expect_same_weld(from_records, weld_triangles(read));
  EXPECT_EQ(from_records.input_vertices, 3 * read.face_count());
  EXPECT_LT(from_records.positions.size(), read.vertices.size() / 4);

  const Vec3d ref = bounding_box(from_records.positions).centre();
  expect_same_report(analyze_welded_triangles(from_records, ref), analyze_topology(read));
  const MassProperties a = mass_properties(from_records, ref, {}, true);
  const MassProperties b = mass_properties(read, {}, &source);
  test::expect_same_mass(a, b);
}

TEST(TopologyTriangles, StlNonFiniteCoordinateIsNamedLikeTheReader) {
  std::vector<std::array<float, 9>> tris = {{0, 0, 0, 1, 0, 0, 0, 1, 0},
                                            {0, 0, 0, 1, 0, 0, 0, 0, NAN}};
  const std::string bytes = test::binary_stl(tris, 2);
  const auto view = binary_stl_view(bytes, "nan.stl");
  ASSERT_TRUE(view.has_value());
  try {
    weld_binary_stl(*view, "nan.stl");
    FAIL() << "no error for a NaN coordinate";
  } catch (const InputError& e) {
    EXPECT_BYTE_ERROR(e, 84u + 50u + 12u + 24u + 8u, "non-finite");
  }
}

TEST(TopologyTriangles, StlWeldReleasingMappedPagesGivesTheSameResult) {
  // 327 680 triangles = 16 MB of records: several release steps.
  const Mesh m = icosphere(7, 1.0);
  const std::vector<char> bytes = test::binary_stl_bytes(m);
  const test::TempFile file(".stl", {bytes.data(), bytes.size()});
  const std::string& path = file.path();
  const auto memory = binary_stl_view(bytes, path);
  ASSERT_TRUE(memory.has_value());
  const WeldedTriangles kept = weld_binary_stl(*memory, path);
  // Two threads weld the two halves; the result is the sequential weld's.
  expect_same_weld(kept, weld_triangles(read_mesh_bytes(bytes, path)));
  {
    const MappedFile file = MappedFile::open(path);
    const auto view = binary_stl_view(file.bytes(), path);
    ASSERT_TRUE(view.has_value());
    const WeldedTriangles released = weld_binary_stl(*view, path, true);
    expect_same_weld(released, kept);
    // The released pages come back from the file when read again.
    EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), file.bytes().begin()));
  }
  TopologyOptions edges_only;
  edges_only.self_intersections = false;
  const TopologyReport r =
      analyze_welded_triangles(kept, bounding_box(kept.positions).centre(), edges_only);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.vertices, m.vertices.size());
  EXPECT_EQ(r.edges, 3 * m.face_count() / 2);
  EXPECT_EQ(r.components, 1u);
}

TEST(TopologyTriangles, StlWeldReadingTheFileGivesTheSameResult) {
  // 81 920 triangles minus 3 (an open mesh): 20 blocks of records, the last one short, and a count
  // that is no multiple of the four lanes.
  Mesh m = icosphere(6, 1.0);
  m.corners.resize(m.corners.size() - 9);            // three triangles fewer: a count that is no
  m.face_offsets.resize(m.face_offsets.size() - 3);  // multiple of the four lanes
  const std::vector<char> bytes = test::binary_stl_bytes(m);
  const test::TempFile file(".stl", {bytes.data(), bytes.size()});
  const auto memory = binary_stl_view(bytes, file.path());
  ASSERT_TRUE(memory.has_value());
  const WeldedTriangles kept = weld_binary_stl(*memory, file.path());
  const MappedFile mapped = MappedFile::open(file.path());
  ASSERT_GE(mapped.descriptor(), 0);
  auto view = binary_stl_view(mapped.bytes(), file.path());
  ASSERT_TRUE(view.has_value());
  view->file = mapped.descriptor();
  for (bool release : {false, true})
    expect_same_weld(weld_binary_stl(*view, file.path(), release), kept);
  EXPECT_EQ(kept.triangle_count(), m.face_count());
}

}  // namespace
}  // namespace pgamesh
