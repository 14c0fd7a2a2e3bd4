// Orientation by nesting (docs/conventions.md §8): the topology report's depth, cavity and inward
// verdicts, and fix_orientation, on nested cubes, separate solids, a torus with a toroidal cavity
// and a rounding residue; every shell flipped the wrong way first, then repaired.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/shell_nesting.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/exact_mass.hpp"
#include "support/nested_shells.hpp"
#include "support/solids.hpp"

namespace pgamesh {
namespace {

using test::centred_cube;
using test::joined;
using test::torus_mesh;

// Cubes of side 8, 4, 2 about the origin; shell i faces the way its depth asks unless bit i of
// `wrong` is set. Volumes 512, −64 (a cavity), 8 (an island in it): 456 in all.
Mesh three_nested_cubes(unsigned wrong) {
  return joined({centred_cube(8, {}, (wrong & 1u) == 0), centred_cube(4, {}, (wrong & 2u) != 0),
                 centred_cube(2, {}, (wrong & 4u) == 0)});
}

TEST(OrientationByNesting, ThreeNestedCubesFaceOutInOut) {
  for (const bool triangles : {false, true}) {  // the polygon pass and the triangle pass
    SCOPED_TRACE(triangles ? "triangles" : "quads");
    const Mesh m = triangles ? test::triangulated(three_nested_cubes(0)) : three_nested_cubes(0);
    const TopologyReport r = analyze_topology(m);
    EXPECT_TRUE(r.closed);
    EXPECT_TRUE(r.volume_valid);
    EXPECT_EQ(r.volume, 456.0);
    ASSERT_EQ(r.components, 3u);
    EXPECT_EQ(r.closed_components, 3u);
    EXPECT_EQ(r.cavity_components, 1u);
    EXPECT_EQ(r.inward_components, 0u);
    ASSERT_EQ(r.component_list.size(), 3u);
    const double volume[3] = {512, -64, 8};
    for (std::uint32_t k = 0; k < 3; ++k) {
      const ComponentSummary& c = r.component_list[k];
      EXPECT_EQ(c.volume, volume[k]) << k;
      EXPECT_EQ(c.depth, k);
      EXPECT_EQ(c.cavity, k == 1);
      EXPECT_FALSE(c.inward);
    }
    for (const std::string& note : r.notes) EXPECT_EQ(note.find("inward"), std::string::npos);

    Mesh fixed = m;
    const OrientationFix fix = fix_orientation(fixed);
    EXPECT_EQ(fix.flipped, 0u);
    EXPECT_EQ(fixed.corners, m.corners);
  }
}

TEST(OrientationByNesting, EveryWronglyFlippedShellIsFoundAndRepaired) {
  const Mesh right = three_nested_cubes(0);
  for (unsigned wrong = 1; wrong < 8; ++wrong) {
    SCOPED_TRACE(wrong);
    Mesh m = three_nested_cubes(wrong);
    const TopologyReport before = analyze_topology(m);
    EXPECT_EQ(before.inward_components, static_cast<std::size_t>(std::popcount(wrong)));
    for (std::uint32_t k = 0; k < 3; ++k) {
      EXPECT_EQ(before.component_list[k].inward, ((wrong >> k) & 1u) != 0) << k;
      EXPECT_EQ(before.component_list[k].depth, k);  // the depth does not depend on orientation
    }
    const OrientationFix fix = fix_orientation(m);
    EXPECT_EQ(fix.flipped, 6u * static_cast<std::size_t>(std::popcount(wrong)));
    for (const ComponentOrientation& c : fix.components) {
      EXPECT_TRUE(c.closed);
      EXPECT_EQ(c.depth, c.component);
      EXPECT_EQ(c.volume, c.component == 1 ? -64.0 : (c.component == 0 ? 512.0 : 8.0));
    }
    // flipped() reverses every corner and the repair keeps the first: the same cycles.
    const TopologyReport after = analyze_topology(m);
    EXPECT_EQ(after.volume, 456.0);
    EXPECT_EQ(after.inward_components, 0u);
    EXPECT_EQ(after.cavity_components, 1u);
  }
  EXPECT_EQ(analyze_topology(right).volume, 456.0);
}

// The bug this rule fixes: a cube of volume 8 with a cavity of volume 1, off centre and touching
// nothing, correctly oriented (inward): volume 7, no defect, and the repair leaves it alone.
TEST(OrientationByNesting, HollowCubeIsNotADefect) {
  const Mesh hollow =
      joined({centred_cube(2, {}, true), centred_cube(1, {0.25, -0.125, 0.25}, false)});
  const TopologyReport r = analyze_topology(hollow);
  EXPECT_EQ(r.volume, 7.0);
  EXPECT_EQ(r.inward_components, 0u);
  EXPECT_EQ(r.cavity_components, 1u);
  EXPECT_TRUE(r.component_list[1].cavity);
  Mesh fixed = hollow;
  EXPECT_EQ(fix_orientation(fixed).flipped, 0u);
  EXPECT_EQ(analyze_topology(fixed).volume, 7.0);

  // The cavity turned outward (volume 9) is the defect, and the repair restores 7.
  Mesh wrong = joined({centred_cube(2, {}, true), centred_cube(1, {0.25, -0.125, 0.25}, true)});
  EXPECT_EQ(analyze_topology(wrong).volume, 9.0);
  EXPECT_EQ(analyze_topology(wrong).inward_components, 1u);
  EXPECT_EQ(fix_orientation(wrong).flipped, 6u);
  EXPECT_EQ(analyze_topology(wrong).volume, 7.0);
}

TEST(OrientationByNesting, SeparateSolidsBothFaceOut) {
  Mesh m = joined({centred_cube(2, {}, true), centred_cube(1, {5, 0, 0}, false)});
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.volume, 7.0);
  EXPECT_EQ(r.cavity_components, 0u);
  EXPECT_EQ(r.inward_components, 1u);
  EXPECT_EQ(r.component_list[1].depth, 0u);
  EXPECT_TRUE(r.component_list[1].inward);
  const OrientationFix fix = fix_orientation(m);
  ASSERT_EQ(fix.components.size(), 1u);
  EXPECT_EQ(fix.components[0].component, 1u);
  EXPECT_EQ(fix.components[0].volume, 1.0);
  EXPECT_EQ(analyze_topology(m).volume, 9.0);
}

// Nine hollow cubes side by side (18 shells): each cavity is found inside its own cube and no
// other; one cavity turned outward is the only defect.
TEST(OrientationByNesting, NineHollowCubesSideBySide) {
  Mesh m;
  for (int i = 0; i < 9; ++i) {
    const Vec3d c{3.0 * (i % 3), 3.0 * (i / 3), 0.5 * i};
    m = joined({m, centred_cube(2, c, true), centred_cube(1, c + Vec3d{0.25, 0, 0}, i == 4)});
  }
  const TopologyReport r = analyze_topology(m);
  EXPECT_EQ(r.volume, 9 * 7.0 + 2.0);
  EXPECT_EQ(r.closed_components, 18u);
  EXPECT_EQ(r.cavity_components, 9u);
  EXPECT_EQ(r.inward_components, 1u);
  for (std::uint32_t k = 0; k < 18; ++k) EXPECT_EQ(r.component_list[k].depth, k % 2) << k;
  EXPECT_TRUE(r.component_list[9].inward);
  const OrientationFix fix = fix_orientation(m);
  EXPECT_EQ(fix.flipped, 6u);
  EXPECT_EQ(analyze_topology(m).volume, 63.0);
}

#ifdef PGAMESH_HAVE_GMP
// A torus (R 4, r 2) with a toroidal cavity (R 4, r 1) along its core: the cavity's test point is
// inside the outer tube, the outer's outside the cavity. The volume is the exact sum of the
// tetrahedra of both shells (rational arithmetic) rounded once.
TEST(OrientationByNesting, TorusWithToroidalCavity) {
  const Mesh outer = torus_mesh(4, 2, 48, 24, {0.5, 0, 0}, true);
  const Mesh cavity = torus_mesh(4, 1, 48, 24, {0.5, 0, 0}, false);
  const Mesh right = joined({outer, cavity});
  const mpq_class exact_sum = test::exact_mass(outer).volume + test::exact_mass(cavity).volume;
  const double exact = exact_sum.get_d();
  EXPECT_GT(test::exact_mass(outer).volume, 0);
  EXPECT_LT(test::exact_mass(cavity).volume, 0);
  for (unsigned wrong = 0; wrong < 4; ++wrong) {
    SCOPED_TRACE(wrong);
    Mesh m = joined({(wrong & 1u) ? test::flipped(outer) : outer,
                     (wrong & 2u) ? test::flipped(cavity) : cavity});
    const TopologyReport before = analyze_topology(m);
    EXPECT_EQ(before.cavity_components, 1u);
    EXPECT_EQ(before.component_list[1].depth, 1u);
    EXPECT_EQ(before.inward_components, static_cast<std::size_t>(std::popcount(wrong)));
    fix_orientation(m);
    const TopologyReport after = analyze_topology(m);
    EXPECT_EQ(after.inward_components, 0u);
    EXPECT_NEAR(after.volume, exact, 1e-13 * exact);
  }
}
#endif

// A closed two-face component — one triangle and the same triangle the other way, starting at
// another corner — encloses nothing; its volume is a rounding residue, which is neither inward
// nor outward: not reported and not flipped. Inside the cube (depth 1) the residue is positive,
// the sign a cavity must not have; outside (depth 0) negative, the sign a solid must not have
// (IEEE doubles without contraction, docs/conventions.md §13).
TEST(OrientationByNesting, RoundingResidueIsLeftAlone) {
  for (const double x : {0.0, -10.0}) {
    SCOPED_TRACE(x);
    Mesh sliver;
    sliver.vertices = {{0.1 + x, 0.7, 0.3}, {1.3 + x, 0.2, 0.9}, {0.4 + x, 1.1, 0.6}};
    sliver.add_face({0, 1, 2});
    sliver.add_face({1, 0, 2});
    const Mesh m = joined({centred_cube(8, {}, true), sliver});
    const TopologyReport r = analyze_topology(m);
    ASSERT_EQ(r.components, 2u);
    const ComponentSummary& s = r.component_list[1];
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.depth, x == 0 ? 1u : 0u);
    if (x == 0)
      EXPECT_GT(s.volume, 0.0);
    else
      EXPECT_LT(s.volume, 0.0);
    Box3 box;
    for (const Vec3d& p : m.vertices) box.add(p);
    EXPECT_LE(std::abs(s.volume), volume_residue_bound(s.area, box.diagonal()));
    EXPECT_FALSE(s.inward);
    EXPECT_FALSE(s.cavity);  // encloses nothing
    EXPECT_EQ(r.inward_components, 0u);
    EXPECT_EQ(r.cavity_components, 0u);
    Mesh fixed = m;
    EXPECT_EQ(fix_orientation(fixed).flipped, 0u);
    EXPECT_EQ(fixed.corners, m.corners);
  }
}

TEST(OrientationByNesting, JudgeShellUsesTheResidueBound) {
  const auto unit = [] { return 1.0; };
  EXPECT_EQ(judge_shell(-4.4e-24, 0, 1.0, unit), ShellOrientation::undecided);
  EXPECT_EQ(judge_shell(4.4e-24, 1, 1.0, unit), ShellOrientation::undecided);
  EXPECT_EQ(judge_shell(0.0, 0, 1.0, unit), ShellOrientation::undecided);
  EXPECT_EQ(judge_shell(-1e-3, 0, 1.0, unit), ShellOrientation::wrong);
  EXPECT_EQ(judge_shell(-1e-3, 1, 1.0, unit), ShellOrientation::right);
  EXPECT_EQ(judge_shell(1e-3, 2, 1.0, unit), ShellOrientation::right);
  EXPECT_EQ(judge_shell(1e-3, 3, 1.0, unit), ShellOrientation::wrong);
  EXPECT_EQ(volume_residue_bound(1, 1), 16 * std::numeric_limits<double>::epsilon());
}

}  // namespace
}  // namespace pgamesh
