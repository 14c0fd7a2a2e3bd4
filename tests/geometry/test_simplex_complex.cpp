// Complexes measured from their boundary (Thm 4.2, Cor. 4.1, eq. 5.3): 2-D polygons (golden,
// non-convex, self-overlapping, with holes), 3-D meshes against the golden mesh properties and the
// PGA3 fast path (body_moments), tetrahedral complexes, and 4-D complexes of 5-cells.
#include <gtest/gtest.h>

#include <random>

#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/complex.hpp"
#include "pgamesh/geometry/polygon2d.hpp"
#include "support/golden.hpp"
#include "support/golden_mesh.hpp"

using namespace pgamesh;
using geometry::Vec2;
using test::json;

namespace {

struct TriMesh {
  std::vector<pgad::Vec<3>> vertices;
  std::vector<int> faces;  // 3 per triangle
};

// The golden case as a triangle mesh of pgad points (the golden meshes are triangulated).
TriMesh mesh_of_case(const json& input) {
  const Mesh mesh = test::golden_case_mesh(input);
  TriMesh m;
  for (const Vec3d& v : mesh.vertices) m.vertices.push_back({v.x, v.y, v.z});
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    EXPECT_EQ(mesh.face_size(f), 3u) << "face " << f;
    for (std::size_t k = 0; k < 3; ++k) m.faces.push_back(static_cast<int>(mesh.face(f)[k]));
  }
  return m;
}

pgad::Vec<3> bbox_centre(const TriMesh& m) {
  pgad::Vec<3> lo = m.vertices[0], hi = m.vertices[0];
  for (const auto& v : m.vertices)
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], v[i]);
      hi[i] = std::max(hi[i], v[i]);
    }
  return {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
}

}  // namespace

// ---- 2-D
// ------------------------------------------------------------------------------------------

TEST(Polygon2d, GoldenNonConvexPolygon) {
  const json file = test::load_golden("pga_basics.json");
  for (const auto& c : file["cases"]) {
    if (c["id"] != "pga2_nonconvex_polygon") continue;
    std::vector<Vec2> ring;
    for (const auto& p : c["input"]["polygon"])
      ring.push_back({p[0].get<double>(), p[1].get<double>()});
    const std::vector<std::vector<Vec2>> rings = {ring};
    const auto m = geometry::polygon_measures(rings);
    const auto t = test::tolerance_of(file, c);
    EXPECT_TRUE(test::near_scalar(m.signed_area, c["expected"]["area"].get<double>(), t));
    EXPECT_TRUE(test::near_group({m.centroid[0], m.centroid[1]},
                                 test::flatten(c["expected"]["centroid"]), t));
    return;
  }
  FAIL() << "pga2_nonconvex_polygon missing";
}

TEST(Polygon2d, HolesOrientationAndSelfOverlap) {
  // 4×4 square (CCW) with a 2×1 hole (CW) at [1,3]×[1,2]: area 14, centroid by moments:
  // (16·(2,2) − 2·(2,1.5)) / 14.
  const std::vector<std::vector<Vec2>> holed = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                                                {{1, 1}, {1, 2}, {3, 2}, {3, 1}}};
  auto m = geometry::polygon_measures(holed);
  EXPECT_DOUBLE_EQ(m.signed_area, 14.0);
  EXPECT_NEAR(m.centroid[0], 2.0, 1e-15);
  EXPECT_NEAR(m.centroid[1], (32.0 - 3.0) / 14.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.perimeter, 16.0 + 6.0);
  // clockwise: the same magnitude, negative
  const std::vector<std::vector<Vec2>> cw = {{{0, 0}, {0, 4}, {4, 4}, {4, 0}}};
  EXPECT_DOUBLE_EQ(geometry::polygon_measures(cw).signed_area, -16.0);
  // L shape (non-convex): unit squares at (0,0), (1,0), (0,1): area 3, centroid (5/6, 5/6)
  const std::vector<std::vector<Vec2>> l = {{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  m = geometry::polygon_measures(l);
  EXPECT_DOUBLE_EQ(m.signed_area, 3.0);
  EXPECT_NEAR(m.centroid[0], 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(m.centroid[1], 5.0 / 6.0, 1e-15);
  // bow tie (figure eight): two triangles of opposite winding cancel: signed area 0
  const std::vector<std::vector<Vec2>> bow = {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
  EXPECT_NEAR(geometry::polygon_measures(bow).signed_area, 0.0, 1e-15);
  // a square traversed twice counts twice (winding number 2)
  const std::vector<std::vector<Vec2>> twice = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  EXPECT_DOUBLE_EQ(geometry::polygon_measures(twice).signed_area, 2.0);
}

TEST(Polygon2d, PentagramWindsTheCentreTwice) {
  // {5/2} star on the unit circle: area = outer pentagon ∪ … with the inner pentagon counted
  // twice; closed form: A = 5/2 sin(144°) ·(winding-weighted) = (5/2) sin(4π/5) for the star chain
  // v_i → v_(i+2): ½ Σ v_i × v_(i+2) = (5/2) sin(4π/5).
  std::vector<Vec2> star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * M_PI * (2 * i) / 5;
    star.push_back({std::cos(a), std::sin(a)});
  }
  const std::vector<std::vector<Vec2>> rings = {star};
  const auto m = geometry::polygon_measures(rings);
  EXPECT_NEAR(m.signed_area, 2.5 * std::sin(4 * M_PI / 5), 1e-15);
  EXPECT_NEAR(m.centroid[0], 0.0, 1e-15);
  EXPECT_NEAR(m.centroid[1], 0.0, 1e-15);
}

TEST(Polygon2d, GapOfAnOpenPolyline) {
  // Three sides of the unit square: the gap is the missing side, length 1 (Cor. 4.1, k = 2).
  const std::vector<pgad::Vec<2>> v = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<int> edges = {0, 1, 1, 2, 2, 3};
  const auto s = geometry::boundary_sums<2>({v, edges, 2}, {0.5, 0.5});
  EXPECT_NEAR(geometry::gap_magnitude(s), 1.0, 1e-15);
}

// ---- 3-D
// ------------------------------------------------------------------------------------------

TEST(Complex3d, GoldenMeshPropertiesAndFastPath) {
  const json file = test::load_golden("mesh_props.json");
  int cases = 0;
  for (const auto& c : file["cases"]) {
    const TriMesh m = mesh_of_case(c["input"]);
    const json& e = c["expected"];
    const auto t = test::tolerance_of(file, c);
    const geometry::BoundaryChain<3> chain{m.vertices, m.faces, 3};
    if (e.contains("volume")) {
      const auto s = geometry::boundary_sums<3>(chain, bbox_centre(m));
      EXPECT_TRUE(test::near_scalar(geometry::signed_volume(s), e["volume"].get<double>(), t))
          << c["id"];
      const auto com = geometry::center_of_mass(s);
      EXPECT_TRUE(test::near_group({com[0], com[1], com[2]}, test::flatten(e["center_of_mass"]), t))
          << c["id"];
      EXPECT_TRUE(
          test::near_scalar(geometry::complex_magnitude(s), std::abs(e["volume"].get<double>()), t))
          << c["id"];
      EXPECT_NEAR(geometry::gap_magnitude(s), e["gap_area"].get<double>(), 1e-9) << c["id"];
      // the PGA3 fast path on the same triangles, about the same reference point
      BoundarySums fast;
      const auto o = bbox_centre(m);
      for (std::size_t f = 0; f < m.faces.size(); f += 3) {
        Vec3d p[3];
        for (std::size_t i = 0; i < 3; ++i) {
          const auto& v = m.vertices[static_cast<std::size_t>(m.faces[f + i])];
          p[i] = Vec3d{v[0] - o[0], v[1] - o[1], v[2] - o[2]};
        }
        add_triangle(fast, p[0], p[1], p[2]);
      }
      const BodyMoments bm = body_moments(fast);
      EXPECT_NEAR(geometry::signed_volume(s), bm.volume, 1e-12 * std::abs(bm.volume)) << c["id"];
      const Vec3d fc = centroid(bm);
      EXPECT_NEAR(com[0], fc.x + o[0], 1e-12 * (1 + std::abs(com[0]))) << c["id"];
      EXPECT_NEAR(com[1], fc.y + o[1], 1e-12 * (1 + std::abs(com[1]))) << c["id"];
      EXPECT_NEAR(com[2], fc.z + o[2], 1e-12 * (1 + std::abs(com[2]))) << c["id"];
    } else {
      // open meshes: the golden carrier sum and signed volume are about the origin
      const auto s = geometry::boundary_sums<3>(chain, {0, 0, 0});
      EXPECT_TRUE(test::near_scalar(geometry::gap_magnitude(s), e["gap_area"].get<double>(), t))
          << c["id"];
      // o ∨ Σ F / 6 about the origin is −(e0 of the carrier sum)/6 …
      EXPECT_TRUE(
          test::near_scalar(geometry::signed_volume(s), -e["carrier_sum"].value("e0", 0.0) / 6, t))
          << c["id"];
      // … while the golden files' generator (docs/conventions.md §18) takes the golden
      // "signed_volume_about_origin" about the FIRST VERTEX (the same as the origin for the cubes)
      const auto s0 = geometry::boundary_sums<3>(chain, m.vertices[0]);
      EXPECT_TRUE(test::near_scalar(geometry::signed_volume(s0),
                                    e["signed_volume_about_origin"].get<double>(), t))
          << c["id"];
      const json& cs = e["carrier_sum"];
      EXPECT_TRUE(test::near_group(
          {s.carrier_sum[1], s.carrier_sum[2], s.carrier_sum[4], s.carrier_sum[8]},
          {cs.value("e0", 0.0), cs.value("e1", 0.0), cs.value("e2", 0.0), cs.value("e3", 0.0)}, t))
          << c["id"];
    }
    ++cases;
  }
  EXPECT_GE(cases, 12);
}

TEST(Complex3d, TetrahedralComplexOfACube) {
  // The unit cube as 6 tetrahedra around the diagonal 0–7 (Kuhn triangulation): the interior sum
  // Σ ‖S(σ3)‖/3! equals the boundary form (Thm 4.2) and the volume 1.
  const std::vector<pgad::Vec<3>> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                       {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  const std::vector<int> tets = {0, 1, 3, 7, 0, 1, 5, 7, 0, 2, 3, 7,
                                 0, 2, 6, 7, 0, 4, 5, 7, 0, 4, 6, 7};
  EXPECT_NEAR(geometry::magnitude_of_simplices<3>(v, tets, 4), 1.0, 1e-15);
  const std::vector<int> faces = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                  2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  const auto s = geometry::boundary_sums<3>({v, faces, 3}, {0.3, -0.2, 0.9});
  EXPECT_NEAR(geometry::complex_magnitude(s), 1.0, 1e-15);
  EXPECT_NEAR(geometry::signed_volume(s), 1.0, 1e-15);
  EXPECT_NEAR(geometry::gap_magnitude(s), 0.0, 1e-15);
  const auto com = geometry::center_of_mass(s);
  for (double x : com) EXPECT_NEAR(x, 0.5, 1e-15);
}

// ---- 4-D
// ------------------------------------------------------------------------------------------

namespace {
// Appends the oriented boundary ∂σ4 = Σ (−1)^i [v0 … v̂i … v4] of a 4-simplex; a negative sign is a
// swap of the first two vertices of the facet.
void add_boundary_of_4simplex(std::vector<int>& facets, const std::array<int, 5>& s) {
  for (int skip = 0; skip < 5; ++skip) {
    std::vector<int> f;
    for (int i = 0; i < 5; ++i)
      if (i != skip) f.push_back(s[static_cast<std::size_t>(i)]);
    if (skip % 2) std::swap(f[0], f[1]);
    facets.insert(facets.end(), f.begin(), f.end());
  }
}
}  // namespace

TEST(Complex4d, BoundaryOfTwoFiveCellsSharingAFacet) {
  // Two 5-cells glued along the facet (1,2,3,4); the shared facet cancels in the boundary sum, so
  // volume, COM and magnitude come from the outer boundary (Thm 4.2, eq. 5.3).
  const std::vector<pgad::Vec<4>> v = {{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0},
                                       {0, 0, 1, 0}, {0, 0, 0, 1}, {1, 1, 1, 1}};
  const std::array<int, 5> a = {0, 1, 2, 3, 4}, b = {5, 2, 1, 3, 4};  // b oriented like a
  const std::vector<pgad::Vec<4>> va = {v[0], v[1], v[2], v[3], v[4]};
  const std::vector<pgad::Vec<4>> vb = {v[5], v[2], v[1], v[3], v[4]};
  const double sa = geometry::carrier<4>(va).c[0] / 24, sb = geometry::carrier<4>(vb).c[0] / 24;
  ASSERT_GT(sa, 0);
  ASSERT_GT(sb, 0);
  std::vector<int> facets;
  add_boundary_of_4simplex(facets, a);
  add_boundary_of_4simplex(facets, b);
  const auto s = geometry::boundary_sums<4>({v, facets, 4}, {0.2, 0.2, 0.2, 0.2});
  EXPECT_NEAR(geometry::signed_volume(s), sa + sb, 1e-15);
  EXPECT_NEAR(geometry::complex_magnitude(s), sa + sb, 1e-15);
  EXPECT_NEAR(geometry::gap_magnitude(s), 0.0, 1e-14);
  // COM: volume-weighted average of the vertex centroids of the two cells
  const auto com = geometry::center_of_mass(s);
  for (std::size_t i = 0; i < 4; ++i) {
    double ca = 0, cb = 0;
    for (const auto& p : va) ca += p[i] / 5;
    for (const auto& p : vb) cb += p[i] / 5;
    EXPECT_NEAR(com[i], (sa * ca + sb * cb) / (sa + sb), 1e-15);
  }
  // the interior form of Thm 4.2
  std::vector<int> cells(a.begin(), a.end());
  cells.insert(cells.end(), b.begin(), b.end());
  EXPECT_NEAR(geometry::magnitude_of_simplices<4>(v, cells, 5), sa + sb, 1e-15);
}

TEST(Complex4d, BadIndicesAreRejected) {
  const std::vector<pgad::Vec<4>> v = {{0, 0, 0, 0}};
  const std::vector<int> facets = {0, 0, 0, 7};
  EXPECT_THROW(geometry::boundary_sums<4>({v, facets, 4}, {}), std::invalid_argument);
  const std::vector<int> ragged = {0, 0, 0};
  EXPECT_THROW(geometry::boundary_sums<4>({v, ragged, 4}, {}), std::invalid_argument);
}
