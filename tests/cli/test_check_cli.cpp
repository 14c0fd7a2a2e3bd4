// `pgamesh check`: the JSON of docs/topology.md on golden meshes, the exit codes, and the repaired
// mesh written by --fix-orientation --output.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::CliRun;
using test::json;
using test::parse_json;
using test::run_cli;
using test::TempFile;

// Runs `pgamesh check ARGS`.
CliRun run_check(const std::string& args) {
  return run_cli("check " + args);
}

// The unit cube without its top (z = 1) square, as OBJ.
const char* open_cube_obj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 4\nf 1 4 2\nf 1 2 6\nf 1 6 5\nf 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n";

TEST(CheckCli, JsonOfAClosedGoldenMesh) {
  const CliRun r = run_check(std::string("'") + PGAMESH_GOLDEN_DIR + "/meshes/torus.obj' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  const json golden = test::load_golden("mesh_props.json");
  json expected;
  for (const auto& c : golden["cases"])
    if (c["id"] == "torus") expected = c["expected"];
  ASSERT_FALSE(expected.is_null());
  EXPECT_EQ(j["triangles"], expected["triangles"]);
  EXPECT_EQ(j["vertices"], expected["vertices"]);
  EXPECT_EQ(j["closed"], true);
  EXPECT_EQ(j["boundary_edges"], 0);
  EXPECT_EQ(j["nonmanifold_edges"], 0);
  EXPECT_EQ(j["orientation_consistent"], true);
  EXPECT_EQ(j["volume_valid"], true);
  EXPECT_TRUE(test::near_scalar(j["area"].get<double>(), expected["area"].get<double>(), {}));
  EXPECT_TRUE(test::near_scalar(j["volume"].get<double>(), expected["volume"].get<double>(), {}));
  EXPECT_TRUE(test::near_scalar(j["gap_area"].get<double>(), expected["gap_area"].get<double>(),
                                {1e-12, 1e-12}));
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["boundary_loops"].size(), 0u);
  EXPECT_EQ(j["notes"].size(), 0u);
}

TEST(CheckCli, JsonOfAnOpenMeshListsItsLoop) {
  const TempFile file("_open_cube.obj", open_cube_obj);
  const std::string& path = file.path();
  const CliRun r = run_check("'" + path + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;  // an open mesh is a result, not an error
  const json j = parse_json(r.out);
  EXPECT_EQ(j["closed"], false);
  EXPECT_EQ(j["volume_valid"], false);
  EXPECT_EQ(j["boundary_edges"], 4);
  EXPECT_EQ(j["gap_area"], 1.0);
  EXPECT_EQ(j["boundary_loop_count"], 1);
  const json& loop = j["boundary_loops"][0];
  EXPECT_EQ(loop["edges"], 4);
  EXPECT_EQ(loop["area"], 1.0);
  EXPECT_EQ(loop["perimeter"], 4.0);
  EXPECT_EQ(loop["vector_area"], json::array({0.0, 0.0, -1.0}));
  EXPECT_EQ(loop["points"].size(), 4u);
  for (const auto& p : loop["points"]) EXPECT_EQ(p[2], 1.0);  // the rim of the missing top
  EXPECT_EQ(j["volume_range"], json::array({2.0 / 3.0, 1.0}));
  ASSERT_GE(j["notes"].size(), 1u);
  EXPECT_NE(j["notes"][0].get<std::string>().find("not meaningful"), std::string::npos);
  // The readable report says the same in words.
  const CliRun text = run_check("'" + path + "'");
  EXPECT_EQ(text.status, 0);
  EXPECT_NE(text.out.find("NOT MEANINGFUL"), std::string::npos);
  EXPECT_NE(text.out.find("boundary loops      1"), std::string::npos);
}

TEST(CheckCli, FixOrientationWritesTheRepairedMesh) {
  // The closed cube with faces 2 and 5 reversed.
  const TempFile flipped(
      "_flipped_cube.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "f 1 3 4\nf 1 4 2\nf 5 8 6\nf 5 8 7\nf 1 2 6\nf 1 5 6\nf 3 7 8\nf 3 8 4\nf 1 5 7\n"
      "f 1 7 3\nf 2 4 8\nf 2 8 6\n");
  const TempFile repaired("_fixed_cube.obj");  // written by the CLI, removed with `repaired`
  const std::string& in = flipped.path();
  const std::string& out = repaired.path();
  const CliRun r = run_check("'" + in + "' --fix-orientation --output '" + out + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["orientation_fix"]["flipped_faces"], 2);
  EXPECT_EQ(j["orientation_fix"]["components"][0]["flipped_faces"], json::array({2, 5}));
  EXPECT_EQ(j["closed"], true);  // the report describes the repaired mesh
  EXPECT_EQ(j["volume"], 1.0);
  const TopologyReport fixed = analyze_topology(read_mesh(out));
  EXPECT_TRUE(fixed.closed);
  EXPECT_EQ(fixed.volume, 1.0);
}

TEST(CheckCli, UnreadableInputFailsWithTheReadersError) {
  const TempFile file("_bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const std::string& bad = file.path();
  const CliRun r = run_check("'" + bad + "' --json");
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find(bad + ":4"), std::string::npos) << r.err;
  const CliRun missing = run_check("/nonexistent/mesh.stl");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("/nonexistent/mesh.stl"), std::string::npos) << missing.err;
}

TEST(CheckCli, BadOptionsExitTwo) {
  const TempFile file("_open_cube.obj", open_cube_obj);
  const std::string& path = file.path();
  EXPECT_EQ(run_check("'" + path + "' --weld-tolerance -1").status, 2);
  EXPECT_EQ(run_check("'" + path + "' --weld-tolerance abc").status, 2);
  EXPECT_EQ(run_check("'" + path + "' --output x.unknown").status, 2);  // no format
  EXPECT_EQ(run_check("'" + path + "' --bogus").status, 2);
  EXPECT_EQ(run_check("").status, 2);
}

TEST(CheckCli, WeldToleranceIsReported) {
  // Two triangles whose shared edge differs by 1e-9 in one coordinate.
  const TempFile file(
      "_seam.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1.000000001 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 4 6 5\n");
  const std::string& path = file.path();
  const json exact = parse_json(run_check("'" + path + "' --json").out);
  EXPECT_EQ(exact["boundary_edges"], 6);
  EXPECT_EQ(exact["components"], 2);
  const json welded = parse_json(run_check("'" + path + "' --json --weld-tolerance 1e-6").out);
  EXPECT_EQ(welded["boundary_edges"], 4);
  EXPECT_EQ(welded["components"], 1);
  EXPECT_EQ(welded["weld"]["merged_vertices"], 2);
  EXPECT_NEAR(welded["weld"]["max_moved"].get<double>(), 1e-9, 1e-15);

  // --output writes what was analysed: the welded mesh, 4 vertices, the two faces kept.
  const TempFile out("_seam_welded.obj", "");
  ASSERT_EQ(run_check("'" + path + "' --weld-tolerance 1e-6 --output '" + out.path() + "'").status,
            0);
  const Mesh written = read_mesh(out.path());
  EXPECT_EQ(written.vertices.size(), 4u);
  EXPECT_EQ(written.face_count(), 2u);
  EXPECT_EQ(analyze_topology(written).boundary_edges, 4u);
}

}  // namespace
}  // namespace pgamesh
