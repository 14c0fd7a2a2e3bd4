// Closed forms, far-from-origin quadrics, classification, fitting and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "pgamesh/models/quadric_convert.hpp"

using namespace pgamesh;
using quadric::Quadric;
using quadric::QuadricType;

TEST(QuadricCore, TangentPlanesOfAxisAlignedEllipsoid) {
  // x²/4 + y²/9 + z² = 1: at (x0,y0,z0) the plane is x x0/4 + y y0/9 + z z0 = 1 (times 2).
  const Quadric q = quadric::ellipsoid({0, 0, 0}, {2, 3, 1});
  const double s = std::sqrt(1.0 / 3);
  for (const Vec3d& p : {Vec3d{2, 0, 0}, Vec3d{0, -3, 0}, Vec3d{2 * s, 3 * s, s}}) {
    const auto pl = quadric::tangent_plane(q, p);
    EXPECT_NEAR(pl[0], 2 * p[0] / 4, 1e-15);
    EXPECT_NEAR(pl[1], 2 * p[1] / 9, 1e-15);
    EXPECT_NEAR(pl[2], 2 * p[2], 1e-15);
    EXPECT_NEAR(pl[3], -2, 1e-14);
    const Vec3d n = quadric::unit_normal(q, p);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-15);
  }
}

TEST(QuadricCore, LineSphereAndParaboloid) {
  const Quadric s = quadric::sphere({1, 2, 3}, 2);
  auto h = quadric::intersect_line(s, {-5, 2, 3}, {2, 0, 0});  // t = 2, 4 → x = −1, 3
  ASSERT_EQ(h.kind, quadric::LineKind::two);
  EXPECT_NEAR(h.t[0], 2, 1e-14);
  EXPECT_NEAR(h.t[1], 4, 1e-14);
  EXPECT_NEAR(h.points[1][0], 3, 1e-14);
  h = quadric::intersect_line(s, {3, 0, 3}, {0, 1, 0});  // tangent at (3, 2, 3)
  ASSERT_EQ(h.kind, quadric::LineKind::tangent);
  EXPECT_NEAR(h.points[0][1], 2, 1e-14);
  h = quadric::intersect_line(s, {3.5, 0, 3}, {0, 1, 0});
  EXPECT_EQ(h.kind, quadric::LineKind::none);
  // Paraboloid z = x² + y²: the line x = 1, y = t, z = 2 meets it at t = ±1; the line z = 2x − 1,
  // y = 0 is tangent at x = 1; a vertical line meets it once.
  const Quadric p{{1, 1, 0, 0, 0, 0, 0, 0, -1, 0}};
  h = quadric::intersect_line(p, {1, 0, 2}, {0, 1, 0});
  ASSERT_EQ(h.kind, quadric::LineKind::two);
  EXPECT_NEAR(h.t[0], -1, 1e-15);
  EXPECT_NEAR(h.t[1], 1, 1e-15);
  h = quadric::intersect_line(p, {0, 0, -1}, {1, 0, 2});
  ASSERT_EQ(h.kind, quadric::LineKind::tangent);
  EXPECT_NEAR(h.t[0], 1, 1e-15);
  h = quadric::intersect_line(p, {2, 1, 0}, {0, 0, 3});
  ASSERT_EQ(h.kind, quadric::LineKind::one);
  EXPECT_NEAR(h.points[0][2], 5, 1e-14);
  // A nearly tangent line is tangent only with a tolerance.
  const double eps = 1e-13;
  h = quadric::intersect_line(s, {3 + eps, 0, 3}, {0, 1, 0});
  EXPECT_NE(h.kind, quadric::LineKind::tangent);
  h = quadric::intersect_line(s, {3 + eps, 0, 3}, {0, 1, 0}, 1e-9);
  EXPECT_EQ(h.kind, quadric::LineKind::tangent);
}

TEST(QuadricCore, FarFromOrigin) {
  const Vec3d c{1e6, -2e6, 3e6};
  const Quadric s = quadric::sphere(c, 10);
  EXPECT_EQ(quadric::classify(s, 1e-12).type, QuadricType::sphere);
  const auto h = quadric::intersect_line(s, {c[0] - 50, c[1], c[2]}, {1, 0, 0});
  ASSERT_EQ(h.kind, quadric::LineKind::two);
  EXPECT_NEAR(h.points[0][0], c[0] - 10, 1e-4);
  EXPECT_NEAR(h.points[1][0], c[0] + 10, 1e-4);
  const Vec3d n = quadric::unit_normal(s, {c[0], c[1] + 10, c[2]});
  EXPECT_NEAR(n[1], 1, 1e-9);
  // A fit of an ellipsoid placed at 1e6 recovers its surface (the fit centres the points).
  std::vector<Vec3d> pts;
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 500; ++k) {
    const double th = std::acos(2 * u(rng) - 1), ph = 2 * M_PI * u(rng);
    pts.push_back({c[0] + 3 * std::sin(th) * std::cos(ph), c[1] + 2 * std::sin(th) * std::sin(ph),
                   c[2] + std::cos(th)});
  }
  const auto f = quadric::fit(pts);
  EXPECT_LT(f.geometric_max, 1e-5);
  // The global coefficients hold this surface only to ~1e-13 of j; the local quadric is exact.
  const auto cl = quadric::classify(f.local, 1e-6);
  EXPECT_EQ(cl.type, QuadricType::ellipsoid);
  EXPECT_NEAR(cl.eigenvalues[1] / cl.eigenvalues[0], 9.0 / 4, 1e-5);
  EXPECT_NEAR(cl.eigenvalues[2] / cl.eigenvalues[0], 9.0, 1e-5);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(f.centroid[k], c[k], 0.5);
  // Translating the fitted quadric back to the origin gives the axis-aligned coefficients, to the
  // precision the coefficients keep at 1e6 (j ~ 1e13 carries only ~3 digits of the radius).
  const Quadric back = quadric::normalized(quadric::translate(f.quadric, {-c[0], -c[1], -c[2]}));
  const Quadric want = quadric::normalized(quadric::ellipsoid({0, 0, 0}, {3, 2, 1}));
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(back.k[k], want.k[k], 2e-3) << k;
}

TEST(QuadricCore, ClassifiesEveryType) {
  using T = QuadricType;
  const Quadric placed =
      quadric::translate(quadric::rotate(Quadric{{1, 2, -3, 0, 0, 0, 0, 0, 0, -1}},
                                         quadric::axis_rotation({1, 1, 0}, 0.7)),
                         {3, -1, 2});
  const std::vector<std::pair<Quadric, T>> cases = {
      {quadric::ellipsoid({1, 2, 3}, {1, 2, 3}), T::ellipsoid},
      {quadric::sphere({1, 2, 3}, 2), T::sphere},
      {Quadric{{1, 1, -1, 0, 0, 0, 0, 0, 0, -1}}, T::hyperboloid_one_sheet},
      {placed, T::hyperboloid_one_sheet},
      {Quadric{{1, 1, -1, 0, 0, 0, 0, 0, 0, 1}}, T::hyperboloid_two_sheets},
      {Quadric{{1, 1, -0.25, 0, 0, 0, 0, 0, 0, 0}}, T::cone},
      {quadric::translate(Quadric{{1, 1, -0.25, 0, 0, 0, 0, 0, 0, 0}}, {5, 6, 7}), T::cone},
      {Quadric{{1, 2, 0, 0, 0, 0, 0, 0, -1, 0}}, T::elliptic_paraboloid},
      {Quadric{{0, 0, 0, 1, 0, 0, 0, 0, -1, 0}}, T::hyperbolic_paraboloid},
      {Quadric{{1, 1, 0, 0, 0, 0, 0, 0, 0, -1}}, T::elliptic_cylinder},
      {Quadric{{1, -1, 0, 0, 0, 0, 0, 0, 0, -1}}, T::hyperbolic_cylinder},
      {Quadric{{1, 0, 0, 0, 0, 0, 0, -1, 0, 0}}, T::parabolic_cylinder},
      {Quadric{{0, 0, 0, 1, 0, 0, 0, 0, 0, 0}}, T::intersecting_planes},
      {Quadric{{1, 0, 0, 0, 0, 0, 0, 0, 0, -4}}, T::parallel_planes},
      {Quadric{{0, 0, 0, 0, 0, 0, 1, 2, 3, 4}}, T::single_plane},
      {Quadric{{1, 0, 0, 0, 0, 0, -2, 0, 0, 1}}, T::single_plane},  // (x − 1)²
      {Quadric{{1, 1, 1, 0, 0, 0, 0, 0, 0, 0}}, T::point},
      {Quadric{{1, 1, 0, 0, 0, 0, 0, 0, 0, 0}}, T::line},
      {Quadric{{1, 1, 1, 0, 0, 0, 0, 0, 0, 1}}, T::imaginary},
      {Quadric{{1, 1, 0, 0, 0, 0, 0, 0, 0, 1}}, T::imaginary},
      {Quadric{{1, 0, 0, 0, 0, 0, 0, 0, 0, 1}}, T::imaginary},
      {Quadric{{0, 0, 0, 0, 0, 0, 0, 0, 0, 3}}, T::imaginary},
      {Quadric{}, T::degenerate},
  };
  for (const auto& [q, t] : cases) {
    EXPECT_EQ(quadric::to_string(quadric::classify(q).type), quadric::to_string(t));
    // Rotated, moved and scaled copies keep their type.
    const Quadric m = quadric::translate(
        quadric::rotate(q, quadric::axis_rotation({0.3, -1, 2}, 1.1)), {-2, 0.5, 4});
    Quadric scaled = m;
    for (double& c : scaled.k) c *= -1e3;
    EXPECT_EQ(quadric::to_string(quadric::classify(scaled).type), quadric::to_string(t));
  }
  const auto c = quadric::classify(quadric::ellipsoid({0, 0, 0}, {1, 2, 4}));
  EXPECT_NEAR(c.eigenvalues[0], 1.0 / 16, 1e-15);
  EXPECT_NEAR(c.eigenvalues[2], 1.0, 1e-15);
  EXPECT_EQ(c.rank3, 3);
  EXPECT_EQ(c.rank4, 4);
}

TEST(QuadricCore, FitNoisyEllipsoids) {
  for (unsigned seed : {1u, 2u, 3u}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> noise(0, 1e-3);
    const Vec3d ctr{0.5 * seed, -1.0, 2.0}, ax{3, 2, 1};
    const quadric::Mat3 r = quadric::axis_rotation({1, -2, 0.5}, 0.3 * seed);
    const Quadric truth = quadric::normalized(
        quadric::translate(quadric::rotate(quadric::ellipsoid({0, 0, 0}, ax), r), ctr));
    std::vector<Vec3d> pts;
    for (int k = 0; k < 2000; ++k) {
      const double th = std::acos(2 * u(rng) - 1), ph = 2 * M_PI * u(rng);
      const Vec3d l{ax[0] * std::sin(th) * std::cos(ph), ax[1] * std::sin(th) * std::sin(ph),
                    ax[2] * std::cos(th)};
      Vec3d p;
      for (int i = 0; i < 3; ++i)
        p[i] = r[i][0] * l[0] + r[i][1] * l[1] + r[i][2] * l[2] + ctr[i] + noise(rng);
      pts.push_back(p);
    }
    const auto f = quadric::fit(pts);
    for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(f.quadric.k[k], truth.k[k], 2e-3) << k;
    EXPECT_GT(f.geometric_rms, 0.5e-3);
    EXPECT_LT(f.geometric_rms, 2e-3);
    EXPECT_LT(f.geometric_max, 1e-2);
    EXPECT_GE(f.algebraic_max, f.algebraic_rms);
    EXPECT_EQ(quadric::classify(f.quadric, 1e-6).type, QuadricType::ellipsoid);
  }
  // Exact points on an ellipsoid: residuals at round-off, the fit equals the 9-point quadric.
  const Quadric e = quadric::ellipsoid({1, 2, 3}, {2, 1, 0.5});
  std::vector<Vec3d> pts;
  for (int n = 0; n < 12; ++n) {
    const double th = 0.2 + 0.25 * n, ph = 1.3 * n + 0.1;
    pts.push_back({1 + 2 * std::sin(th) * std::cos(ph), 2 + std::sin(th) * std::sin(ph),
                   3 + 0.5 * std::cos(th)});
  }
  const auto f = quadric::fit(pts);
  EXPECT_LT(f.geometric_max, 1e-12);
  std::array<Vec3d, 9> nine;
  std::copy(pts.begin(), pts.begin() + 9, nine.begin());
  const Quadric t9 = quadric::through_nine_points(nine);
  const Quadric want = quadric::normalized(e);
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(f.quadric.k[k], want.k[k], 1e-12);
    EXPECT_NEAR(t9.k[k], want.k[k], 1e-12);
  }
}

TEST(QuadricCore, BadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vec3d> eight(8, Vec3d{0, 0, 0});
  for (int k = 0; k < 8; ++k) eight[static_cast<std::size_t>(k)] = {1.0 * k, 0.5 * k * k, 1.0};
  EXPECT_THROW(quadric::fit(eight), ModelError);
  // 9 points on a plane (a lower-order surface): no unique quadric.
  std::array<Vec3d, 9> planar;
  for (int k = 0; k < 9; ++k)
    planar[static_cast<std::size_t>(k)] = {std::cos(0.7 * k) * (1 + 0.1 * k), std::sin(0.7 * k),
                                           0.3};
  EXPECT_THROW(quadric::through_nine_points(planar), ModelError);
  EXPECT_THROW(qcga::quadric_from_points(planar), ModelError);
  EXPECT_THROW(quadric::fit(planar), ModelError);
  std::vector<Vec3d> many_planar;
  for (int k = 0; k < 100; ++k)
    many_planar.push_back({std::cos(k * 1.0) * k, std::sin(k * 2.0), 1});
  EXPECT_THROW(quadric::fit(many_planar), ModelError);
  // NaN coordinates.
  std::array<Vec3d, 9> with_nan = planar;
  with_nan[4][1] = nan;
  EXPECT_THROW(quadric::through_nine_points(with_nan), ModelError);
  EXPECT_THROW(qcga::quadric_from_points_ga(with_nan), ModelError);
  std::vector<Vec3d> nan_fit(with_nan.begin(), with_nan.end());
  EXPECT_THROW(quadric::fit(nan_fit), ModelError);
  EXPECT_THROW(quadric::fit(std::vector<Vec3d>(20, Vec3d{1, 1, 1})), ModelError);  // coincident
  // Lines: zero or non-finite direction, non-finite origin.
  const Quadric s = quadric::sphere({0, 0, 0}, 1);
  EXPECT_THROW(quadric::intersect_line(s, {0, 0, 0}, {0, 0, 0}), ModelError);
  EXPECT_THROW(quadric::intersect_line(s, {0, 0, 0}, {nan, 0, 1}), ModelError);
  EXPECT_THROW(quadric::intersect_line(s, {nan, 0, 0}, {0, 0, 1}), ModelError);
  EXPECT_THROW(qcga::intersect_line(qcga::dual_quadric(s), {0, 0, 0}, {0, 0, 0}), ModelError);
  // Singular point, non-finite coefficients, bad indices, non-point.
  const Quadric cone{{1, 1, -1, 0, 0, 0, 0, 0, 0, 0}};
  EXPECT_THROW(quadric::unit_normal(cone, {0, 0, 0}), ModelError);
  EXPECT_THROW(quadric::classify(Quadric{{nan, 0, 0, 0, 0, 0, 0, 0, 0, 0}}), ModelError);
  EXPECT_THROW(dpga::rotor(0, 0, 0.1), ModelError);
  EXPECT_THROW(dpga::rotor(0, 3, 0.1), ModelError);
  EXPECT_THROW(dcga::rotor(1, 1, 0.1), ModelError);
  EXPECT_THROW(quadric::plane_rotation(2, 5, 0.1), ModelError);
  EXPECT_THROW(qcga::point_coordinates(qcga::Vector{}), ModelError);
  EXPECT_THROW(dcga::point_coordinates(dcga::Multivector{}), ModelError);
  EXPECT_THROW(qcga::from_clifford(clifford::basis_blade(3, 1.0)), ModelError);
  static_assert(std::is_base_of_v<std::invalid_argument, ModelError>);
}
