// `pgamesh check` on hollow parts (docs/conventions.md §8, orientation by nesting): a correctly
// oriented cavity is reported as a cavity, not as a defect, and --fix-orientation --output keeps
// it; a wrongly oriented one is repaired. Through OBJ (the polygon pass), binary PLY and binary
// STL (the passes that weld triangles straight from the file).
#include <gtest/gtest.h>

#include <string>

#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/nested_shells.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::centred_cube;
using test::CliRun;
using test::joined;
using test::json;
using test::parse_json;
using test::run_cli;
using test::TempFile;

// A cube of volume 8 with a cubic cavity of volume 1 off its centre, touching nothing; the cavity
// faces in (right) or out (the defect).
Mesh hollow_cube(bool cavity_right) {
  return joined({centred_cube(2, {}, true), centred_cube(1, {0.25, -0.125, 0.25}, !cavity_right)});
}

// `pgamesh props FILE --json`'s volume.
double props_volume(const std::string& path) {
  const CliRun r = run_cli("props '" + path + "' --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return parse_json(r.out)["volume"].get<double>();
}

TEST(CheckNestingCli, ARightCavityIsACavityNotADefect) {
  const TempFile in("_hollow_cube.obj", write_mesh_bytes(hollow_cube(true), MeshFormat::obj));
  const CliRun r = run_cli("check '" + in.path() + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["volume"], 7.0);
  EXPECT_EQ(j["volume_valid"], true);
  EXPECT_EQ(j["cavity_components"], 1);
  EXPECT_EQ(j["inward_components"], 0);
  EXPECT_EQ(j["component_list"][0]["depth"], 0);
  EXPECT_EQ(j["component_list"][0]["cavity"], false);
  EXPECT_EQ(j["component_list"][1]["depth"], 1);
  EXPECT_EQ(j["component_list"][1]["cavity"], true);
  EXPECT_EQ(j["component_list"][1]["inward"], false);
  EXPECT_EQ(j["component_list"][1]["volume"], -1.0);
  for (const auto& note : j["notes"])
    EXPECT_EQ(note.get<std::string>().find("inward"), std::string::npos) << note;
  const CliRun text = run_cli("check '" + in.path() + "'");
  EXPECT_NE(text.out.find("(2 closed, 1 cavity)"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("inward"), std::string::npos) << text.out;
}

TEST(CheckNestingCli, FixOrientationKeepsARightCavity) {
  const TempFile in("_hollow_cube.obj", write_mesh_bytes(hollow_cube(true), MeshFormat::obj));
  const TempFile out("_hollow_cube_fixed.obj");
  const CliRun r =
      run_cli("check '" + in.path() + "' --fix-orientation --output '" + out.path() + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r.out)["orientation_fix"]["flipped_faces"], 0);
  EXPECT_EQ(props_volume(out.path()), 7.0);
}

TEST(CheckNestingCli, FixOrientationTurnsAWrongCavityIn) {
  const TempFile in("_hollow_cube_wrong.obj",
                    write_mesh_bytes(hollow_cube(false), MeshFormat::obj));
  const TempFile out("_hollow_cube_wrong_fixed.obj");
  EXPECT_EQ(props_volume(in.path()), 9.0);
  const CliRun r =
      run_cli("check '" + in.path() + "' --fix-orientation --output '" + out.path() + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["orientation_fix"]["flipped_faces"], 6);
  const json& c = j["orientation_fix"]["components"][0];
  EXPECT_EQ(c["first_face"], 6);
  EXPECT_EQ(c["depth"], 1);
  EXPECT_EQ(c["volume"], -1.0);
  EXPECT_EQ(j["volume"], 7.0);  // the report describes the repaired mesh
  EXPECT_EQ(j["inward_components"], 0);
  EXPECT_EQ(props_volume(out.path()), 7.0);
}

// Cubes of side 8, 4, 2 about the origin as triangles, the island (side 2) facing in: volumes
// 512, −64, −8 before the repair, 512, −64, 8 after (456 in all).
TEST(CheckNestingCli, TriangleFilePassesFindTheNesting) {
  const Mesh m = test::triangulated(
      joined({centred_cube(8, {}, true), centred_cube(4, {}, false), centred_cube(2, {}, false)}));
  for (const MeshFormat format : {MeshFormat::ply_binary_le, MeshFormat::stl_binary}) {
    const bool ply = format == MeshFormat::ply_binary_le;
    SCOPED_TRACE(ply ? "ply" : "stl");
    const TempFile in(ply ? "_nested.ply" : "_nested.stl", write_mesh_bytes(m, format));
    const TempFile out(ply ? "_nested_fixed.ply" : "_nested_fixed.stl");
    const CliRun before = run_cli("check '" + in.path() + "' --json");
    ASSERT_EQ(before.status, 0) << before.err;
    const json j = parse_json(before.out);
    EXPECT_EQ(j["volume"], 440.0);
    EXPECT_EQ(j["inward_components"], 1);
    EXPECT_EQ(j["cavity_components"], 1);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(j["component_list"][k]["depth"], k);
    EXPECT_EQ(j["component_list"][2]["inward"], true);
    const CliRun r =
        run_cli("check '" + in.path() + "' --fix-orientation --output '" + out.path() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(props_volume(out.path()), 456.0);
  }
}

}  // namespace
}  // namespace pgamesh
