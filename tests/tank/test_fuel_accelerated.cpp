// The hierarchy and the sorted sweep against the reference pass on random planes; the golden gauge
// table and inverse cases; inverse(forward(level)) = level; the attitude convention.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"
#include "support/golden.hpp"
#include "tank/tank_test_support.hpp"

using namespace pgamesh;
using namespace pgamesh::tank;
using pgamesh::test::json;
using pgamesh::test::json_vec3;
using pgamesh::test::random_unit;

namespace {

// Far from the origin the plane's position is only known to a few units in the last place of the
// absolute coordinates (4.7e-10 at 3e6): the paths differ by that much when they sum about
// different points (the reference pass about o′ near the fuel, the accelerated paths about the
// tank's centre with the cone over the free surface, cone_over_surface), each o′ off the plane by
// its own rounding. `far` is four such ulps; 0 near the origin does not make the test stricter
// than the relative terms.
double far_ulps(const Tank& t) {
  const double x = length(t.reference) + length(t.upper - t.lower);
  return 4 * (std::nextafter(x, INFINITY) - x);
}

void expect_same_state(const FuelState& a, const FuelState& b, const Tank& t) {
  const double size = length(t.upper - t.lower);
  const double far = length(t.reference) > 1e3 * size ? far_ulps(t) : 0;
  EXPECT_NEAR(a.volume, b.volume, 1e-13 * t.volume + far * t.area);
  EXPECT_NEAR(a.wetted_area, b.wetted_area, 1e-12 * t.area + far * size);
  EXPECT_NEAR(a.surface_area, b.surface_area, 1e-12 * t.area + far * size);
  EXPECT_NEAR(a.surface.area, b.surface.area, 1e-12 * t.area + far * size);
  EXPECT_EQ(a.has_center, b.has_center);
  if (a.has_center && a.volume > 1e-6 * t.volume) {
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(a.center_of_mass[i], b.center_of_mass[i], 1e-11 * size + far);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(a.inertia_com[i][j], b.inertia_com[i][j],
                    1e-11 * t.volume * size * size + far * t.area * size * size);
  }
  if (a.surface.area > 1e-6 * t.area) {
    EXPECT_NEAR(length(a.surface.centroid - b.surface.centroid), 0, 1e-10 * size + far);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(a.surface.second[i], b.surface.second[i],
                  1e-10 * t.area * size * size + far * size * size * size);
  }
}

}  // namespace

TEST(FuelIndex, AgreesWithReferencePassOnRandomPlanes) {
  std::vector<Tank> tanks;
  tanks.push_back(make_tank(icosphere(4, 1.7)));
  tanks.push_back(make_tank(capsule(0.6, 2, 40, 10)));
  tanks.push_back(make_tank(pgamesh::test::load_golden_obj("meshes/torus.obj")));
  tanks.push_back(make_tank(pgamesh::test::load_golden_obj("meshes/icosphere_L3_far.obj")));
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> uni(-0.05, 1.05);
  for (const Tank& t : tanks) {
    const FuelIndex index(t);
    for (int k = 0; k < 100; ++k) {
      const Vec3d up = random_unit(rng);
      const LevelRange r = level_range(t, up);
      const LevelRange ir = index.range(up);
      EXPECT_EQ(r.lowest, ir.lowest);
      EXPECT_EQ(r.highest, ir.highest);
      const double level = r.lowest + uni(rng) * (r.highest - r.lowest);
      SCOPED_TRACE(k);
      expect_same_state(index.query(fuel_plane(up, level)), fuel_naive(t, fuel_plane(up, level)),
                        t);
    }
  }
}

TEST(FuelIndex, ExactAtPlanesThroughVerticesAndFaces) {
  const Tank t = make_tank(box(1, 1, 1));
  const FuelIndex index(t);
  const double k = 1 / std::sqrt(3.0);
  for (auto [up, level] : {std::pair{Vec3d{0, 0, 1}, -0.5}, std::pair{Vec3d{0, 0, 1}, 0.5},
                           std::pair{Vec3d{0, 0, 1}, 0.0}, std::pair{Vec3d{k, k, k}, -0.5 * k},
                           std::pair{Vec3d{k, k, k}, 0.5 * k}}) {
    const FuelState a = index.query(fuel_plane(up, level));
    const FuelState b = fuel_naive(t, fuel_plane(up, level));
    EXPECT_NEAR(a.volume, b.volume, 1e-15);
    EXPECT_NEAR(a.wetted_area, b.wetted_area, 1e-15);
    EXPECT_NEAR(a.surface_area, b.surface_area, 1e-15);
  }
}

TEST(FuelSweep, AgreesWithReferencePassAndGoldenTable) {
  const Tank sphere = make_tank(icosphere(3, 1));
  std::mt19937_64 rng(23);
  for (int k = 0; k < 5; ++k) {
    const Vec3d up = random_unit(rng);
    const auto levels = even_levels(level_range(sphere, up), 40);
    const auto rows = fuel_sweep(sphere, up, levels);
    for (std::size_t i = 0; i < levels.size(); ++i)
      expect_same_state(rows[i], fuel_naive(sphere, fuel_plane(up, levels[i])), sphere);
  }
  // Unsorted and repeated levels come back in the order given.
  const std::vector<double> shuffled = {0.3, -0.9, 0.3, 2.0, -2.0, 0.0};
  const auto rows = fuel_sweep(sphere, {0, 0, 1}, shuffled);
  for (std::size_t i = 0; i < shuffled.size(); ++i)
    EXPECT_NEAR(rows[i].volume, fuel_naive(sphere, fuel_plane({0, 0, 1}, shuffled[i])).volume,
                1e-13 * sphere.volume);

  const json file = pgamesh::test::load_golden("fuel_slices.json");
  int found = 0;
  for (const json& c : file["cases"]) {
    if (!c["input"].contains("table")) continue;
    ++found;
    const Tank t = make_tank(pgamesh::test::load_golden_obj(c["input"]["mesh"].get<std::string>()));
    const Vec3d up = json_vec3(c["input"]["up"]);
    const auto levels = even_levels(level_range(t, up), c["input"]["table"].get<int>());
    const auto table = fuel_sweep(t, up, levels);
    const json& expected = c["expected"]["rows_level_volume"];
    ASSERT_EQ(table.size(), expected.size());
    for (std::size_t i = 0; i < table.size(); ++i) {
      EXPECT_NEAR(levels[i], expected[i][0].get<double>(), 1e-12);
      EXPECT_NEAR(table[i].volume, expected[i][1].get<double>(), 1e-12);
    }
    EXPECT_NEAR(t.volume, c["expected"]["total_volume"].get<double>(), 1e-12);
  }
  EXPECT_EQ(found, 1);
}

TEST(FuelSweep, AgreesAtVertexHeightsAndBetween) {
  // Levels through vertices (ties between a vertex and a level: the vertex is fuel), many levels
  // between two vertex heights, and triangles that cross no level at all.
  std::vector<Tank> tanks;
  tanks.push_back(make_tank(capsule(0.6, 2, 24, 6)));
  tanks.push_back(make_tank(pgamesh::test::load_golden_obj("meshes/torus.obj")));
  tanks.push_back(make_tank(box(2, 3, 4)));
  std::mt19937_64 rng(5);
  for (const Tank& t : tanks) {
    for (const Vec3d up : {Vec3d{0, 0, 1}, Vec3d{1, 0, 0}, random_unit(rng)}) {
      std::vector<double> levels;
      for (std::size_t i = 0; i < t.vertices.size(); i += 7)
        levels.push_back(dot(up, t.vertices[i]));
      const LevelRange r = level_range(t, up);
      const auto dense = even_levels({r.lowest, r.lowest + 0.01 * (r.highest - r.lowest)}, 50);
      levels.insert(levels.end(), dense.begin(), dense.end());
      const auto sparse = even_levels(r, 3);
      levels.insert(levels.end(), sparse.begin(), sparse.end());
      const auto rows = fuel_sweep(t, up, levels);
      for (std::size_t i = 0; i < levels.size(); ++i) {
        SCOPED_TRACE(i);
        expect_same_state(rows[i], fuel_naive(t, FuelPlane{up, levels[i]}), t);
      }
    }
  }
}

TEST(FreeSurface, ConeFromMomentsEqualsFanOfTetrahedra) {
  // A random polygon in the plane z = h (exactly: o′ on it), its cone from the reference point
  // as the fan of tetrahedra (reference, o′, p, q) of body_moments against cone_over_surface.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> uni(-1, 1);
  for (int k = 0; k < 20; ++k) {
    const double h = 2 * uni(rng);
    const FuelPlane plane{{0, 0, 1}, h};
    const Vec3d reference{0.3 * uni(rng), 0.3 * uni(rng), 0};
    const SurfaceFrame frame = surface_frame(plane, reference);
    ASSERT_EQ(frame.origin.z, h);
    FreeSurfaceSums sums;
    BoundarySums fan;
    const Vec3d o = frame.origin - reference;
    std::vector<Vec3d> loop;
    for (int i = 0; i < 7; ++i)  // star-shaped about a shifted centre, counter-clockwise
      loop.push_back(Vec3d{0.5 + (1 + 0.5 * uni(rng)) * std::cos(i * 0.8975979010256552),
                           -0.2 + (1 + 0.5 * uni(rng)) * std::sin(i * 0.8975979010256552), h} -
                     reference);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec3d p = loop[i], q = loop[(i + 1) % loop.size()];
      add_segment(sums, plane_coordinates(frame, p - o), plane_coordinates(frame, q - o));
      add_triangle(fan, o, p, q);
    }
    const BoundarySums cone = cone_over_surface(sums, frame, reference);
    const double scale = std::abs(fan.volume6) + 1;
    EXPECT_NEAR(cone.volume6, fan.volume6, 1e-14 * scale);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(cone.moment24[i], fan.moment24[i], 1e-13 * scale);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(cone.second120[i], fan.second120[i], 1e-13 * scale);
  }
}

TEST(FuelSweep, EmptyAndFullAreExactWithFacesInTheEndPlanes) {
  const Tank t = make_tank(box(2, 3, 4));
  const std::vector<double> levels = {-2.5, -2, -1, 2, 3};
  const auto rows = fuel_sweep(t, {0, 0, 1}, levels);
  EXPECT_EQ(rows[0].volume, 0);
  EXPECT_EQ(rows[1].volume, 0);
  EXPECT_FALSE(rows[1].has_center);
  EXPECT_NEAR(rows[1].surface_area, 6, 1e-15);  // the bottom face: the limit from above
  EXPECT_NEAR(rows[2].volume, 6, 1e-14);
  EXPECT_EQ(rows[3].volume, t.volume);
  EXPECT_EQ(rows[3].fraction, 1);
  EXPECT_EQ(rows[3].surface_area, 0);
  EXPECT_EQ(rows[4].volume, t.volume);
  const FuelIndex index(t);
  EXPECT_EQ(index.query(fuel_plane({0, 0, 1}, -2)).volume, 0);
  EXPECT_EQ(index.query(fuel_plane({0, 0, 1}, 2)).volume, t.volume);
}

TEST(InverseLevel, GoldenCasesAndRoundTrips) {
  const json file = pgamesh::test::load_golden("fuel_slices.json");
  int found = 0;
  for (const json& c : file["cases"]) {
    const json& in = c["input"];
    if (!in.contains("volume")) continue;
    ++found;
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tank t = make_tank(pgamesh::test::load_golden_obj(in["mesh"].get<std::string>()));
    const FuelIndex index(t);
    const LevelSolution s =
        level_for_volume(index, json_vec3(in["up"]), in["volume"].get<double>());
    EXPECT_NEAR(s.level, c["expected"]["level"].get<double>(), 1e-10);
    EXPECT_LT(s.iterations, 20);
  }
  EXPECT_EQ(found, 2);

  // inverse(forward(level)) = level, on a capsule tank at random attitudes.
  const Tank t = make_tank(capsule(0.6, 2, 48, 12));
  const FuelIndex index(t);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.001, 0.999);
  for (int k = 0; k < 50; ++k) {
    const Vec3d up = random_unit(rng);
    const LevelRange r = level_range(t, up);
    const double level = r.lowest + uni(rng) * (r.highest - r.lowest);
    const double v = fuel_naive(t, fuel_plane(up, level)).volume;
    const LevelSolution s = level_for_volume(index, up, v);
    EXPECT_NEAR(s.level, level, 1e-11 * (r.highest - r.lowest)) << k;
    EXPECT_LT(s.iterations, 30) << k;
    const LevelSolution f = level_for_fraction(index, up, v / t.volume);
    EXPECT_NEAR(f.level, level, 1e-11 * (r.highest - r.lowest)) << k;
  }
  // Ends and errors.
  const LevelRange r = level_range(t, {0, 0, 1});
  EXPECT_EQ(level_for_volume(index, {0, 0, 1}, 0).level, r.lowest);
  EXPECT_EQ(level_for_volume(index, {0, 0, 1}, t.volume).level, r.highest);
  EXPECT_THROW(level_for_volume(index, {0, 0, 1}, -1e-9), std::domain_error);
  EXPECT_THROW(level_for_volume(index, {0, 0, 1}, t.volume * 1.001), std::domain_error);
  EXPECT_THROW(level_for_fraction(index, {0, 0, 1}, 1.5), std::domain_error);
  EXPECT_THROW(level_for_volume(index, {0, 0, 0}, 1), std::invalid_argument);
  // A list of volumes.
  const std::vector<double> volumes = {0.1, 0.5, 1.0};
  const auto levels = levels_for_volumes(index, {0, 0, 1}, volumes);
  for (std::size_t i = 0; i < volumes.size(); ++i)
    EXPECT_NEAR(fuel_naive(t, fuel_plane({0, 0, 1}, levels[i].level)).volume, volumes[i], 1e-12);
}

TEST(InverseLevel, FlatBottomTankStartsAtTheBottomFace) {
  // V(level) jumps in slope at the bottom face (a face in the plane): still converges.
  const Tank t = make_tank(box(2, 3, 4));
  const FuelIndex index(t);
  for (double v : {1e-9, 0.6, 12.0, 23.9999}) {
    const LevelSolution s = level_for_volume(index, {0, 0, 1}, v);
    EXPECT_NEAR(s.level, -2 + v / 6, 1e-12) << v;
  }
}

TEST(Attitude, PitchNoseUpRollRightDown) {
  const double deg = std::numbers::pi / 180;
  for (double pitch : {-20.0, 0.0, 7.5, 30.0})
    for (double roll : {-45.0, 0.0, 10.0}) {
      const Vec3d up = up_from_attitude({0, 0, 1}, pitch * deg, roll * deg);
      const double t = pitch * deg, f = roll * deg;
      EXPECT_NEAR(up.x, std::sin(t), 1e-15);
      EXPECT_NEAR(up.y, std::sin(f) * std::cos(t), 1e-15);
      EXPECT_NEAR(up.z, std::cos(f) * std::cos(t), 1e-15);
    }
  // Nose up: fuel runs aft. A long box tank (x forward) half full, pitched 10° up: the fuel's
  // centre of mass moves to negative x; rolled right side down it moves to negative y (right).
  const Tank t = make_tank(box(4, 1, 1));
  const FuelIndex index(t);
  const Vec3d pitched = up_from_attitude({0, 0, 1}, 10 * deg, 0);
  const auto s = level_for_fraction(index, pitched, 0.5);
  EXPECT_LT(index.query(fuel_plane(pitched, s.level)).center_of_mass.x, -0.1);
  const Vec3d rolled = up_from_attitude({0, 0, 1}, 0, 10 * deg);
  const auto s2 = level_for_fraction(index, rolled, 0.5);
  EXPECT_LT(index.query(fuel_plane(rolled, s2.level)).center_of_mass.y, -0.01);
  // Apparent gravity: braking (deceleration along −x) pushes the fuel forward.
  const Vec3d braking = up_from_gravity({2.0, 0, -9.81});
  EXPECT_NEAR(braking.x, -2.0 / std::hypot(2.0, 9.81), 1e-15);
  EXPECT_THROW(up_from_gravity({0, 0, 0}), std::invalid_argument);
}
