// Welding: exact (bitwise, −0 == +0), deterministic numbering, and the tolerance weld on a mesh
// whose seams were jittered.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"
#include "topology_test_meshes.hpp"

namespace pgamesh {
namespace {

TEST(Weld, ExactWeldMergesBitwiseEqualAndBothZeros) {
  const std::vector<Vec3d> v = {
      {0.0, 1.0, 2.0}, {-0.0, 1.0, 2.0}, {0.0, 1.0, std::nextafter(2.0, 3.0)},
      {5.0, 5.0, 5.0}, {0.0, 1.0, 2.0},  {5.0, 5.0, 5.0}};
  const WeldMap w = weld_map(v);
  ASSERT_EQ(w.welded_count(), 3u);
  EXPECT_EQ(w.merged, 3u);
  EXPECT_EQ(w.max_moved, 0.0);
  // Numbered by first appearance, represented by the first input vertex of each class.
  EXPECT_EQ(w.to_welded, (std::vector<std::uint32_t>{0, 0, 1, 2, 0, 2}));
  EXPECT_EQ(w.representative, (std::vector<std::uint32_t>{0, 2, 3}));
}

TEST(Weld, ManyVerticesGrowTheTableAndStayExact) {
  // 200 000 distinct points, each repeated 3 times in a shuffled order: the table grows past its
  // first size and every repeat must find its class.
  std::vector<Vec3d> unique;
  for (int i = 0; i < 200000; ++i)
    unique.push_back({std::sin(i * 0.001), std::cos(i * 0.37), i * 1e-3});
  std::vector<std::uint32_t> order;
  for (std::uint32_t i = 0; i < unique.size(); ++i)
    for (int r = 0; r < 3; ++r) order.push_back(i);
  std::mt19937 rng(7);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<Vec3d> v;
  for (std::uint32_t i : order) v.push_back(unique[i]);
  const WeldMap w = weld_map(v);
  EXPECT_EQ(w.welded_count(), unique.size());
  EXPECT_EQ(w.merged, 2 * unique.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    ASSERT_EQ(v[w.representative[w.to_welded[i]]], v[i]);
    ASSERT_LE(w.representative[w.to_welded[i]], i);
  }
}

TEST(Weld, WeldedMeshRenumbersCornersOnly) {
  const WeldResult r = weld(test::unshared(test::unit_cube()));
  EXPECT_EQ(r.mesh.vertices.size(), 8u);
  EXPECT_EQ(r.mesh.face_count(), 12u);
  EXPECT_EQ(r.map.merged, 28u);
  const Mesh cube = test::unit_cube();
  for (std::size_t c = 0; c < cube.corners.size(); ++c)
    EXPECT_EQ(r.mesh.vertices[r.mesh.corners[c]], cube.vertices[cube.corners[c]]);
}

TEST(Weld, RejectsBadTolerance) {
  const std::vector<Vec3d> v = {{0, 0, 0}};
  EXPECT_THROW(weld_map(v, -1.0), std::invalid_argument);
  EXPECT_THROW(weld_map(v, std::nan("")), std::invalid_argument);
  EXPECT_THROW(weld_map(v, INFINITY), std::invalid_argument);
}

// A cube whose triangles carry their own vertex copies, each moved by up to `jitter` per axis: the
// exact weld sees a triangle soup, the tolerance weld the closed cube again.
Mesh jittered_cube(double jitter, unsigned seed) {
  Mesh m = test::unshared(test::unit_cube());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (auto& p : m.vertices) p += Vec3d{u(rng), u(rng), u(rng)};
  return m;
}

TEST(Weld, ToleranceWeldClosesJitteredSeams) {
  const double jitter = 1e-7;
  const Mesh m = jittered_cube(jitter, 42);
  const TopologyReport exact = analyze_topology(m);
  EXPECT_EQ(exact.vertices, 36u);
  EXPECT_EQ(exact.boundary_edges, 36u);
  EXPECT_EQ(exact.components, 12u);
  EXPECT_FALSE(exact.closed);

  TopologyOptions opt;
  opt.weld_tolerance = 1e-5;
  const TopologyReport r = analyze_topology(m, opt);
  EXPECT_EQ(r.vertices, 8u);
  EXPECT_EQ(r.merged_vertices, 28u);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.weld_tolerance, 1e-5);
  // Every copy moved to the first copy of its corner: at most the diagonal of the jitter box twice.
  EXPECT_GT(r.weld_max_moved, 0.0);
  EXPECT_LE(r.weld_max_moved, 2 * std::sqrt(3.0) * jitter);
  EXPECT_NEAR(r.volume, 1.0, 1e-5);
  EXPECT_LT(r.gap_area, 1e-14);  // welded: the carriers cancel up to rounding
}

TEST(Weld, ToleranceWeldIsLeaderClusteringNotChaining) {
  // 0, 0.6, 1.2 with tolerance 1: 0.6 joins 0; 1.2 is 1.2 from the leader 0 and stays apart.
  const std::vector<Vec3d> v = {{0, 0, 0}, {0.6, 0, 0}, {1.2, 0, 0}, {1.9, 0, 0}};
  const WeldMap w = weld_map(v, 1.0);
  EXPECT_EQ(w.to_welded, (std::vector<std::uint32_t>{0, 0, 1, 1}));
  EXPECT_DOUBLE_EQ(w.max_moved, 0.7);
}

TEST(Weld, ToleranceWeldPicksTheEarliestLeaderAcrossCells) {
  // Leaders 0 at x = 0.95 and 1 at x = 2.05 (cells 0 and 2 for tolerance 1); the vertex at 1.5
  // (cell 1) is within 1 of both and must join the earlier one.
  const std::vector<Vec3d> v = {{0.95, 0, 0}, {2.05, 0, 0}, {1.5, 0, 0}};
  const WeldMap w = weld_map(v, 1.0);
  EXPECT_EQ(w.to_welded, (std::vector<std::uint32_t>{0, 1, 0}));
}

}  // namespace
}  // namespace pgamesh
