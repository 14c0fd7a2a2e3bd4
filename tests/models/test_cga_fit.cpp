// Sphere, plane and cylinder fits on generated noisy points with known parameters (fixed seeds).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "pgamesh/models/cga.hpp"
#include "support/model_checks.hpp"

using namespace pgamesh;
using namespace pgamesh::cga;

using pgamesh::test::expect_near;
using pgamesh::test::pi;

namespace {

std::vector<Vec3d> noisy_sphere(Vec3d c, double r, std::size_t n, double noise, unsigned seed,
                                double max_polar = pi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  // A normal distribution needs a positive deviation: exact points draw no noise at all.
  std::normal_distribution<double> g(0, noise > 0 ? noise : 1);
  std::vector<Vec3d> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double z = 1 - u(rng) * (1 - std::cos(max_polar)), phi = 2 * pi * u(rng);
    const double s = std::sqrt(1 - z * z);
    const double dr = noise > 0 ? g(rng) : 0.0;
    out.push_back(c + (r + dr) * Vec3d{s * std::cos(phi), s * std::sin(phi), z});
  }
  return out;
}

}  // namespace

TEST(CgaFitSphere, ExactPointsGiveTheSphere) {
  const auto pts = noisy_sphere({1, -2, 3}, 2.5, 50, 0.0, 1);
  const SphereFit f = fit_sphere(pts);
  expect_near(f.center, {1, -2, 3}, 1e-12);
  EXPECT_NEAR(f.radius, 2.5, 1e-12);
  EXPECT_LT(f.rms, 1e-12);
  EXPECT_LT(f.max_error, 1e-12);
  // Four points: the sphere through them (Hitzer eq. 43 agrees).
  const std::span<const Vec3d> four(pts.data(), 4);
  const SphereFit g = fit_sphere(four);
  const RoundParams sp = sphere_params(sphere(pts[0], pts[1], pts[2], pts[3]));
  expect_near(g.center, sp.center, 1e-11);
  EXPECT_NEAR(g.radius, sp.radius, 1e-11);
}

TEST(CgaFitSphere, NoisyPointsRecoverTheParameters) {
  const double noise = 0.01;
  const auto pts = noisy_sphere({10, 20, -5}, 4, 20000, noise, 2);
  const SphereFit f = fit_sphere(pts);
  expect_near(f.center, {10, 20, -5}, 1e-3);
  EXPECT_NEAR(f.radius, 4, 1e-3);
  EXPECT_NEAR(f.rms, noise, 0.05 * noise);
  EXPECT_GT(f.max_error, 3 * noise);
  EXPECT_LT(f.max_error, 6 * noise);
  // A cap of 60° (one-sided data) and a far-away sphere.
  const SphereFit cap = fit_sphere(noisy_sphere({0, 0, 0}, 1, 5000, 1e-4, 3, pi / 3));
  expect_near(cap.center, {0, 0, 0}, 2e-3);
  EXPECT_NEAR(cap.radius, 1, 2e-3);
  const SphereFit far = fit_sphere(noisy_sphere({1e6, 2e6, -3e6}, 2, 2000, 1e-3, 4));
  expect_near(far.center, {1e6, 2e6, -3e6}, 2e-4);
  EXPECT_NEAR(far.radius, 2, 2e-4);
  // The dual sphere it returns is the conformal object.
  EXPECT_NEAR(sphere_params(f.dual_sphere, Form::dual).radius, f.radius, 1e-12);
}

TEST(CgaFitPlane, NoisyPlane) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  std::normal_distribution<double> g(0, 0.02);
  const Vec3d n = Vec3d{2, -1, 2} / 3.0, o{1, 1, 1};
  Vec3d a = cross(n, Vec3d{1, 0, 0});
  a = a / length(a);
  const Vec3d b = cross(n, a);
  std::vector<Vec3d> pts;
  for (int i = 0; i < 10000; ++i) pts.push_back(o + u(rng) * a + u(rng) * b + g(rng) * n);
  const PlaneFit f = fit_plane(pts);
  expect_near(f.normal, n, 1e-3);  // the largest component (2/3) is positive already
  EXPECT_NEAR(f.distance, dot(n, o), 1e-3);
  EXPECT_NEAR(f.rms, 0.02, 1e-3);
  EXPECT_NEAR(plane_params(f.dual_plane, Form::dual).distance, f.distance, 1e-15);
  const PlaneFit exact = fit_plane(std::vector<Vec3d>{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
  expect_near(exact.normal, {0, 0, 1}, 1e-15);
  EXPECT_NEAR(exact.distance, 1, 1e-15);
}

TEST(CgaFitCylinder, NoisyCylinders) {
  struct Case {
    Vec3d p, d;
    double r, h, noise;
  };
  // A long thin one, a short wide one (the PCA axis is wrong for it) and a tilted one.
  for (const Case& k :
       {Case{{1, 2, 3}, {0, 0, 1}, 0.5, 10, 0.005}, Case{{-2, 0, 1}, {1, 0, 0}, 3, 1, 0.01},
        Case{{5, -5, 2}, Vec3d{1, 2, 3} / std::sqrt(14.0), 1.5, 4, 0.002}}) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g(0, k.noise);
    Vec3d a = cross(k.d, std::abs(k.d.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0});
    a = a / length(a);
    const Vec3d b = cross(k.d, a);
    std::vector<Vec3d> pts;
    for (int i = 0; i < 5000; ++i) {
      const double t = (u(rng) - 0.5) * k.h, phi = 2 * pi * u(rng), rr = k.r + g(rng);
      pts.push_back(k.p + t * k.d + rr * (std::cos(phi) * a + std::sin(phi) * b));
    }
    const CylinderFit f = fit_cylinder(pts);
    const double align = std::abs(dot(f.axis_direction, k.d));
    EXPECT_NEAR(align, 1, 1e-5);
    const Vec3d off = f.axis_point - k.p;
    EXPECT_LT(length(off - dot(off, k.d) * k.d), 5 * k.noise);  // the axes coincide
    EXPECT_NEAR(f.radius, k.r, 3 * k.noise);
    EXPECT_NEAR(f.rms, k.noise, 0.1 * k.noise);
  }
}

TEST(CgaFitErrors, BadInputNamesTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec3d> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_MODEL_ERROR(fit_sphere(three), "at least 4 points, got 3");
  EXPECT_MODEL_ERROR(fit_sphere(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}),
                     "coplanar");
  EXPECT_MODEL_ERROR(fit_sphere(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}),
                     "point 3 has a non-finite coordinate");
  EXPECT_MODEL_ERROR(fit_sphere(std::vector<Vec3d>(5, Vec3d{1, 1, 1})), "coincide");
  EXPECT_MODEL_ERROR(fit_plane(std::vector<Vec3d>{{0, 0, 0}, {1, 1, 1}}), "at least 3");
  EXPECT_MODEL_ERROR(fit_plane(std::vector<Vec3d>{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}),
                     "collinear");
  EXPECT_MODEL_ERROR(fit_cylinder(three), "at least 6");
  std::vector<Vec3d> line;
  for (int i = 0; i < 10; ++i) line.push_back({1.0 * i, 2.0 * i, 0});
  EXPECT_MODEL_ERROR(fit_cylinder(line), "collinear");
}
