// The topology report of meshes of polygons against the brute-force reference
// (support/reference_topology.hpp): random soups of faces of zero to seven corners with repeated
// and welded corners, and copies of earlier faces rotated, reversed and shuffled (the same vertex
// set in another cycle), small and large enough for the two-thread path; the rule that makes a face
// a duplicate, on a hand-built case; and the real polygon meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/golden.hpp"
#include "support/reference_topology.hpp"

namespace pgamesh {
namespace {

using test::expect_matches_reference;

// `faces` random faces on the 3×3×3 grid (the first `pool` of its points, a quarter of them listed
// twice so that the weld merges them): faces of up to `max_corners` corners, some with a corner
// repeated, and three in ten a copy of an earlier face, rotated, reversed or shuffled.
Mesh polygon_soup(std::uint32_t seed, std::size_t faces, int pool, int max_corners) {
  std::mt19937 rng(seed);
  auto below = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  Mesh m;
  for (int i = 0; i < pool; ++i)
    m.vertices.push_back({double(i % 3), double(i / 3 % 3), double(i / 9 % 3) + 0.25 * (i % 2)});
  for (int i = 0; i < pool / 4; ++i)
    m.vertices.push_back(m.vertices[static_cast<std::size_t>(3 * i % pool)]);
  const int vertices = static_cast<int>(m.vertices.size());
  std::vector<std::vector<std::uint32_t>> listed;
  for (std::size_t f = 0; f < faces; ++f) {
    std::vector<std::uint32_t> face;
    if (below(10) < 3 && !listed.empty()) {
      face = listed[static_cast<std::size_t>(below(static_cast<int>(listed.size())))];
      const int how = below(4);
      if (how == 0 && !face.empty())
        std::rotate(face.begin(), face.begin() + below(static_cast<int>(face.size())), face.end());
      if (how == 1) std::reverse(face.begin(), face.end());
      if (how == 2) std::shuffle(face.begin(), face.end(), rng);
    } else {
      const int corners = below(3) == 0 ? 3 + below(3) : below(max_corners + 1);
      for (int i = 0; i < corners; ++i) face.push_back(static_cast<std::uint32_t>(below(vertices)));
      if (corners >= 2 && below(5) == 0) face[1] = face[0];  // a collapsed side
    }
    listed.push_back(face);
    m.corners.insert(m.corners.end(), face.begin(), face.end());
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  }
  return m;
}

TEST(TopologyPolygons, RandomSoupsMatchTheReference) {
  TopologyOptions small_lists;
  small_lists.list_cap = 3;
  TopologyOptions tolerant;
  tolerant.weld_tolerance = 0.3;  // merges the points 0.25 apart
  std::size_t duplicated = 0, collapsed = 0, nonmanifold = 0, inconsistent = 0, open_chains = 0;
  for (std::uint32_t seed = 1; seed <= 150; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh m = polygon_soup(seed, 1 + seed % 50, 6 + static_cast<int>(seed % 25), 7);
    for (const TopologyOptions& options : {TopologyOptions{}, small_lists, tolerant}) {
      const TopologyReport r = analyze_topology(m, options);
      expect_matches_reference(r, m, options);
      duplicated += r.duplicated_faces;
      collapsed += r.collapsed_faces;
      nonmanifold += r.nonmanifold_edges;
      inconsistent += r.inconsistent_edges;
      for (const BoundaryLoop& loop : r.boundary_loops) open_chains += loop.closed ? 0 : 1;
    }
  }
  // The soups do exercise every defect.
  EXPECT_GT(duplicated, 0u);
  EXPECT_GT(collapsed, 0u);
  EXPECT_GT(nonmanifold, 0u);
  EXPECT_GT(inconsistent, 0u);
  EXPECT_GT(open_chains, 0u);
}

TEST(TopologyPolygons, LargeSoupsTakeTheParallelPath) {
  // 30 000 faces on 50 vertices: the edge pass counts, fills and groups on two threads sharing one
  // union–find while the faces are tallied on a third; every vertex is a large fan. Without the
  // search for intersecting faces: most pairs of these faces meet (some 10^8).
  TopologyOptions edges_only;
  edges_only.self_intersections = false;
  for (std::uint32_t seed = 1; seed <= 2; ++seed) {
    SCOPED_TRACE(seed);
    const Mesh m = polygon_soup(seed, 30000, 40, 6);
    const TopologyReport r = analyze_topology(m, edges_only);
    expect_matches_reference(r, m, edges_only);
    EXPECT_GT(r.duplicated_faces, 0u);
    EXPECT_GT(r.nonmanifold_edges, 0u);
  }
}

TEST(TopologyPolygons, ADuplicateRepeatsAFaceThatRepeatsNone) {
  // Four quads on the corners of a square, in the three cycles its four vertices make: face 0 the
  // square 0 1 2 3 (first side on edge 01), face 1 the bow-tie 1 3 2 0 (first side 13; it uses edge
  // 01, so it repeats face 0), faces 2 and 3 the bow-tie 0 2 1 3 (first side 02). Face 2 lies on
  // face 1's first side, not on face 0's: face 1 repeats face 0, so face 2 repeats none, and face 3
  // repeats face 2 — two duplicates, though all four faces have the same vertex set.
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.add_face({0, 1, 2, 3});
  m.add_face({1, 3, 2, 0});
  m.add_face({0, 2, 1, 3});
  m.add_face({0, 2, 1, 3});
  const TopologyReport r = analyze_topology(m);
  expect_matches_reference(r, m);
  EXPECT_EQ(r.edges, 6u);
  ASSERT_EQ(r.duplicated_faces, 2u);
  EXPECT_EQ(r.duplicated_list[0].face, 1u);
  EXPECT_EQ(r.duplicated_list[0].same_as, 0u);
  EXPECT_EQ(r.duplicated_list[1].face, 3u);
  EXPECT_EQ(r.duplicated_list[1].same_as, 2u);
}

TEST(TopologyPolygons, FacesWithoutEdges) {
  // Faces of no, one and two corners, and a quad whose corners weld to two vertices: collapsed,
  // zero-area, in no component; the quad 0 1 2 2 is a triangle with a collapsed side.
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  m.face_offsets.push_back(0);
  m.add_face({0});
  m.add_face({0, 1});
  m.add_face({0, 1, 3, 1});
  m.add_face({0, 1, 2, 2});
  const TopologyReport r = analyze_topology(m);
  expect_matches_reference(r, m);
  EXPECT_EQ(r.collapsed_faces, 4u);
  EXPECT_EQ(r.zero_area_faces, 4u);
  EXPECT_EQ(r.edges, 3u);
  EXPECT_EQ(r.boundary_edges, 3u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.component_list[0].first_face, 4u);
  ASSERT_EQ(r.boundary_loops.size(), 1u);
  EXPECT_EQ(r.boundary_loops[0].half_edges, (std::vector<std::uint32_t>{7, 8, 10}));
}

TEST(TopologyPolygons, RealPolygonMeshesMatchTheReference) {
  if (test::shared_meshes_dir().empty())
    GTEST_SKIP() << "../shared/meshes not found (" PGAMESH_SHARED_MESHES_DIR "): skipped";
  std::size_t polygon_meshes = 0;
  for (const char* name : {"npm/conway-tI.obj", "mayavi2/shuttle.obj", "geomview/mushroom.off",
                           "octave-matgeom/dodecahedron.ply", "assimp-testmodels/cube_binary.ply",
                           "npm/teapot.obj", "stl-models/quad.ascii.stl"}) {
    const std::string path = test::shared_meshes_dir() + "/" + name;
    if (!std::filesystem::exists(path)) continue;
    SCOPED_TRACE(name);
    const Mesh m = read_mesh(path);
    expect_matches_reference(analyze_topology(m), m);
    polygon_meshes += m.corners.size() != 3 * m.face_count() ? 1 : 0;
  }
  EXPECT_GE(polygon_meshes, 2u);
}

}  // namespace
}  // namespace pgamesh
