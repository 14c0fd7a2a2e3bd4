// analyze_topology(Mesh&&), which welds the mesh in its own arrays, against
// analyze_topology(const Mesh&) field by field — on closed, open, unwelded, inconsistent,
// duplicated, polygon and tolerance-welded meshes and on the real meshes of ../shared/meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"
#include "support/read_helpers.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::expect_same_report;

// Doubles compared bit for bit: the two calls must run the same arithmetic.
void expect_bits(double a, double b, const char* what) {
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << what << ": " << a << " vs " << b;
}
void expect_bits(Vec3d a, Vec3d b, const char* what) {
  for (int k = 0; k < 3; ++k) expect_bits(a[k], b[k], what);
}

// Both calls on `mesh`; returns the report of the moved one.
TopologyReport expect_same_topology(const Mesh& mesh, const TopologyOptions& options = {}) {
  const TopologyReport kept = analyze_topology(mesh, options);
  Mesh copy = mesh;
  const TopologyReport moved = analyze_topology(std::move(copy), options);
  expect_same_report(moved, kept);
  return moved;
}

// weld_triangles on a moved mesh (corners renumbered and positions compacted in place) against
// the copying weld.
void expect_same_weld(const Mesh& mesh, double tolerance) {
  const WeldedTriangles kept = weld_triangles(mesh, tolerance);
  Mesh copy = mesh;
  const WeldedTriangles moved = weld_triangles(std::move(copy), tolerance);
  EXPECT_TRUE(copy.vertices.empty() && copy.corners.empty());
  ASSERT_EQ(moved.positions.size(), kept.positions.size());
  EXPECT_EQ(std::memcmp(moved.positions.data(), kept.positions.data(),
                        kept.positions.size() * sizeof(Vec3d)),
            0);
  EXPECT_EQ(moved.corners, kept.corners);
  EXPECT_EQ(moved.representative, kept.representative);
  EXPECT_EQ(moved.input_vertices, kept.input_vertices);
  EXPECT_EQ(moved.merged, kept.merged);
  expect_bits(moved.max_moved, kept.max_moved, "max_moved");
  expect_bits(moved.tolerance, kept.tolerance, "tolerance");
}

// weld on a moved mesh of any faces (vertices compacted and corners renumbered in its arrays)
// against the copying weld.
void expect_same_mesh_weld(const Mesh& mesh, double tolerance) {
  const WeldResult kept = weld(mesh, tolerance);
  Mesh copy = mesh;
  const WeldResult moved = weld(std::move(copy), tolerance);
  EXPECT_TRUE(copy.vertices.empty() && copy.corners.empty());
  ASSERT_EQ(moved.mesh.vertices.size(), kept.mesh.vertices.size());
  if (!kept.mesh.vertices.empty()) {  // memcmp of an empty vector's null data() is undefined
    EXPECT_EQ(std::memcmp(moved.mesh.vertices.data(), kept.mesh.vertices.data(),
                          kept.mesh.vertices.size() * sizeof(Vec3d)),
              0);
  }
  EXPECT_EQ(moved.mesh.corners, kept.mesh.corners);
  EXPECT_EQ(moved.mesh.face_offsets, kept.mesh.face_offsets);
  EXPECT_EQ(moved.map.to_welded, kept.map.to_welded);
  EXPECT_EQ(moved.map.representative, kept.map.representative);
  EXPECT_EQ(moved.map.merged, kept.map.merged);
  expect_bits(moved.map.max_moved, kept.map.max_moved, "max_moved");
  expect_bits(moved.map.tolerance, kept.map.tolerance, "tolerance");
}

TEST(TopologyMovedMesh, WeldMapCompactingEqualsWeldMap) {
  std::vector<Vec3d> v = test::unshared(test::triangulated(test::uv_sphere(1, 8, 12))).vertices;
  v.push_back({7, 7, 7});  // unreferenced, its own class
  v.push_back({-0.0, 0.0, 5});
  v.push_back({0.0, -0.0, 5});  // welds with the one before; the first keeps its −0
  for (double tolerance : {0.0, 1e-9}) {
    const WeldMap expected = weld_map(v, tolerance);
    std::vector<Vec3d> compacted = v;
    const WeldMap got = weld_map_compacting(compacted, tolerance);
    EXPECT_EQ(got.to_welded, expected.to_welded);
    EXPECT_EQ(got.representative, expected.representative);
    EXPECT_EQ(got.merged, expected.merged);
    expect_bits(got.max_moved, expected.max_moved, "max_moved");
    ASSERT_EQ(compacted.size(), expected.welded_count());
    for (std::size_t id = 0; id < compacted.size(); ++id)
      expect_bits(compacted[id], v[expected.representative[id]], "welded position");
    EXPECT_TRUE(std::signbit(compacted.back().x));
  }
  std::vector<Vec3d> none;
  EXPECT_EQ(weld_map_compacting(none).welded_count(), 0u);
  EXPECT_THROW(weld_map_compacting(none, -1), std::invalid_argument);
}

TEST(TopologyMovedMesh, WeldInPlace) {
  const Mesh sphere = test::triangulated(test::uv_sphere(2, 20, 30));
  expect_same_weld(sphere, 0);                  // nothing merges: positions kept as they are
  expect_same_weld(test::unshared(sphere), 0);  // six corners a vertex: compacted
  Mesh near = test::unshared(sphere);
  for (std::size_t i = 0; i < near.vertices.size(); i += 3) near.vertices[i].y -= 1e-10;
  expect_same_weld(near, 1e-8);
  // −0 and +0 weld; the representative keeps its own sign.
  Mesh zeros = test::unshared(test::unit_cube());
  for (auto& v : zeros.vertices)
    if (v.x == 0) v.x = -0.0;
  zeros.vertices[0].x = 0.0;
  expect_same_weld(zeros, 0);
  Mesh quads = test::unit_cube_quads();
  EXPECT_THROW(weld_triangles(std::move(quads)), std::invalid_argument);
  Mesh bad = test::unit_cube();
  bad.corners[4] = 8;
  EXPECT_THROW(weld_triangles(std::move(bad)), std::out_of_range);
}

TEST(TopologyMovedMesh, WeldOfAnyFacesInPlace) {
  const Mesh sphere = test::uv_sphere(2, 20, 30);  // quads, and triangles at the poles
  expect_same_mesh_weld(sphere, 0);
  expect_same_mesh_weld(test::unshared(sphere), 0);
  Mesh near = test::unshared(sphere);
  for (std::size_t i = 0; i < near.vertices.size(); i += 3) near.vertices[i].y -= 1e-10;
  expect_same_mesh_weld(near, 1e-8);
  expect_same_mesh_weld(Mesh{}, 0);
  Mesh bad = test::unit_cube_quads();
  bad.corners[4] = 8;
  EXPECT_THROW(weld(std::move(bad)), std::out_of_range);
}

// The lowest index of a vertex at p's coordinates (the weld's representative, by brute force).
std::uint32_t lowest_vertex_at(const Mesh& m, Vec3d p) {
  for (std::uint32_t i = 0; i < m.vertices.size(); ++i)
    if (m.vertices[i] == p) return i;
  ADD_FAILURE() << "no vertex at the edge's end";
  return 0;
}

TEST(TopologyMovedMesh, RepresentativesKeptOnlyWhenVerticesMerge) {
  const Mesh cube = test::unit_cube();
  for (const Mesh& m : {cube, test::unshared(cube)}) {
    const bool merges = m.vertices.size() > 8;
    const WeldedTriangles kept = weld_triangles(m);
    const WeldedTriangles moved = weld_triangles(Mesh(m));
    EXPECT_EQ(kept.representative.size(), merges ? 8u : 0u);
    EXPECT_EQ(moved.representative.size(), merges ? 8u : 0u);
    for (std::uint32_t w = 0; w < 8; ++w) {
      EXPECT_EQ(kept.input_vertex(w), lowest_vertex_at(m, kept.positions[w]));
      EXPECT_EQ(moved.input_vertex(w), kept.input_vertex(w));
    }
    // The boundary edges name input vertices either way: those of the removed face z = 1 (2).
    const Mesh open = test::without_faces(m, {2});
    const TopologyReport r = expect_same_topology(open);
    ASSERT_EQ(r.boundary_edge_list.size(), 3u);
    for (const EdgeLocation& e : r.boundary_edge_list) {
      EXPECT_EQ(e.vertex0, lowest_vertex_at(open, e.p0));
      EXPECT_EQ(e.vertex1, lowest_vertex_at(open, e.p1));
      EXPECT_EQ(e.p0.z, 1.0);
      EXPECT_EQ(e.p1.z, 1.0);
    }
  }
}

TEST(TopologyMovedMesh, TrianglesClosedOpenUnweldedFlippedDuplicated) {
  const Mesh cube = test::unit_cube();
  EXPECT_TRUE(expect_same_topology(cube).closed);
  EXPECT_EQ(expect_same_topology(test::without_faces(cube, {2, 7})).boundary_edges, 6u);
  EXPECT_EQ(expect_same_topology(test::unshared(cube)).merged_vertices, 36u - 8u);
  EXPECT_GT(expect_same_topology(test::with_flipped(cube, {0, 5})).inconsistent_edges, 0u);
  EXPECT_EQ(expect_same_topology(test::merged(cube, cube)).duplicated_faces, 12u);
  const Mesh sphere = test::triangulated(test::uv_sphere(2, 20, 30));
  EXPECT_TRUE(expect_same_topology(test::unshared(sphere)).closed);
}

TEST(TopologyMovedMesh, PolygonsAreWeldedInPlaceToo) {
  const Mesh quads = test::unit_cube_quads();
  EXPECT_TRUE(expect_same_topology(quads).closed);
  EXPECT_EQ(expect_same_topology(test::without_faces(quads, {1})).boundary_loops.size(), 1u);
  EXPECT_EQ(expect_same_topology(test::unshared(quads)).merged_vertices, 24u - 8u);
  EXPECT_EQ(expect_same_topology(test::merged(quads, quads)).duplicated_faces, 6u);
  // Quads and triangles at once (a UV sphere's poles are triangles), welded from fresh copies.
  EXPECT_TRUE(expect_same_topology(test::unshared(test::uv_sphere(2, 20, 30))).closed);
  Mesh copy = quads;
  analyze_topology(std::move(copy));
  EXPECT_TRUE(copy.vertices.empty() && copy.corners.empty());
}

TEST(TopologyMovedMesh, ToleranceWeld) {
  for (const Mesh& cube : {test::unit_cube(), test::unit_cube_quads()}) {
    Mesh m = test::unshared(cube);
    for (std::size_t i = 0; i < m.vertices.size(); i += 2) m.vertices[i].x += 1e-9;
    TopologyOptions o;
    o.weld_tolerance = 1e-6;
    const TopologyReport r = expect_same_topology(m, o);
    EXPECT_TRUE(r.closed);
    EXPECT_GT(r.weld_max_moved, 0);
  }
}

// The message of the exception analyze_topology(mesh, options) throws, through either overload
// (they must agree), and that it is an E.
template <class E>
std::string error_of(const Mesh& mesh, const TopologyOptions& options = {}) {
  std::string kept, moved;
  try {
    analyze_topology(mesh, options);
  } catch (const E& e) {
    kept = e.what();
  }
  try {
    analyze_topology(Mesh(mesh), options);
  } catch (const E& e) {
    moved = e.what();
  }
  EXPECT_EQ(moved, kept);
  return kept;
}

TEST(TopologyMovedMesh, BadInputThrowsTheSame) {
  for (const Mesh& cube : {test::unit_cube(), test::unit_cube_quads()}) {
    Mesh m = cube;
    m.corners[5] = 99;
    EXPECT_EQ(error_of<std::out_of_range>(m), "mesh: corner 5 names vertex 99 of 8");
    m = cube;
    m.face_offsets[2] = 1;
    EXPECT_EQ(error_of<std::out_of_range>(m), "mesh: face offsets descend at face 1");
    m = cube;
    m.face_offsets.back() -= 1;
    EXPECT_EQ(error_of<std::out_of_range>(m), "mesh: face offsets do not span the corner list");
    TopologyOptions bad;
    bad.weld_tolerance = -1;
    EXPECT_EQ(error_of<std::invalid_argument>(cube, bad),
              "weld tolerance must be a finite number >= 0");
    bad = {};
    bad.area_threshold = -1;
    EXPECT_EQ(error_of<std::invalid_argument>(cube, bad),
              "area threshold must be a finite number >= 0");
  }
}

TEST(TopologyMovedMesh, RealMeshes) {
  const std::string dir = test::shared_mesh("");
  if (dir.empty()) GTEST_SKIP() << "../shared/meshes not found";
  for (const char* name :
       {"npm/bunny.obj", "npm/bunny.stl", "npm/teapot.obj", "npm/conway-tI.obj",
        "stl-models/gearwheel.ascii.stl", "stl-models/quad.ascii.stl", "mayavi2/shuttle.obj",
        "openscad-testing-data/issue1580-back-to-back.stl", "assimp-testmodels/cube_binary.ply",
        "geomview/mushroom.off", "octave-matgeom/dodecahedron.ply"}) {
    SCOPED_TRACE(name);
    const std::string path = test::shared_mesh(name);
    if (path.empty()) continue;
    expect_same_topology(read_mesh(path));
  }
}

}  // namespace
}  // namespace pgamesh
