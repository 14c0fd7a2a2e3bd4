// The self-intersection pass (self_intersections.hpp, docs/topology.md "Self-intersections")
// against pairs counted by hand and against the brute-force exact reference
// (tests/support/reference_self_intersections.hpp): overlapping, touching and nested cubes, a
// folded surface, coplanar neighbours, degenerate faces, closed meshes with none, random soups.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/mesh/topology/self_intersections.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/nested_shells.hpp"
#include "support/reference_self_intersections.hpp"
#include "support/solids.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {

namespace {

using IntersectingPairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// Every pair the pass finds, in order (the list uncapped).
IntersectingPairs self_intersecting_pairs_found(const Mesh& mesh) {
  const SelfIntersections s = find_self_intersections(mesh, SIZE_MAX);
  IntersectingPairs out;
  for (const SelfIntersection& p : s.list) out.emplace_back(p.face0, p.face1);
  EXPECT_EQ(out.size(), s.pairs);
  return out;
}

// The unit cube of triangles moved by `offset` and scaled by `scale`.
Mesh unit_cube_at(Vec3d offset, double scale = 1) {
  return test::transformed(test::unit_cube(), [&](Vec3d p) { return offset + p * scale; });
}

void expect_self_intersections_match_reference(const Mesh& mesh) {
  const IntersectingPairs found = self_intersecting_pairs_found(mesh);
#ifdef PGAMESH_HAVE_GMP
  EXPECT_EQ(found, test::reference_self_intersections(mesh));
#endif
}

}  // namespace

// Two unit cubes, the second moved by (½, ½, ½): each of the three faces of one that cut the other
// (x = 1, y = 1, z = 1 of the first; x = ½, y = ½, z = ½ of the second) crosses the two
// perpendicular ones of the other inside both — by hand, per pair of squares, the diagonals decide
// which of the 2 × 2 triangle pairs meet; the exact reference counts them.
TEST(SelfIntersections, OverlappingCubesAreFlagged) {
  const Mesh mesh = test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({0.5, 0.5, 0.5})});
  const SelfIntersections s = find_self_intersections(mesh);
  EXPECT_GT(s.pairs, 0u);
  for (const SelfIntersection& p : s.list) {
    EXPECT_LT(p.face0, 12u);  // every pair has one face of each cube
    EXPECT_GE(p.face1, 12u);
    // The point is in the overlap [½, 1]³, on the surface of both.
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(p.point[k], 0.5);
      EXPECT_LE(p.point[k], 1.0);
    }
  }
  expect_self_intersections_match_reference(mesh);

  const TopologyReport r = analyze_topology(mesh);
  EXPECT_TRUE(r.self_intersections_checked);
  EXPECT_EQ(r.self_intersecting_pairs, s.pairs);
  EXPECT_TRUE(r.closed);
  EXPECT_FALSE(r.volume_valid);
  const std::string note = "self-intersecting: " + std::to_string(s.pairs) + " face pairs";
  EXPECT_TRUE(std::any_of(r.notes.begin(), r.notes.end(),
                          [&](const std::string& n) { return n.rfind(note, 0) == 0; }));

  TopologyOptions without;
  without.self_intersections = false;
  const TopologyReport unchecked = analyze_topology(mesh, without);
  EXPECT_FALSE(unchecked.self_intersections_checked);
  EXPECT_TRUE(unchecked.volume_valid);  // what the pass catches: nothing else is wrong
}

// Two cubes sharing a face, its vertices welded: both triangulate the shared square with the same
// diagonal, so its two triangles coincide with two of the other cube (2 pairs, by hand: faces
// 10 = {1, 3, 7} and 11 = {1, 7, 5} of the first, 21 = {1, 7, 3} and 20 = {1, 5, 7} of the second;
// the other pairs across the square lie on opposite sides of the diagonal).
TEST(SelfIntersections, CubesTouchingAtAFaceOverlapThere) {
  const Mesh mesh = test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 0, 0})});
  EXPECT_EQ(self_intersecting_pairs_found(mesh), (IntersectingPairs{{10, 21}, {11, 20}}));
  expect_self_intersections_match_reference(mesh);
}

// Touching along a welded edge or at a welded vertex only: faces that share the vertex may meet
// there (docs/topology.md: the weld makes them neighbours), so nothing is flagged.
TEST(SelfIntersections, CubesTouchingAtAWeldedEdgeOrVertexDoNotIntersect) {
  EXPECT_EQ(
      find_self_intersections(test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 1, 0})}))
          .pairs,
      0u);
  EXPECT_EQ(
      find_self_intersections(test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 1, 1})}))
          .pairs,
      0u);
  expect_self_intersections_match_reference(
      test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 1, 0})}));
  expect_self_intersections_match_reference(
      test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 1, 1})}));
}

// Faces that share no vertex and touch are flagged (CGAL's rule): a half-size cube standing on the
// x = 1 face of the unit cube (faces 10, 11), its corners not the unit cube's. Every pair has one
// of those two faces; the exact reference counts which of the small cube's faces touch them.
TEST(SelfIntersections, TouchingWithoutSharedVerticesIsAnIntersection) {
  const Mesh mesh = test::joined({unit_cube_at({0, 0, 0}), unit_cube_at({1, 0.25, 0.25}, 0.5)});
  const IntersectingPairs found = self_intersecting_pairs_found(mesh);
  ASSERT_FALSE(found.empty());
  for (const auto& [f, g] : found) {
    EXPECT_TRUE(f == 10 || f == 11) << f;  // the unit cube's x = 1 face
    EXPECT_GE(g, 12u);
  }
  expect_self_intersections_match_reference(mesh);
  // Moved off by one unit in the last place, they no longer touch.
  const Mesh apart = test::joined(
      {unit_cube_at({0, 0, 0}), unit_cube_at({std::nextafter(1.0, 2.0), 0.25, 0.25}, 0.5)});
  EXPECT_EQ(find_self_intersections(apart).pairs, 0u);
}

TEST(SelfIntersections, NestedCubesDoNotIntersect) {
  const Mesh mesh = test::joined(
      {test::centred_cube(3, {0, 0, 0}, true), test::centred_cube(1, {0.2, -0.3, 0.1}, false)});
  EXPECT_EQ(find_self_intersections(mesh).pairs, 0u);
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_EQ(r.self_intersecting_pairs, 0u);
  EXPECT_TRUE(r.volume_valid);
  expect_self_intersections_match_reference(mesh);
}

TEST(SelfIntersections, ClosedMeshesHaveNone) {
  for (const Mesh& mesh : {test::torus_mesh(3, 1, 48, 24, {0, 0, 0}, true),
                           test::uv_sphere(2, 24, 48), test::box_mesh(1, 2, 3),
                           test::triangulated(test::torus_mesh(3, 1, 48, 24, {1, 2, 3}, true))}) {
    const SelfIntersections s = find_self_intersections(mesh);
    EXPECT_EQ(s.pairs, 0u);
    EXPECT_EQ(s.degenerate_triangles, 0u);
  }
  for (const char* name : {"/bunny.stl", "/tank.obj"}) {
    const Mesh mesh = read_mesh(std::string(PGAMESH_BUNDLED_MESHES_DIR) + name);
    const TopologyReport r = analyze_topology(mesh);
    EXPECT_TRUE(r.self_intersections_checked);
    EXPECT_EQ(r.self_intersecting_pairs, 0u) << name;
  }
}

// A folded surface: the top corner (1, 1, 1) of the unit cube pushed down through the bottom face
// to (0.25, 0.3, −0.5): the faces around it now pass through the bottom's triangles.
TEST(SelfIntersections, FoldedSurfaceIsFlagged) {
  Mesh mesh = test::unit_cube();
  mesh.vertices[7] = {0.25, 0.3, -0.5};
  EXPECT_GT(find_self_intersections(mesh).pairs, 0u);
  expect_self_intersections_match_reference(mesh);
}

// Coplanar neighbours: two triangles sharing an edge overlap when their third corners lie on the
// same side of it (1 pair, by hand), not when on opposite sides.
TEST(SelfIntersections, CoplanarNeighboursOverlapOnlyOnTheSameSide) {
  Mesh folded;
  folded.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.5, 0}};
  folded.add_face({0, 1, 2});
  folded.add_face({1, 0, 3});
  EXPECT_EQ(self_intersecting_pairs_found(folded), (IntersectingPairs{{0, 1}}));
  expect_self_intersections_match_reference(folded);

  Mesh flat = folded;
  flat.vertices[3] = {0.25, -0.5, 0};
  EXPECT_EQ(find_self_intersections(flat).pairs, 0u);
  expect_self_intersections_match_reference(flat);

  // Sharing one vertex, coplanar: overlapping wedges intersect, wedges touching along a ray from
  // the vertex intersect where one edge runs along the other.
  Mesh wedges;
  wedges.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0.5, 0}, {0, 1, 0}};
  wedges.add_face({0, 1, 2});
  wedges.add_face({0, 3, 4});
  EXPECT_EQ(self_intersecting_pairs_found(wedges), (IntersectingPairs{{0, 1}}));
  expect_self_intersections_match_reference(wedges);
  Mesh fan = wedges;
  fan.vertices[3] = {2, 2, 0};  // along the shared ray 0 → 2, beyond it: overlap on the ray
  EXPECT_EQ(self_intersecting_pairs_found(fan), (IntersectingPairs{{0, 1}}));
  expect_self_intersections_match_reference(fan);
}

// Zero-area faces — collinear corners, a corner repeated, all corners at one point — have no
// interior: they are left out (counted), and nothing crashes.
TEST(SelfIntersections, DegenerateFacesAreLeftOut) {
  Mesh mesh = test::unit_cube();
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back({-1, 0.5, 0.5});
  mesh.vertices.push_back({0.5, 0.5, 0.5});
  mesh.vertices.push_back({2, 0.5, 0.5});  // a needle through the cube
  mesh.add_face({base, base + 1, base + 2});
  mesh.add_face({0, 0, 7});
  mesh.add_face({base + 1, base + 1, base + 1});
  const SelfIntersections s = find_self_intersections(mesh);
  EXPECT_EQ(s.pairs, 0u);
  EXPECT_EQ(s.degenerate_triangles, 3u);
  expect_self_intersections_match_reference(mesh);
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_EQ(r.self_intersecting_pairs, 0u);
}

// Polygons are tested through their fans: two quads crossing like a plus sign.
TEST(SelfIntersections, PolygonsAreTestedThroughTheirFans) {
  Mesh mesh;
  mesh.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
                   {0, -2, -1}, {0, 2, -1}, {0, 2, 1}, {0, -2, 1}};
  mesh.add_face({0, 1, 2, 3});
  mesh.add_face({4, 5, 6, 7});
  EXPECT_EQ(self_intersecting_pairs_found(mesh), (IntersectingPairs{{0, 1}}));
  expect_self_intersections_match_reference(mesh);
  const Mesh boxes = test::joined(
      {test::box_mesh(1, 1, 1), test::transformed(test::box_mesh(1, 1, 1), [](Vec3d p) {
         return p + Vec3d{0.5, 0.25, 0.125};
       })});
  EXPECT_GT(find_self_intersections(boxes).pairs, 0u);
  expect_self_intersections_match_reference(boxes);
}

#ifdef PGAMESH_HAVE_GMP
// Random soups against the exact reference: corners on a coarse grid (shared vertices, coplanar
// and collinear cases, touching, coincident faces), and corners anywhere (general position),
// triangles and quads.
// Two overlapping spheres of 20 480 triangles each: enough fan triangles that the hierarchy is
// built in two halves on two threads and the queries run on two. Their pairs must be those of the
// faces near the other sphere alone (a mesh small enough for one thread), face for face: only
// faces whose boxes reach into the other sphere's box can meet it, and one sphere's faces do not
// meet each other.
TEST(SelfIntersections, TwoThreadHierarchyFindsWhatOneThreadFinds) {
  const Mesh a = icosphere(5, 1.0);
  const Mesh b = test::translated(icosphere(5, 1.0), {1.5, 0.25, 0.125});
  const Mesh both = test::merged(a, b);
  // The faces of `m` whose corners' box reaches x ≥ low (a) or x ≤ high (b).
  auto near = [](const Mesh& m, auto reaches) {
    std::vector<std::uint32_t> faces;
    for (std::uint32_t f = 0; f < m.face_count(); ++f)
      for (std::size_t k = 0; k < m.face_size(f); ++k)
        if (reaches(m.vertices[m.face(f)[k]].x)) {
          faces.push_back(f);
          break;
        }
    return faces;
  };
  const std::vector<std::uint32_t> near_a = near(a, [](double x) { return x >= 0.45; });
  const std::vector<std::uint32_t> near_b = near(b, [](double x) { return x <= 1.05; });
  Mesh small;
  small.vertices = both.vertices;
  const auto b_base = static_cast<std::uint32_t>(a.vertices.size());
  for (std::uint32_t f : near_a) small.add_face({a.face(f)[0], a.face(f)[1], a.face(f)[2]});
  for (std::uint32_t f : near_b)
    small.add_face({b.face(f)[0] + b_base, b.face(f)[1] + b_base, b.face(f)[2] + b_base});
  ASSERT_GE(both.face_count(), 40000u);
  ASSERT_LT(small.face_count(), 16000u);  // below two threads' worth of fan triangles
  const IntersectingPairs found = self_intersecting_pairs_found(both);
  IntersectingPairs expected;
  const auto b_face = static_cast<std::uint32_t>(a.face_count());
  for (const auto& [f0, f1] : self_intersecting_pairs_found(small))  // back to both's numbering
    expected.emplace_back(near_a[f0], b_face + near_b[f1 - near_a.size()]);
  std::sort(expected.begin(), expected.end());
  EXPECT_GT(found.size(), 100u);
  EXPECT_EQ(found, expected);
}

TEST(SelfIntersections, RandomSoupsMatchTheExactReference) {
  std::mt19937 rng(20261127);
  std::size_t total = 0;
  for (int round = 0; round < 30; ++round) {
    const bool grid = round % 2 == 0;
    const int corners = round % 3 == 0 ? 4 : 3;
    std::uniform_int_distribution<int> cell(0, 3);
    std::uniform_real_distribution<double> anywhere(0, 1);
    Mesh mesh;
    const int vertices = grid ? 24 : 40;
    for (int v = 0; v < vertices; ++v)
      mesh.vertices.push_back(grid ? Vec3d{cell(rng) / 3.0, cell(rng) / 3.0, cell(rng) / 3.0}
                                   : Vec3d{anywhere(rng), anywhere(rng), anywhere(rng)});
    std::uniform_int_distribution<std::uint32_t> pick(0, vertices - 1);
    for (int f = 0; f < 30; ++f) {
      if (corners == 3) {
        mesh.add_face({pick(rng), pick(rng), pick(rng)});
      } else {
        mesh.add_face({pick(rng), pick(rng), pick(rng), pick(rng)});
      }
    }
    SCOPED_TRACE("round " + std::to_string(round));
    expect_self_intersections_match_reference(mesh);
    total += find_self_intersections(mesh).pairs;
  }
  EXPECT_GT(total, 0u);  // the soups do intersect: the comparison is not of empty lists
}

// The small real meshes of tests/data/meshes against the exact reference (which tests every pair
// of triangles whose boxes overlap, so only the meshes of a few thousand faces).
TEST(SelfIntersections, SmallRealMeshesMatchTheExactReference) {
  for (const char* name : {"/npm/teapot.obj", "/octave-matgeom/dodecahedron.ply",
                           "/assimp-testmodels/cube_binary.ply"}) {
    const Mesh mesh = read_mesh(std::string(PGAMESH_SHARED_MESHES_DIR) + name);
    SCOPED_TRACE(name);
    expect_self_intersections_match_reference(mesh);
  }
}
#endif

}  // namespace pgamesh
