// Topology fields of every case of golden/mesh_props.json (closed, boundary and non-manifold edges,
// orientation, vertices after the weld, gap, carrier sum, signed volume about the origin of the
// open cases), and the identities that tie the boundary loops to the gap (Stokes: the loops'
// vector areas add up to ½ Σ F's normal part).
#include <gtest/gtest.h>

#include "pgamesh/geometry/gap.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/golden.hpp"
#include "support/golden_mesh.hpp"

namespace pgamesh {
namespace {

using test::json;
using test::near_group;
using test::near_scalar;

TEST(TopologyGolden, MeshPropsTopologyFields) {
  const json file = test::load_golden("mesh_props.json");
  int checked = 0;
  for (const auto& c : file["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    const json& e = c["expected"];
    const test::Tolerance tol = test::tolerance_of(file, c);
    const TopologyReport r = analyze_topology(test::golden_case_mesh(c["input"]));
    EXPECT_EQ(r.triangles, e["triangles"].get<std::size_t>());
    EXPECT_EQ(r.vertices, e["vertices"].get<std::size_t>());
    EXPECT_EQ(r.boundary_edges, e["boundary_edges"].get<std::size_t>());
    EXPECT_EQ(r.nonmanifold_edges, e["nonmanifold_edges"].get<std::size_t>());
    EXPECT_EQ(r.orientation_consistent, e["orientation_consistent"].get<bool>());
    EXPECT_EQ(r.closed, e["closed"].get<bool>());
    EXPECT_EQ(r.volume_valid, e["closed"].get<bool>());
    EXPECT_TRUE(near_scalar(r.area, e["area"].get<double>(), tol));
    EXPECT_TRUE(near_scalar(r.gap_area, e["gap_area"].get<double>(), tol));
    const auto cs = test::blades(e["carrier_sum"]);
    EXPECT_TRUE(near_group({r.carrier_sum.e0, r.carrier_sum.e1, r.carrier_sum.e2, r.carrier_sum.e3},
                           {cs.count("e0") ? cs.at("e0") : 0.0, cs.count("e1") ? cs.at("e1") : 0.0,
                            cs.count("e2") ? cs.at("e2") : 0.0, cs.count("e3") ? cs.at("e3") : 0.0},
                           tol));
    if (e.contains("volume")) {
      EXPECT_TRUE(near_scalar(r.volume, e["volume"].get<double>(), tol));
      EXPECT_EQ(r.volume_min, r.volume_max);
    }
    if (e.contains("signed_volume_about_origin")) {
      // V(q) = V(ref) − (1/3) G·(q − ref) (geometry/gap.hpp). The golden files' generator
      // (docs/conventions.md §18) accumulates about the mesh's first vertex and does not move the
      // volume of an open mesh, so its "signed_volume_about_origin" is V(vertex 0) (the origin
      // itself for the cubes); V(origin) is −e0/6 of the golden carrier sum.
      const Mesh m = test::golden_case_mesh(c["input"]);
      auto volume_at = [&](Vec3d q) {
        return r.volume - dot(r.gap_vector, q - r.reference_point) / 3;
      };
      EXPECT_TRUE(near_scalar(volume_at(m.vertices[0]),
                              e["signed_volume_about_origin"].get<double>(), tol));
      EXPECT_TRUE(near_scalar(volume_at(Vec3d{}), -cs.at("e0") / 6, tol));
      EXPECT_LE(r.volume_min, volume_at(m.vertices[0]));
      EXPECT_GE(r.volume_max, volume_at(m.vertices[0]));
      EXPECT_LT(r.volume_min, r.volume_max);
    }
    // Loops: every boundary edge in exactly one closed loop; the loops' vector areas add up to the
    // gap vector, so the gap is at most the sum of the loop areas (equal for one planar hole).
    std::size_t loop_edges = 0;
    Vec3d loop_sum{};
    for (const BoundaryLoop& loop : r.boundary_loops) {
      EXPECT_TRUE(loop.closed);
      loop_edges += loop.half_edges.size();
      loop_sum += loop.vector_area;
    }
    EXPECT_EQ(loop_edges, r.boundary_edges);
    const double scale = std::max(1.0, r.gap_area);
    EXPECT_NEAR(loop_sum.x, r.gap_vector.x, 1e-12 * scale);
    EXPECT_NEAR(loop_sum.y, r.gap_vector.y, 1e-12 * scale);
    EXPECT_NEAR(loop_sum.z, r.gap_vector.z, 1e-12 * scale);
    EXPECT_GE(r.loops_area, r.gap_area - 1e-12 * scale);
    ++checked;
  }
  EXPECT_EQ(checked, 13);
}

TEST(TopologyGolden, EllipsoidWithFiveHolesHasFiveTriangularLoops) {
  // The five removed faces share no edge (golden case ellipsoid_L3_holes: 15 boundary edges), so
  // each leaves a triangular loop whose area is the removed face's. Faces 0 and 1 share a vertex:
  // there the two holes touch, and the tracing splits the figure-eight into two loops.
  const Mesh full = read_mesh(std::string(PGAMESH_GOLDEN_DIR) + "/meshes/ellipsoid_L3.obj");
  json input = {{"mesh_file", "meshes/ellipsoid_L3.obj"}, {"remove_faces", {0, 1, 500, 900, 1201}}};
  const TopologyReport r = analyze_topology(test::golden_case_mesh(input));
  ASSERT_EQ(r.boundary_loops.size(), 5u);
  double removed_area = 0;
  for (std::size_t f : {0, 1, 500, 900, 1201}) {
    const Vec3d a = full.vertices[full.face(f)[0]], b = full.vertices[full.face(f)[1]],
                c = full.vertices[full.face(f)[2]];
    removed_area += 0.5 * length(cross(b - a, c - a));
  }
  EXPECT_NEAR(r.loops_area, removed_area, 1e-14 * removed_area);
  for (const BoundaryLoop& loop : r.boundary_loops) EXPECT_EQ(loop.half_edges.size(), 3u);
}

}  // namespace
}  // namespace pgamesh
