// Boundary sums against closed forms: an axis-aligned box and a tetrahedron (pyramid reference
// worked example, with the corrected figures of docs/conventions.md §17).
#include <gtest/gtest.h>

#include "pgamesh/geometry/body_moments.hpp"

using namespace pgamesh;

namespace {

// Box [0,a]×[0,b]×[0,c], 12 outward CCW triangles, about the reference point ref.
BoundarySums box_sums(double a, double b, double c, Vec3d ref) {
  const Vec3d v[8] = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                      {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  BoundarySums s;
  for (const auto& q : quads) {
    add_triangle(s, v[q[0]] - ref, v[q[1]] - ref, v[q[2]] - ref);
    add_triangle(s, v[q[0]] - ref, v[q[2]] - ref, v[q[3]] - ref);
  }
  return s;
}

}  // namespace

TEST(BodyMoments, BoxClosedForm) {
  const double a = 2, b = 3, c = 5;
  for (Vec3d ref : {Vec3d{0, 0, 0}, Vec3d{1, 1.5, 2.5}, Vec3d{-7, 4, 100}}) {
    const BodyMoments m = body_moments(box_sums(a, b, c, ref));
    EXPECT_DOUBLE_EQ(m.volume, a * b * c);
    EXPECT_DOUBLE_EQ(m.area, 2 * (a * b + b * c + c * a));
    EXPECT_NEAR(m.gap_area, 0, 1e-12);
    const Vec3d com = centroid(m) + ref;
    EXPECT_NEAR(com.x, a / 2, 1e-13);
    EXPECT_NEAR(com.y, b / 2, 1e-13);
    EXPECT_NEAR(com.z, c / 2, 1e-13);
    // Central inertia of a box at density 1: m/12 (b² + c²), ... and no products of inertia.
    const Mat3 ic = inertia_from_second_moment(central_second_moment(m), 1.0);
    const double mass = a * b * c;
    EXPECT_NEAR(ic[0][0], mass / 12 * (b * b + c * c), 1e-11);
    EXPECT_NEAR(ic[1][1], mass / 12 * (a * a + c * c), 1e-11);
    EXPECT_NEAR(ic[2][2], mass / 12 * (a * a + b * b), 1e-11);
    EXPECT_NEAR(ic[0][1], 0, 1e-11);
    EXPECT_NEAR(ic[1][2], 0, 1e-11);
    EXPECT_NEAR(ic[0][2], 0, 1e-11);
  }
}

TEST(BodyMoments, OpenBoxGapIsMissingFaceArea) {
  // The box without its top face: the gap ½‖ΣF‖ is exactly the area of the coplanar hole
  // (Cor. 4.1).
  const double a = 2, b = 3, c = 5;
  const Vec3d v[8] = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                      {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
  const int quads[5][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  BoundarySums s;
  for (const auto& q : quads) {
    add_triangle(s, v[q[0]], v[q[1]], v[q[2]]);
    add_triangle(s, v[q[0]], v[q[2]], v[q[3]]);
  }
  EXPECT_DOUBLE_EQ(body_moments(s).gap_area, a * b);
}

TEST(BodyMoments, PyramidReferenceExample) {
  // Pyramid reference §3 (eqs. 26–35) corrected as in docs/conventions.md §17: the wedge
  // (o, A, B, C), density 10⁻⁵, V = 4000/3, c = (10, 6.25, 2), inertia about the origin and
  // about c.
  const Vec3d A{40, 0, 0}, B{0, 25, 0}, C{0, 0, 8};
  BoundarySums s;
  add_triangle(s, A, B, C);
  const BodyMoments m = body_moments(s);
  const double rho = 10e-6;
  EXPECT_DOUBLE_EQ(m.volume, 4000.0 / 3);
  const Vec3d c = centroid(m);
  EXPECT_DOUBLE_EQ(c.x, 10);
  EXPECT_DOUBLE_EQ(c.y, 6.25);
  EXPECT_DOUBLE_EQ(c.z, 2);
  const Mat3 io = inertia_from_second_moment(m.second, rho);
  const Mat3 io_expected = {{{0.91866666666666667, -2.0 / 3, -0.21333333333333333},
                             {-2.0 / 3, 2.2186666666666667, -0.13333333333333333},
                             {-0.21333333333333333, -0.13333333333333333, 2.9666666666666667}}};
  const Mat3 ic = inertia_from_second_moment(central_second_moment(m), rho);
  const Mat3 ic_expected = {{{0.3445, 1.0 / 6, 0.053333333333333333},
                             {1.0 / 6, 0.832, 0.033333333333333333},
                             {0.053333333333333333, 0.033333333333333333, 1.1125}}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(io[i][j], io_expected[i][j], 1e-14) << i << "," << j;
      EXPECT_NEAR(ic[i][j], ic_expected[i][j], 1e-14) << i << "," << j;
    }
  // The origin tensor is the central one shifted by m·parallel(c) (pyramid reference eq. 33).
  const Mat3 shift = parallel_axis(c);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(io[i][j], ic[i][j] + rho * m.volume * shift[i][j], 1e-14);
}

TEST(BodyMoments, CarrierEqualsJoinOfPoints) {
  const Vec3d a{1.5, -2, 0.25}, b{3, 1, -1}, c{-0.5, 2, 4};
  const auto f = triangle_carrier(a, b, c);
  const auto j = pga3::join(pga3::point(a), pga3::point(b), pga3::point(c));
  EXPECT_DOUBLE_EQ(f.e1, j.e1);
  EXPECT_DOUBLE_EQ(f.e2, j.e2);
  EXPECT_DOUBLE_EQ(f.e3, j.e3);
  EXPECT_NEAR(f.e0, j.e0, 1e-14);
  EXPECT_NEAR(origin_join(f), dot(a, cross(b, c)), 1e-14);  // o ∨ F = det(a, b, c)
}

TEST(BodyMoments, BentQuadHasItsFanAreaAndIsReportedBent) {
  // The unit square with corner 2 lifted by h: fan triangles (c0, c1, c2) and (c0, c2, c3) have
  // normals (0, −h, 1) and (−h, 0, 1), so the fan's area is √(1 + h²); their sum N = (−h, −h, 2)
  // puts corners 1 and 3 at height −h/‖N‖ and corners 0 and 2 at 0, a slab of half-width
  // h / (2‖N‖); the face's size is ‖c2 − c0‖ = √(2 + h²).
  for (double h : {0.5, 1e-3}) {
    SCOPED_TRACE(h);
    const Vec3d v[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, h}, {0, 1, 0}};
    BoundarySums s;
    add_polygon(s, v, 4);
    const double fan = std::sqrt(1 + h * h);
    EXPECT_NEAR(s.area2 / 2, fan, 4e-16 * fan);
    // The fan's area, not the area of its projection onto the mean plane, ½‖N‖.
    EXPECT_GT(s.area2 / 2 - std::sqrt(2 * h * h + 4) / 2, 0.1 * h * h);
    const double deviation = h / (2 * std::sqrt(2 * h * h + 4));
    EXPECT_EQ(s.planarity.nonplanar_faces, 1u);
    EXPECT_NEAR(s.planarity.largest_deviation, deviation, 1e-15 * deviation);
    EXPECT_NEAR(s.planarity.largest_relative, deviation / std::sqrt(2 + h * h), 1e-15 * deviation);
  }
}

TEST(BodyMoments, NearlyFlatQuadIsNotReportedBent) {
  // Lifted by 1e-8 of its size, the quad is within face_planarity_tolerance of flat.
  const Vec3d v[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-8}, {0, 1, 0}};
  BoundarySums s;
  add_polygon(s, v, 4);
  EXPECT_EQ(s.planarity.nonplanar_faces, 0u);
  EXPECT_NEAR(s.area2 / 2, 1, 1e-15);
}

TEST(BodyMoments, ConcavePolygonAreaIsExactAndPlanarityMerges) {
  // An L-shaped hexagon (area 3) whose fan from its first corner folds back over the reflex
  // corner: the folded triangle counts negatively, so the area is exactly 3 (every fan area is an
  // integer here), where Σ ‖F_i‖ would give 4.
  const Vec3d l[6] = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
  BoundarySums s;
  add_polygon(s, l, 6);
  EXPECT_EQ(s.area2, 6);
  EXPECT_EQ(s.volume6, 0);
  EXPECT_EQ(s.planarity.nonplanar_faces, 0u);
  // Sums of faces merge their planarity by count and maximum, in either order.
  const Vec3d bent[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}};
  const Vec3d more[4] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0.1}, {0, 2, 0}};
  BoundarySums a, b;
  add_polygon(a, bent, 4);
  add_polygon(b, more, 4);
  BoundarySums ab = s, ba = s;
  ab += a;
  ab += b;
  ba += b;
  ba += a;
  EXPECT_EQ(ab.planarity.nonplanar_faces, 2u);
  EXPECT_EQ(ab.planarity.largest_relative, a.planarity.largest_relative);
  EXPECT_EQ(ab.planarity.largest_deviation, ba.planarity.largest_deviation);
  EXPECT_EQ(ab.planarity.largest_relative, ba.planarity.largest_relative);
}
