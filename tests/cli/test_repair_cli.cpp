// `pgamesh repair` and the tolerance weld of `pgamesh fuel`: the repaired file read back and
// measured, the report's counts, the exit codes, and a tank closed only by a weld.
#include <gtest/gtest.h>

#include <string>

#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "support/cli_run.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::CliRun;
using test::json;
using test::parse_json;
using test::run_cli;
using test::TempFile;

// The box [0,2]³ without its top, as unwelded triangles (an STL's soup) in OBJ, plus a
// duplicate of the first triangle.
const char* open_box_soup =
    "v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 0 0\nv 0 2 0\nv 2 2 0\n"  // bottom, facing down
    "v 0 0 0\nv 2 0 0\nv 2 0 2\nv 0 0 0\nv 2 0 2\nv 0 0 2\n"  // y = 0
    "v 2 0 0\nv 2 2 0\nv 2 2 2\nv 2 0 0\nv 2 2 2\nv 2 0 2\n"  // x = 2
    "v 2 2 0\nv 0 2 0\nv 0 2 2\nv 2 2 0\nv 0 2 2\nv 2 2 2\n"  // y = 2
    "v 0 2 0\nv 0 0 0\nv 0 0 2\nv 0 2 0\nv 0 0 2\nv 0 2 2\n"  // x = 0
    "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 10 11 12\nf 13 14 15\nf 16 17 18\nf 19 20 21\nf 22 23 24\n"
    "f 25 26 27\nf 28 29 30\nf 1 2 3\n";

TEST(RepairCli, ClosesAnOpenSoupIntoASolid) {
  const TempFile in("_open_box_soup.obj", open_box_soup);
  const TempFile out("_open_box_repaired.obj", "");
  const CliRun r = run_cli("repair '" + in.path() + "' --output '" + out.path() + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["weld"]["merged"], 30 - 8);
  EXPECT_EQ(j["removed_faces"]["duplicated"], 1);
  EXPECT_EQ(j["removed_faces"]["list"], json::array({10}));
  EXPECT_EQ(j["holes"]["count"], 1);
  EXPECT_EQ(j["holes"]["capped"], 1);
  EXPECT_EQ(j["holes"]["cap_triangles"], 2);
  EXPECT_EQ(j["holes"]["list"][0]["area"], 4.0);
  EXPECT_EQ(j["result"]["closed"], true);
  EXPECT_EQ(j["result"]["volume_valid"], true);
  EXPECT_EQ(j["result"]["volume"], 8.0);
  // The file holds what the report describes.
  const TopologyReport t = analyze_topology(read_mesh(out.path()));
  EXPECT_TRUE(t.closed);
  EXPECT_EQ(t.volume, 8.0);
  EXPECT_EQ(t.faces, 12u);
}

TEST(RepairCli, ReadableReportAndRefusals) {
  const TempFile in("_open_box_soup_text.obj", open_box_soup);
  const TempFile out("_open_box_text.stl", "");
  const CliRun r = run_cli("repair '" + in.path() + "' -o '" + out.path() + "' --no-caps");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("holes           1: 0 capped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not a solid"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote " + out.path()), std::string::npos) << r.out;

  EXPECT_EQ(run_cli("repair '" + in.path() + "'").status, 2);  // --output is required
  EXPECT_EQ(run_cli("repair '" + in.path() + "' -o x.unknown").status, 2);
  EXPECT_EQ(run_cli("repair '" + in.path() + "' -o x.obj --planarity -1").status, 2);
  const CliRun missing = run_cli("repair /nonexistent/in.stl -o '" + out.path() + "'");
  EXPECT_EQ(missing.status, 1);
  EXPECT_TRUE(missing.out.empty());
  EXPECT_NE(missing.err.find("/nonexistent/in.stl"), std::string::npos) << missing.err;
}

// A closed unit cube whose two halves are 4e-9 apart at their seam: `fuel` refuses it as read
// and gauges it welded within 1e-6.
TEST(FuelWeldTolerance, GaugesATankClosedByAWeld) {
  const TempFile in("_seam_cube.obj",
                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                    "v 1.000000004 0 0\nv 1.000000004 1 0\nv 1.000000004 1 1\nv 1.000000004 0 1\n"
                    "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\n"
                    "f 1 5 8\nf 1 8 4\nf 9 10 11\nf 9 11 12\n");
  EXPECT_EQ(run_cli("fuel '" + in.path() + "' --fraction 0.5").status, 1);
  const CliRun r = run_cli("fuel '" + in.path() + "' --fraction 0.5 --weld-tolerance 1e-6 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["weld"]["merged"], 4);
  EXPECT_NEAR(j["weld"]["max_moved"].get<double>(), 4e-9, 1e-15);
  EXPECT_EQ(j["tank_volume"], 1.0);
  EXPECT_NEAR(j["level"].get<double>(), 0.5, 1e-12);
}

}  // namespace
}  // namespace pgamesh
