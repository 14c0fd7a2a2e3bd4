// Identities that must hold to rounding on random planes through real meshes: fuel + ullage =
// tank for volume, wall area and centre of mass (the ullage is the fuel of the flipped plane),
// and the free surfaces of the two sides coincide.
#include <gtest/gtest.h>

#include <random>

#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/tank/fuel_state.hpp"
#include "support/golden.hpp"
#include "tank/tank_test_support.hpp"

using namespace pgamesh;
using namespace pgamesh::tank;

namespace {

void check_identities(const Tank& t, int planes, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> uni(0, 1);
  const BodyMoments whole = body_moments(t.total);
  const Vec3d com = t.reference + centroid(whole);
  const double size = length(t.upper - t.lower);
  // Absolute coordinates far from the origin carry their own rounding (a few ulps of |x|): the
  // plane's position too, and the two sides are summed about points o′ near each side, each off
  // the plane by its own rounding, so the volumes agree to (free-surface area) × far.
  const double far = 1e-14 * length(t.reference);
  for (int k = 0; k < planes; ++k) {
    Vec3d up{g(rng), g(rng), g(rng)};
    up = up / length(up);
    const LevelRange r = level_range(t, up);
    const double level = r.lowest + (0.02 + 0.96 * uni(rng)) * (r.highest - r.lowest);
    const FuelState below = fuel_naive(t, fuel_plane(up, level));
    const FuelState above = fuel_naive(t, fuel_plane(-up, -level));
    SCOPED_TRACE(k);
    const double plane_rounding = far * below.surface_area;
    EXPECT_NEAR(below.volume + above.volume, t.volume, 1e-13 * t.volume + plane_rounding);
    EXPECT_NEAR(below.fraction + above.fraction, 1, 1e-13 + plane_rounding / t.volume);
    EXPECT_NEAR(below.ullage_volume, above.volume, 1e-13 * t.volume + plane_rounding);
    EXPECT_NEAR(below.wetted_area + above.wetted_area, t.area, 1e-13 * t.area);
    EXPECT_NEAR(below.surface_area, above.surface_area, 1e-13 * t.area);
    EXPECT_NEAR(below.surface.area, above.surface.area, 1e-13 * t.area);
    const Vec3d combined =
        (below.volume * below.center_of_mass + above.volume * above.center_of_mass) /
        (below.volume + above.volume);
    EXPECT_NEAR(length(combined - com), 0, 1e-13 * size + far);
    EXPECT_NEAR(length(below.surface.centroid - above.surface.centroid), 0, 1e-11 * size + far);
    // The free-surface centroid lies in the plane.
    EXPECT_NEAR(dot(below.surface.centroid, up), level, 1e-13 * size + far);
  }
}

}  // namespace

TEST(FuelIdentities, RandomPlanesThroughRealMeshes) {
  const std::string dir = pgamesh::test::shared_meshes_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/meshes is absent";
  for (const char* name : {"/npm/bunny.obj", "/mayavi2/shuttle.obj"}) {
    SCOPED_TRACE(name);
    const pgamesh::Mesh mesh = pgamesh::test::load_obj_file(dir + name);
    const Tank t = make_tank(mesh);
    ASSERT_TRUE(tank_fitness(mesh, t).fit) << "gap " << t.gap_area << " volume " << t.volume;
    check_identities(t, 50, 11);
  }
}

TEST(FuelIdentities, RandomPlanesThroughGoldenTorusAndFarSphere) {
  for (const char* name : {"meshes/torus.obj", "meshes/icosphere_L3_far.obj"}) {
    SCOPED_TRACE(name);
    check_identities(make_tank(pgamesh::test::load_golden_obj(name)), 50, 5);
  }
}

TEST(FuelIdentities, DerivativeOfVolumeIsFreeSurfaceArea) {
  const Tank t = make_tank(capsule(0.6, 2, 64, 16));
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  for (int k = 0; k < 20; ++k) {
    Vec3d up{g(rng), g(rng), g(rng)};
    up = up / length(up);
    const LevelRange r = level_range(t, up);
    const double level = r.lowest + (0.1 + 0.8 * k / 20.0) * (r.highest - r.lowest);
    const double h = 1e-6;
    const double dv = fuel_naive(t, fuel_plane(up, level + h)).volume -
                      fuel_naive(t, fuel_plane(up, level - h)).volume;
    EXPECT_NEAR(fuel_naive(t, fuel_plane(up, level)).surface_area, dv / (2 * h), 1e-6);
  }
}
