// pgamesh repair (docs/topology.md, "Repair"): weld, faces that bound nothing, caps, orientation by
// nesting — each on a solid whose volume is known in closed form, and each repaired mesh must pass
// the topology check.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "pgamesh/mesh/repair/hole_cap.hpp"
#include "pgamesh/mesh/repair/repair.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/nested_shells.hpp"
#include "support/solids.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

using test::box_mesh;
using test::centred_cube;
using test::joined;
using test::triangulated;
using test::unshared;

// A copy without the faces whose corners all satisfy `drop_if`.
Mesh without_faces(const Mesh& m, const std::function<bool(Vec3d)>& drop_if) {
  Mesh out;
  out.vertices = m.vertices;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    bool all = true;
    for (std::size_t k = 0; k < m.face_size(f); ++k) all = all && drop_if(m.vertices[m.face(f)[k]]);
    if (all) continue;
    out.corners.insert(out.corners.end(), m.face(f), m.face(f) + m.face_size(f));
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
  }
  return out;
}

void expect_solid(const Mesh& m, double volume, double tolerance = 0) {
  const TopologyReport r = analyze_topology(m);
  EXPECT_TRUE(r.closed);
  EXPECT_TRUE(r.volume_valid);
  EXPECT_EQ(r.inward_components, 0u);
  EXPECT_NEAR(r.volume, volume, tolerance);
}

TEST(Repair, LeavesASolidAlone) {
  Mesh m = triangulated(box_mesh(2, 3, 4));
  const Mesh before = m;
  const RepairReport r = repair(m);
  EXPECT_FALSE(r.changed());
  EXPECT_EQ(m.corners, before.corners);
  EXPECT_EQ(m.vertices, before.vertices);
  expect_solid(m, 24);
}

// The hollow cube of issue "orientation by nesting": volume 7 through the repair, whichever way
// the cavity faced.
TEST(Repair, HollowCubeKeepsItsCavity) {
  for (bool cavity_outward : {false, true}) {
    Mesh m =
        joined({centred_cube(2, {}, true), centred_cube(1, {0.25, -0.125, 0.25}, cavity_outward)});
    const RepairReport r = repair(m);
    EXPECT_EQ(r.reversed_faces, cavity_outward ? 6u : 0u);
    const TopologyReport t = analyze_topology(m);
    EXPECT_EQ(t.volume, 7.0);
    EXPECT_EQ(t.cavity_components, 1u);
    EXPECT_TRUE(t.volume_valid);
  }
}

TEST(Repair, WeldsASoupOfFaces) {
  Mesh m = unshared(triangulated(box_mesh(1, 2, 3)));
  ASSERT_EQ(m.vertices.size(), 36u);
  const RepairReport r = repair(m);
  EXPECT_EQ(r.merged_vertices, 36u - 8u);
  EXPECT_EQ(r.output_vertices, 8u);
  expect_solid(m, 6);
}

TEST(Repair, ToleranceWeldClosesNearMisses) {
  Mesh m = unshared(triangulated(box_mesh(1, 1, 1)));
  for (std::size_t i = 0; i < m.vertices.size(); ++i)  // 1e-9 off, a different way each time
    m.vertices[i] += 1e-9 * Vec3d{double(i % 3) - 1, double(i % 5) / 4 - 0.5, double(i % 2)};
  // The exact weld merges nothing: 12 lone triangles, whose outlines are no holes to cap.
  Mesh exact = m;
  const RepairReport none = repair(exact);
  EXPECT_EQ(none.holes_capped, 0u);
  EXPECT_EQ(none.holes_refused, 12u);
  EXPECT_NE(none.holes[0].refused.find("outline of one face"), std::string::npos);
  EXPECT_FALSE(analyze_topology(exact).closed);
  RepairOptions o;
  o.weld_tolerance = 1e-6;
  const RepairReport r = repair(m, o);
  EXPECT_EQ(r.output_vertices, 8u);
  EXPECT_LE(r.weld_max_moved, 1e-6);
  expect_solid(m, 1, 1e-8);
}

// An open box: the missing top is capped in its plane, two triangles, volume 8 again.
TEST(Repair, CapsAPlanarHole) {
  Mesh m = without_faces(triangulated(box_mesh(2, 2, 2)), [](Vec3d p) { return p.z == 2; });
  const RepairReport r = repair(m);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes_capped, 1u);
  EXPECT_EQ(r.holes[0].rim_vertices, 4u);
  EXPECT_EQ(r.holes[0].area, 4.0);
  EXPECT_EQ(r.cap_triangles, 2u);
  expect_solid(m, 8);
}

// A cap is laid in its rim's plane; a face of the mesh through that plane inside the rim (a spike
// standing in the open box, through its top) would cut it: the hole is refused, the mesh left open
// and not made self-intersecting. The same box with the spike wholly inside is capped.
TEST(Repair, RefusesACapThatWouldCrossTheMesh) {
  const Mesh open_box =
      without_faces(triangulated(box_mesh(2, 2, 2)), [](Vec3d p) { return p.z == 2; });
  Mesh crossed = joined(
      {open_box, test::tetrahedron_mesh({0.5, 0.5, 1}, {1.5, 0.5, 1}, {1, 1.5, 1}, {1, 1, 2.5})});
  const RepairReport r = repair(crossed);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes_capped, 0u);
  EXPECT_EQ(r.holes_refused, 1u);
  EXPECT_EQ(r.cap_triangles, 0u);
  EXPECT_NE(r.holes[0].refused.find("its cap would cross the mesh"), std::string::npos)
      << r.holes[0].refused;
  const TopologyReport t = analyze_topology(crossed);
  EXPECT_EQ(t.boundary_edges, 4u);  // the rim, still open
  EXPECT_EQ(t.self_intersecting_pairs, 0u);

  Mesh inside = joined(
      {open_box, test::tetrahedron_mesh({0.5, 0.5, 1}, {1.5, 0.5, 1}, {1, 1.5, 1}, {1, 1, 1.5})});
  const RepairReport capped = repair(inside);
  EXPECT_EQ(capped.holes_capped, 1u);
  // The box of volume 8 with a cavity: the tetrahedron (base area 1/2·1·1, height 1/2) is
  // enclosed by the capped box, so it is oriented inward and subtracted.
  expect_solid(inside, 8 - 1.0 / 12);
}

// A cylinder without its top fan: the 24-gon rim capped, volume the prism's.
TEST(Repair, CapsAConvexPolygonRim) {
  const int n = 24;
  const double pi = std::acos(-1.0);
  Mesh m;
  for (int i = 0; i < n; ++i)
    for (double z : {0.0, 1.0})
      m.vertices.push_back({std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), z});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.add_face({2 * i, 2 * j, 2 * j + 1, 2 * i + 1});  // side, outward
  }
  std::vector<std::uint32_t> bottom;
  for (int i = n - 1; i >= 0; --i) bottom.push_back(static_cast<std::uint32_t>(2 * i));
  m.corners.insert(m.corners.end(), bottom.begin(), bottom.end());
  m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  const RepairReport r = repair(m);
  EXPECT_EQ(r.holes_capped, 1u);
  EXPECT_EQ(r.cap_triangles, static_cast<std::size_t>(n - 2));
  expect_solid(m, 0.5 * n * std::sin(2 * pi / n), 1e-14);
}

TEST(Repair, RemovesCollapsedAndDuplicateFaces) {
  Mesh m = triangulated(box_mesh(2, 2, 2));
  m.add_face({0, 0, 1});                                   // collapsed
  m.add_face({m.face(3)[0], m.face(3)[1], m.face(3)[2]});  // a copy of face 3
  m.add_face({m.face(5)[1], m.face(5)[2], m.face(5)[0]});  // a copy of face 5, rotated
  const RepairReport r = repair(m);
  EXPECT_EQ(r.collapsed_faces, 1u);
  EXPECT_EQ(r.duplicate_faces, 2u);
  EXPECT_EQ(r.removed_faces, (std::vector<std::uint32_t>{12, 13, 14}));
  EXPECT_EQ(m.face_count(), 12u);
  expect_solid(m, 8);
}

// Two unit cubes sharing the face x = 1: the wall is there twice, in opposite directions; removing
// both faces leaves the 2 × 1 × 1 box.
TEST(Repair, RemovesADoubleWall) {
  Mesh m = joined({box_mesh(1, 1, 1), test::transformed(box_mesh(1, 1, 1), [](Vec3d p) {
                     return p + Vec3d{1, 0, 0};
                   })});
  ASSERT_FALSE(analyze_topology(m).closed);  // the wall's edges have four faces after the weld
  const RepairReport r = repair(m);
  EXPECT_EQ(r.opposite_pairs, 1u);
  EXPECT_EQ(m.face_count(), 10u);
  expect_solid(m, 2);
}

TEST(Repair, NonPlanarRimNeedsForce) {
  // The open box with one top corner raised: the rim is 0.1 out of its plane.
  Mesh open = without_faces(triangulated(box_mesh(2, 2, 2)), [](Vec3d p) { return p.z == 2; });
  for (Vec3d& v : open.vertices)
    if (v.x == 2 && v.y == 2 && v.z == 2) v.z = 2.4;
  Mesh m = open;
  RepairReport r = repair(m);
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_EQ(r.holes_refused, 1u);
  EXPECT_NE(r.holes[0].refused.find("not planar"), std::string::npos);
  // One corner 0.4 up: about ±0.1 about the best-fit plane (exactly 0.1 for the least-squares
  // plane; the vector area's plane through the centroid is close to it).
  EXPECT_NEAR(r.holes[0].max_deviation, 0.1, 0.002);
  EXPECT_FALSE(analyze_topology(m).closed);

  RepairOptions o;
  o.hole.force = true;
  m = open;
  r = repair(m, o);
  EXPECT_EQ(r.holes_capped, 1u);
  const TopologyReport t = analyze_topology(m);
  EXPECT_TRUE(t.closed);
  EXPECT_GT(t.volume, 8.0);
}

TEST(HoleCap, ConcaveRimIsTriangulatedInside) {
  // An L-shaped rim in z = 0, running clockwise seen from +z (as the faces around a hole on a
  // top surface do): the cap runs counter-clockwise, normal +z, area 3.
  const std::vector<Vec3d> p{{0, 0, 0}, {0, 2, 0}, {1, 2, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}};
  const std::vector<std::uint32_t> rim{0, 1, 2, 3, 4, 5};
  const HoleCap cap = cap_hole(p, rim);
  ASSERT_TRUE(cap.capped()) << cap.refused;
  EXPECT_EQ(cap.normal, (Vec3d{0, 0, 1}));
  EXPECT_EQ(cap.area, 3.0);
  ASSERT_EQ(cap.triangles.size(), 4u);
  double area = 0;
  for (const auto& t : cap.triangles) {
    const double z = cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z / 2;
    EXPECT_GT(z, 0);  // every triangle counter-clockwise: none folds over the notch
    area += z;
  }
  EXPECT_EQ(area, 3.0);
}

TEST(HoleCap, RefusesRimsThatCannotBeCapped) {
  const std::vector<Vec3d> p{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}, {1, 0, 0}};
  // A bow tie: its sides cross.
  EXPECT_NE(cap_hole(p, std::vector<std::uint32_t>{0, 1, 2, 3}).refused.find("crosses itself"),
            std::string::npos);
  // Collinear: no area.
  EXPECT_NE(cap_hole(p, std::vector<std::uint32_t>{0, 4, 2}).refused.find("no area"),
            std::string::npos);
  // A vertex twice.
  EXPECT_NE(cap_hole(p, std::vector<std::uint32_t>{0, 1, 2, 0, 3}).refused.find("twice"),
            std::string::npos);
  EXPECT_FALSE(cap_hole(p, std::vector<std::uint32_t>{0, 1}).capped());
}

}  // namespace
}  // namespace pgamesh
