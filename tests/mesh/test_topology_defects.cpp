// Defects the topology pass must find and name: inconsistent orientation (and its repair),
// duplicated faces, zero-area and nearly-zero faces, non-manifold edges, several components.
#include <gtest/gtest.h>

#include <cmath>

#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::unit_cube;

std::vector<std::uint32_t> flipped_faces(const OrientationFix& fix) {
  std::vector<std::uint32_t> out;
  for (const auto& c : fix.components)
    out.insert(out.end(), c.flipped_faces.begin(), c.flipped_faces.end());
  return out;
}

TEST(TopologyDefects, FlippedFacesAreInconsistentAndFixRestoresExactlyThem) {
  const Mesh good = unit_cube();
  Mesh bad = test::with_flipped(good, {3, 8});
  const TopologyReport r = analyze_topology(bad);
  EXPECT_FALSE(r.orientation_consistent);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.volume_valid);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.gap_area != 0.0, true);  // reversed faces no longer cancel
  // Faces 3 (4, 7, 6) and 8 (0, 4, 6) share the edge 4–6, which both reversed stays consistent;
  // their other four edges now run twice the same way.
  EXPECT_EQ(r.inconsistent_edges, 4u);

  const OrientationFix fix = fix_orientation(bad);
  EXPECT_EQ(fix.flipped, 2u);
  EXPECT_EQ(fix.conflicts, 0u);
  EXPECT_EQ(flipped_faces(fix), (std::vector<std::uint32_t>{3, 8}));
  ASSERT_EQ(fix.components.size(), 1u);
  EXPECT_TRUE(fix.components[0].closed);
  EXPECT_DOUBLE_EQ(fix.components[0].volume, 1.0);
  EXPECT_EQ(bad.corners, good.corners);  // with_flipped and the fix keep the first corner
}

TEST(TopologyDefects, EdgeUsedThreeTimesOneWayIsNamedInTheNote) {
  // Three triangles on the edge 0→1, all in the same direction: one inconsistent edge used by
  // three faces, which the note must not call "twice".
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}};
  m.add_face({0, 1, 2});
  m.add_face({0, 1, 3});
  m.add_face({0, 1, 4});
  const TopologyReport r = analyze_topology(m);
  EXPECT_FALSE(r.orientation_consistent);
  ASSERT_EQ(r.inconsistent_edges, 1u);
  ASSERT_EQ(r.inconsistent_edge_list.size(), 1u);
  EXPECT_EQ(r.inconsistent_edge_list[0].face_count, 3u);
  bool named = false;
  for (const auto& note : r.notes) {
    EXPECT_EQ(note.find("twice"), std::string::npos) << note;
    if (note.starts_with("orientation inconsistent: 1 edges are used by two or more faces in the "
                         "same direction"))
      named = true;
  }
  EXPECT_TRUE(named);
}

TEST(TopologyDefects, FixWhenTheSeedFaceItselfWasFlipped) {
  // Face 0 is the walk's seed; the outward step must still reverse exactly the flipped faces.
  const Mesh good = unit_cube();
  Mesh bad = test::with_flipped(good, {0, 1, 5});
  const OrientationFix fix = fix_orientation(bad);
  EXPECT_EQ(flipped_faces(fix), (std::vector<std::uint32_t>{0, 1, 5}));
  EXPECT_EQ(bad.corners, good.corners);
}

TEST(TopologyDefects, InwardClosedMeshIsConsistentButNegative) {
  const Mesh good = unit_cube();
  Mesh inward = test::with_flipped(good, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  const TopologyReport r = analyze_topology(inward);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.orientation_consistent);
  EXPECT_DOUBLE_EQ(r.volume, -1.0);
  EXPECT_EQ(r.inward_components, 1u);
  const OrientationFix fix = fix_orientation(inward);
  EXPECT_EQ(fix.flipped, 12u);
  EXPECT_EQ(inward.corners, good.corners);
  EXPECT_DOUBLE_EQ(analyze_topology(inward).volume, 1.0);
}

TEST(TopologyDefects, OutwardClosedMeshIsLeftAlone) {
  Mesh m = unit_cube();
  const OrientationFix fix = fix_orientation(m);
  EXPECT_EQ(fix.flipped, 0u);
  EXPECT_TRUE(fix.components.empty());
  EXPECT_EQ(m.corners, unit_cube().corners);
}

TEST(TopologyDefects, OpenComponentKeepsItsMajorityOrientation) {
  Mesh open = test::without_faces(unit_cube(), {2, 3});  // 10 faces left
  Mesh bad = test::with_flipped(open, {0, 4, 7});
  const OrientationFix fix = fix_orientation(bad);
  EXPECT_EQ(flipped_faces(fix), (std::vector<std::uint32_t>{0, 4, 7}));
  EXPECT_FALSE(fix.components[0].closed);
  EXPECT_EQ(bad.corners, open.corners);
}

TEST(TopologyDefects, DuplicatedFacesInEitherOrientation) {
  Mesh m = unit_cube();
  m.add_face({0, 2, 3});  // face 12 = face 0
  m.add_face({7, 4, 5});  // face 13 = face 2 (4, 5, 7) reversed
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.duplicated_faces, 2u);
  ASSERT_EQ(r.duplicated_list.size(), 2u);
  EXPECT_EQ(r.duplicated_list[0].face, 12u);
  EXPECT_EQ(r.duplicated_list[0].same_as, 0u);
  EXPECT_EQ(r.duplicated_list[1].face, 13u);
  EXPECT_EQ(r.duplicated_list[1].same_as, 2u);
  EXPECT_DOUBLE_EQ(r.duplicated_list[0].area, 0.5);
  EXPECT_DOUBLE_EQ(r.duplicated_list[0].centroid.x, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.duplicated_list[0].centroid.y, 2.0 / 3.0);
  EXPECT_FALSE(r.volume_valid);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.nonmanifold_edges, 6u);  // each duplicate puts a third face on its three edges
  bool noted = false;
  for (const auto& n : r.notes) noted |= n.find("duplicated faces: 2") != std::string::npos;
  EXPECT_TRUE(noted);
}

TEST(TopologyDefects, DoubleSidedTriangleIsClosedButDuplicated) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 1});
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.closed);              // every edge two opposite uses...
  EXPECT_EQ(r.duplicated_faces, 1u);  // ...but it is one face twice: volume is not meaningful
  EXPECT_FALSE(r.volume_valid);
  EXPECT_EQ(r.volume, 0.0);
}

TEST(TopologyDefects, ZeroAndSmallAreaFacesAreReportedSeparately) {
  Mesh m = unit_cube();
  // A collapsed triangle (two corners on one vertex), an exactly collinear one on the cube's edge
  // 0–1 through a new vertex 8 = (0.5, 0, 0), and a sliver with area 1e-12 of its longest side².
  m.vertices.push_back({0.5, 0.0, 0.0});
  m.vertices.push_back({0.5, 1e-12, 0.0});
  m.add_face({0, 0, 1});  // face 12: collapsed
  m.add_face({0, 8, 1});  // face 13: collinear, exactly zero normal
  m.add_face({0, 1, 9});  // face 14: area ½·1·1e-12
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.zero_area_faces, 2u);
  EXPECT_EQ(r.collapsed_faces, 1u);
  ASSERT_EQ(r.zero_area_list.size(), 2u);
  EXPECT_EQ(r.zero_area_list[0].face, 12u);
  EXPECT_EQ(r.zero_area_list[1].face, 13u);
  EXPECT_EQ(r.zero_area_list[1].area, 0.0);
  EXPECT_EQ(r.small_area_faces, 1u);
  ASSERT_EQ(r.small_area_list.size(), 1u);
  EXPECT_EQ(r.small_area_list[0].face, 14u);
  EXPECT_DOUBLE_EQ(r.small_area_list[0].area, 0.5e-12);
  EXPECT_DOUBLE_EQ(r.area, 6.0 + 0.5e-12);
  // A larger threshold does not reclassify zero faces; a zero threshold flags no small ones.
  TopologyOptions none;
  none.area_threshold = 0;
  EXPECT_EQ(analyze_topology(m, none).small_area_faces, 0u);
}

TEST(TopologyDefects, SmallAreaThresholdIsExactAtItsBoundary) {
  // The sliver (0,0,0), (1,0,0), (0.5,h,0): own area h/2, longest side 1, so it is small exactly
  // when h/2 <= threshold. Heights on both sides of the boundary, from far (where the pass decides
  // without a square root) to one ulp away (where the exact comparison decides).
  const double threshold = 1e-9, edge = 2 * threshold;
  const double heights[] = {edge * 0.5,
                            std::nextafter(edge, 0.0),
                            edge,
                            std::nextafter(edge, 1.0),
                            edge * (1 + 1e-12),
                            edge * (1 + 1e-9),
                            edge * (1 + 1e-8),
                            edge * 2,
                            1e-3};
  for (const double h : heights) {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}};
    m.add_face({0, 1, 2});
    TopologyOptions options;
    options.area_threshold = threshold;
    const TopologyReport r = analyze_topology(m, options);
    EXPECT_EQ(r.small_area_faces, 0.5 * h <= threshold ? 1u : 0u) << "h = " << h;
    EXPECT_EQ(r.zero_area_faces, 0u);
  }
}

TEST(TopologyDefects, CollapsedFaceDoesNotBreakItsNeighbours) {
  // Weld two corners of one triangle together (a tolerance weld would do this): the collapsed face
  // is left out of the edges, so the remaining faces still close up around it.
  Mesh m = unit_cube();
  m.vertices[7] = m.vertices[3] = {1, 1, 0.5};  // collapse the vertical edge 3–7 to a point
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.vertices, 7u);
  EXPECT_EQ(r.collapsed_faces, 2u);  // faces 7 (2, 7, 3) and 10 (1, 3, 7)
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.components, 1u);
}

TEST(TopologyDefects, NonManifoldBackToBackTetrahedra) {
  // Two tetrahedra sharing the edge (0,0,0)–(0,0,1): that edge carries four faces.
  Mesh m;
  m.vertices = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  // Tetra A = (0, 2, 3, 1) outward, tetra B = (0, 4, 5, 1) outward.
  m.add_face({0, 3, 2});
  m.add_face({0, 2, 1});
  m.add_face({0, 1, 3});
  m.add_face({2, 3, 1});
  m.add_face({0, 5, 4});
  m.add_face({0, 4, 1});
  m.add_face({0, 1, 5});
  m.add_face({4, 5, 1});
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.nonmanifold_edges, 1u);
  ASSERT_EQ(r.nonmanifold_edge_list.size(), 1u);
  EXPECT_EQ(r.nonmanifold_edge_list[0].face_count, 4u);
  EXPECT_EQ(r.nonmanifold_edge_list[0].p0, (Vec3d{0, 0, 0}));
  EXPECT_EQ(r.nonmanifold_edge_list[0].p1, (Vec3d{0, 0, 1}));
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_TRUE(r.orientation_consistent);
  EXPECT_FALSE(r.closed);
  EXPECT_TRUE(r.volume_valid);  // consistent and without gap: the volume is the two tetrahedra's
  EXPECT_DOUBLE_EQ(r.volume, 2.0 / 6.0);
  EXPECT_EQ(r.components, 1u);
}

TEST(TopologyDefects, TwoDisjointCubesAreTwoComponents) {
  const Mesh m = test::merged(unit_cube(), test::translated(unit_cube(), {3, 0, 0}));
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.closed_components, 2u);
  ASSERT_EQ(r.component_list.size(), 2u);
  EXPECT_EQ(r.component_list[0].first_face, 0u);
  EXPECT_EQ(r.component_list[1].first_face, 12u);
  EXPECT_EQ(r.component_list[1].faces, 12u);
  EXPECT_DOUBLE_EQ(r.component_list[1].volume, 1.0);
  EXPECT_DOUBLE_EQ(r.component_list[1].area, 6.0);
  EXPECT_TRUE(r.closed);
  EXPECT_DOUBLE_EQ(r.volume, 2.0);
}

TEST(TopologyDefects, CubesTouchingAlongAnEdgeAreOneNonManifoldComponent) {
  const Mesh m = test::merged(unit_cube(), test::translated(unit_cube(), {1, 1, 0}));
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.vertices, 14u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.nonmanifold_edges, 1u);
  EXPECT_DOUBLE_EQ(r.volume, 2.0);
}

TEST(TopologyDefects, ListsAreCappedButCountsAreNot) {
  Mesh m;
  for (int i = 0; i < 50; ++i) {
    const auto b = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back({double(i), 0, 0});
    m.vertices.push_back({double(i) + 1, 0, 0});
    m.vertices.push_back({double(i), 1, 0});
    m.add_face({b, b + 1, b + 2});
  }
  TopologyOptions opt;
  opt.list_cap = 5;
  const TopologyReport r = analyze_topology(m, opt);
  EXPECT_EQ(r.components, 50u);
  EXPECT_EQ(r.component_list.size(), 5u);
  EXPECT_EQ(r.boundary_edges, 150u);
  EXPECT_EQ(r.boundary_edge_list.size(), 5u);
  EXPECT_EQ(r.boundary_loops.size(), 50u);
  EXPECT_DOUBLE_EQ(r.gap_area, 25.0);  // 50 coplanar triangles of area ½ facing +z
  EXPECT_DOUBLE_EQ(r.loops_area, 25.0);
}

}  // namespace
}  // namespace pgamesh
