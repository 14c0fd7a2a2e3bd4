// Self-intersections through the commands (docs/topology.md, "Self-intersections"): `check`
// reports them (readable and JSON), and the volume is not a solid's, so `props --urdf`/`--mjcf`
// and `fuel` refuse the mesh; `--no-self-intersections` and `props --no-topology` skip the search.
// The mesh: two unit cubes, the second moved by (½, ½, ½), as binary STL (welded from the records)
// and OBJ (the Mesh path); CGAL 5.5's PMP::self_intersections counts 18 intersecting face pairs
// (bench/compare_self_intersections.sh).
#include <gtest/gtest.h>

#include <string>

#include "mesh/topology_test_meshes.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/nested_shells.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::CliRun;
using test::parse_json;
using test::run_cli;
using test::TempFile;

// Two overlapping unit cubes (12 triangles each, those of bench/self_intersection_meshes.py).
Mesh overlapping_unit_cubes() {
  const Mesh cube = test::unit_cube();
  return test::joined({cube, test::transformed(cube, [](Vec3d p) {
                         return p + Vec3d{0.5, 0.5, 0.5};
                       })});
}

constexpr std::size_t cgal_pairs = 18;  // CGAL 5.5, PMP::self_intersections

TEST(SelfIntersectionsCli, CheckReportsThePairs) {
  for (MeshFormat format : {MeshFormat::stl_binary, MeshFormat::obj}) {
    const TempFile in(format == MeshFormat::obj ? "_cubes.obj" : "_cubes.stl",
                      write_mesh_bytes(overlapping_unit_cubes(), format));
    const CliRun r = run_cli("check '" + in.path() + "' --json --max-list 3");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = parse_json(r.out);
    EXPECT_EQ(j["self_intersecting_pairs"], cgal_pairs);
    EXPECT_EQ(j["self_intersection_list"].size(), 3u);
    EXPECT_EQ(j["closed"], true);
    EXPECT_EQ(j["volume_valid"], false);
    const std::string note = "self-intersecting: " + std::to_string(cgal_pairs) + " face pairs";
    EXPECT_NE(r.out.find(note), std::string::npos);

    const CliRun text = run_cli("check '" + in.path() + "'");
    ASSERT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("self-intersections  18 face pairs"), std::string::npos) << text.out;

    const CliRun skipped = run_cli("check '" + in.path() + "' --json --no-self-intersections");
    ASSERT_EQ(skipped.status, 0) << skipped.err;
    const auto k = parse_json(skipped.out);
    EXPECT_TRUE(k["self_intersecting_pairs"].is_null());
    EXPECT_EQ(k["volume_valid"], true);  // nothing else is wrong with it
  }
}

TEST(SelfIntersectionsCli, PropsAndFuelSayTheVolumeIsNotASolids) {
  const TempFile in("_cubes.stl",
                    write_mesh_bytes(overlapping_unit_cubes(), MeshFormat::stl_binary));
  const CliRun props = run_cli("props '" + in.path() + "' --json");
  ASSERT_EQ(props.status, 0) << props.err;
  const auto j = parse_json(props.out);
  EXPECT_EQ(j["volume_valid"], false);
  EXPECT_EQ(j["topology"]["self_intersecting_pairs"], cgal_pairs);
  for (const char* format : {"--urdf", "--mjcf"}) {
    const CliRun refused = run_cli("props '" + in.path() + "' " + format);
    EXPECT_EQ(refused.status, 1);
    EXPECT_EQ(refused.out, "");
    EXPECT_NE(refused.err.find("self-intersecting"), std::string::npos) << refused.err;
  }
  const CliRun fuel = run_cli("fuel '" + in.path() + "' --fraction 0.5");
  EXPECT_EQ(fuel.status, 1);
  EXPECT_NE(fuel.err.find("self-intersecting"), std::string::npos) << fuel.err;

  const CliRun fast = run_cli("props '" + in.path() + "' --json --no-topology");
  ASSERT_EQ(fast.status, 0) << fast.err;
  EXPECT_TRUE(parse_json(fast.out)["topology"].is_null());
  const CliRun unchecked = run_cli("props '" + in.path() + "' --json --no-self-intersections");
  ASSERT_EQ(unchecked.status, 0) << unchecked.err;
  const auto u = parse_json(unchecked.out);
  EXPECT_TRUE(u["topology"]["self_intersecting_pairs"].is_null());
  EXPECT_EQ(u["volume_valid"], true);
}

}  // namespace
}  // namespace pgamesh
