// Accuracy against exact rational arithmetic on the double input (issue item 3): volume, centre
// of mass and inertia about the centre of mass within 1e-12 relative, also after translating the
// mesh by 1e6 along each axis (the translated coordinates are rounded; the reference is exact for
// the rounded input).
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "support/solids.hpp"

#ifdef PGAMESH_HAVE_GMP
#include "support/exact_mass.hpp"
#endif

using namespace pgamesh;
using namespace pgamesh::test;

namespace {

#ifdef PGAMESH_HAVE_GMP
void expect_exact(const Mesh& m, double rel) {
  const ExactSummary x = exact_summary(m);
  const MassProperties p = mass_properties(m);
  EXPECT_NEAR(p.volume, x.volume, rel * std::abs(x.volume));
  // The centre of mass to 1e-12 of the part's size (stricter than relative to |c| far away), plus
  // the rounding of |c| itself.
  Box3 box;
  for (const Vec3d& v : m.vertices) box.add(v);
  const double size = box.diagonal();
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(
        p.center_of_mass[i], x.center_of_mass[i],
        rel * size + 2 * std::numeric_limits<double>::epsilon() * std::abs(x.center_of_mass[i]))
        << i;
  double scale = 0;
  for (const auto& row : x.inertia_com)
    for (double v : row) scale = std::max(scale, std::abs(v));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(p.inertia_com[i][j], x.inertia_com[i][j], rel * scale) << i << "," << j;
}

// A lumpy closed surface: a UV sphere with seeded random radii (and quads, which stay non-planar).
Mesh lumpy(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.7, 1.3);
  Mesh m = uv_sphere(1, 12, 20);
  for (Vec3d& v : m.vertices) v = u(rng) * Vec3d{2.5 * v.x, v.y, 0.6 * v.z};
  return m;
}
#endif

}  // namespace

TEST(MassExact, AgreesWithRationalArithmetic) {
#ifndef PGAMESH_HAVE_GMP
  GTEST_SKIP() << "GMP (gmpxx) not found: exact comparisons skipped";
#else
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    expect_exact(lumpy(seed), 1e-12);
  }
  expect_exact(tetrahedron_mesh({0.1, 0.2, 0.3}, {1.7, 0.1, 0.2}, {0.3, 2.9, 0.1}, {0.2, 0.3, 0.9}),
               1e-12);
#endif
}

TEST(MassExact, FarFromTheOriginStaysExact) {
#ifndef PGAMESH_HAVE_GMP
  GTEST_SKIP() << "GMP (gmpxx) not found: exact comparisons skipped";
#else
  const Mesh base = lumpy(7);
  for (Vec3d t : {Vec3d{1e6, 0, 0}, Vec3d{0, 1e6, 0}, Vec3d{0, 0, 1e6}, Vec3d{1e6, 1e6, 1e6},
                  Vec3d{-1e6, 2e6, -3e6}}) {
    SCOPED_TRACE(t.x + 10 * t.y + 100 * t.z);
    expect_exact(transformed(base, [&](Vec3d v) { return v + t; }), 1e-12);
  }
#endif
}
