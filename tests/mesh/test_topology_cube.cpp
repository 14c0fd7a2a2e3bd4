// Topology of cubes: closed, minus one face (the gap is exactly the face), minus two adjacent faces
// (the gap is √2, not the missing 2: docs/conventions.md §6, paper Cor. 4.1), as triangles, as
// quads (closed, open, a face listed twice) and as both at once, against counts worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "pgamesh/mesh/topology/topology.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::unit_cube;

TEST(TopologyCube, ClosedCubeIsClosedWithNoGap) {
  const TopologyReport r = analyze_topology(unit_cube());
  EXPECT_EQ(r.faces, 12u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 18u);  // 12 cube edges + 6 face diagonals
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.orientation_consistent);
  EXPECT_TRUE(r.volume_valid);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.closed_components, 1u);
  EXPECT_TRUE(r.boundary_loops.empty());
  EXPECT_DOUBLE_EQ(r.area, 6.0);
  EXPECT_DOUBLE_EQ(r.volume, 1.0);
  EXPECT_EQ(r.gap_area, 0.0);
  EXPECT_EQ(r.volume_ambiguity(), 0.0);
  // Σ F about the origin: e0 = −6 V (docs/conventions.md §8), normal part 0.
  EXPECT_DOUBLE_EQ(r.carrier_sum.e0, -6.0);
  EXPECT_TRUE(r.notes.empty());
}

TEST(TopologyCube, UnsharedCubeWeldsToEightVertices) {
  const TopologyReport r = analyze_topology(test::unshared(unit_cube()));
  EXPECT_EQ(r.input_vertices, 36u);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.merged_vertices, 28u);
  EXPECT_TRUE(r.closed);
  EXPECT_DOUBLE_EQ(r.volume, 1.0);
}

TEST(TopologyCube, CubeMinusTopGapIsTheMissingFace) {
  // Faces 2, 3 are the z = 1 square (outward normal +z).
  const TopologyReport r = analyze_topology(test::without_faces(unit_cube(), {2, 3}));
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.orientation_consistent);
  EXPECT_FALSE(r.volume_valid);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_EQ(r.gap_area, 1.0);  // coplanar hole: exactly its area
  ASSERT_EQ(r.boundary_loops.size(), 1u);
  const BoundaryLoop& loop = r.boundary_loops[0];
  EXPECT_TRUE(loop.closed);
  EXPECT_EQ(loop.half_edges.size(), 4u);
  EXPECT_EQ(loop.perimeter, 4.0);
  EXPECT_EQ(loop.area, 1.0);
  // The remaining faces run the rim clockwise seen from above: vector area −(face normal × area).
  EXPECT_EQ(loop.vector_area.x, 0.0);
  EXPECT_EQ(loop.vector_area.y, 0.0);
  EXPECT_EQ(loop.vector_area.z, -1.0);
  EXPECT_EQ(r.gap_vector.z, -1.0);
  EXPECT_EQ(r.loops_area, 1.0);
  // V(q) over the vertices: 2/3 with q on the bottom, 1 (the whole cube) with q in the hole's
  // plane.
  EXPECT_DOUBLE_EQ(r.volume_min, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.volume_max, 1.0);
  EXPECT_DOUBLE_EQ(r.volume_ambiguity(), 1.0 / 3.0);
  // golden mesh_props.json cube_without_top: carrier sum e0 −4, e3 −2.
  EXPECT_DOUBLE_EQ(r.carrier_sum.e0, -4.0);
  EXPECT_DOUBLE_EQ(r.carrier_sum.e3, -2.0);
  EXPECT_DOUBLE_EQ(r.area, 5.0);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes[0].find("open"), std::string::npos);
}

TEST(TopologyCube, CubeMinusTwoAdjacentFacesGapIsRootTwo) {
  // Drop z = 1 (2, 3) and x = 1 (10, 11): one loop of 6 edges, missing area 2, gap √2.
  const TopologyReport r = analyze_topology(test::without_faces(unit_cube(), {2, 3, 10, 11}));
  EXPECT_EQ(r.boundary_edges, 6u);
  EXPECT_DOUBLE_EQ(r.gap_area, std::sqrt(2.0));
  ASSERT_EQ(r.boundary_loops.size(), 1u);
  EXPECT_EQ(r.boundary_loops[0].half_edges.size(), 6u);
  EXPECT_DOUBLE_EQ(r.boundary_loops[0].perimeter, 6.0);
  EXPECT_DOUBLE_EQ(r.boundary_loops[0].area, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(r.boundary_loops[0].vector_area.x, -1.0);
  EXPECT_DOUBLE_EQ(r.boundary_loops[0].vector_area.z, -1.0);
  EXPECT_DOUBLE_EQ(r.carrier_sum.e0, -2.0);
  EXPECT_DOUBLE_EQ(r.carrier_sum.e1, -2.0);
  EXPECT_DOUBLE_EQ(r.carrier_sum.e3, -2.0);
}

TEST(TopologyCube, QuadCubeIsClosed) {
  const TopologyReport r = analyze_topology(test::unit_cube_quads());
  EXPECT_EQ(r.faces, 6u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 12u);  // V − E + F = 8 − 12 + 6 = 2
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.orientation_consistent);
  EXPECT_TRUE(r.volume_valid);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.closed_components, 1u);
  EXPECT_EQ(r.component_list[0].faces, 6u);
  EXPECT_DOUBLE_EQ(r.area, 6.0);
  EXPECT_DOUBLE_EQ(r.volume, 1.0);
  EXPECT_DOUBLE_EQ(r.component_list[0].volume, 1.0);
  EXPECT_EQ(r.gap_area, 0.0);
  EXPECT_TRUE(r.boundary_loops.empty());
  EXPECT_TRUE(r.notes.empty());
}

TEST(TopologyCube, QuadCubeMinusTopHasOneSquareLoop) {
  // Face 1 is the z = 1 square 4 5 7 6: its four edges are left with one face each.
  const TopologyReport r = analyze_topology(test::without_faces(test::unit_cube_quads(), {1}));
  EXPECT_EQ(r.faces, 5u);
  EXPECT_EQ(r.edges, 12u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.volume_valid);
  EXPECT_EQ(r.components, 1u);
  ASSERT_EQ(r.boundary_loops.size(), 1u);
  const BoundaryLoop& loop = r.boundary_loops[0];
  EXPECT_TRUE(loop.closed);
  EXPECT_EQ(loop.half_edges.size(), 4u);
  EXPECT_EQ(loop.perimeter, 4.0);
  EXPECT_EQ(loop.area, 1.0);
  EXPECT_EQ(loop.vector_area.z, -1.0);
  EXPECT_EQ(r.gap_area, 1.0);
  EXPECT_DOUBLE_EQ(r.volume_min, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.volume_max, 1.0);
}

TEST(TopologyCube, QuadListedTwiceIsOneDuplicate) {
  // Face 0 (0 2 3 1) again, then reversed: each repeats face 0, and face 0's four edges are used
  // by three faces, then by four (two each way).
  Mesh m = test::unit_cube_quads();
  m.add_face({0, 2, 3, 1});
  TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.duplicated_faces, 1u);
  EXPECT_EQ(r.duplicated_area_faces, 1u);
  ASSERT_EQ(r.duplicated_list.size(), 1u);
  EXPECT_EQ(r.duplicated_list[0].face, 6u);
  EXPECT_EQ(r.duplicated_list[0].same_as, 0u);
  EXPECT_DOUBLE_EQ(r.duplicated_list[0].area, 1.0);
  EXPECT_EQ(r.edges, 12u);
  EXPECT_EQ(r.nonmanifold_edges, 4u);
  EXPECT_EQ(r.inconsistent_edges, 0u);  // 2 : 1 uses pair up but for the odd one out
  EXPECT_FALSE(r.volume_valid);
  m.add_face({0, 1, 3, 2});
  r = analyze_topology(m);
  EXPECT_EQ(r.duplicated_faces, 2u);
  EXPECT_EQ(r.duplicated_list[1].face, 7u);
  EXPECT_EQ(r.duplicated_list[1].same_as, 0u);
  EXPECT_EQ(r.nonmanifold_edges, 4u);
  EXPECT_EQ(r.inconsistent_edges, 0u);  // 2 : 2
}

TEST(TopologyCube, TrianglesAndQuadsTogether) {
  // The z faces as quads, the other four sides as the triangle pairs of unit_cube: 10 faces, the
  // 12 cube edges and 4 diagonals (V − E + F = 8 − 16 + 10 = 2).
  Mesh m = test::without_faces(test::unit_cube(), {0, 1, 2, 3});
  m.add_face({0, 2, 3, 1});
  m.add_face({4, 5, 7, 6});
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.faces, 10u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.edges, 16u);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.volume_valid);
  EXPECT_EQ(r.components, 1u);
  EXPECT_DOUBLE_EQ(r.area, 6.0);
  EXPECT_DOUBLE_EQ(r.volume, 1.0);
}

TEST(TopologyCube, FarFromOriginKeepsDigits) {
  // docs/conventions.md §13: accumulated about the bounding-box centre, a cube 1e6 away still
  // measures exactly.
  const Mesh far = test::translated(test::without_faces(unit_cube(), {2, 3}), {1e6, -2e6, 3e6});
  const TopologyReport r = analyze_topology(far);
  EXPECT_EQ(r.gap_area, 1.0);
  EXPECT_EQ(r.boundary_loops[0].area, 1.0);
  EXPECT_DOUBLE_EQ(r.volume_max, 1.0);
  EXPECT_DOUBLE_EQ(r.volume_min, 2.0 / 3.0);
}

TEST(TopologyCube, HolesTouchingAtAVertexAreTwoLoops) {
  // Faces 1 (0, 3, 1) of the bottom and 11 (1, 7, 5) of x = 1 share vertex 1 and no edge: their
  // holes touch at a vertex, and each is a loop of three edges (not one figure-eight of six).
  const TopologyReport r = analyze_topology(test::without_faces(unit_cube(), {1, 11}));
  EXPECT_EQ(r.boundary_edges, 6u);
  ASSERT_EQ(r.boundary_loops.size(), 2u);
  for (const BoundaryLoop& loop : r.boundary_loops) {
    EXPECT_TRUE(loop.closed);
    EXPECT_EQ(loop.half_edges.size(), 3u);
    EXPECT_DOUBLE_EQ(loop.area, 0.5);
  }
  EXPECT_DOUBLE_EQ(r.loops_area, 1.0);
  EXPECT_DOUBLE_EQ(r.gap_area, 0.5 * std::sqrt(2.0));  // −½ e3 and −½ e1: not coplanar
}

TEST(TopologyCube, EmptyMesh) {
  const TopologyReport r = analyze_topology(Mesh{});
  EXPECT_EQ(r.faces, 0u);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.volume_valid);
  EXPECT_EQ(r.components, 0u);
  EXPECT_EQ(r.area, 0.0);
}

TEST(TopologyCube, BadIndicesThrow) {
  Mesh m = unit_cube();
  m.corners[5] = 99;
  EXPECT_THROW(analyze_topology(m), std::out_of_range);
}

}  // namespace
}  // namespace pgamesh
