// `pgamesh fuel` end to end: golden values through --json and --csv, the attitude convention,
// and the errors (open mesh, zero up vector, levels outside the tank, volumes too large).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::json;
using pgamesh::test::parse_json;
using pgamesh::test::run_cli;
using pgamesh::test::TempFile;

namespace {

// Runs `pgamesh fuel ARGS`.
CliRun run_fuel(const std::string& args) {
  return run_cli("fuel " + args);
}

std::string golden_mesh(const std::string& name) {
  return std::string(PGAMESH_GOLDEN_DIR) + "/meshes/" + name;
}

std::string vec_arg(const json& j) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g", j[0].get<double>(), j[1].get<double>(),
                j[2].get<double>());
  return buf;
}

std::string num_arg(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

const json& golden_case(const json& file, const std::string& id) {
  for (const json& c : file["cases"])
    if (c["id"] == id) return c;
  throw std::runtime_error("no golden case " + id);
}

}  // namespace

TEST(FuelCli, LevelJsonMatchesGolden) {
  const json file = pgamesh::test::load_golden("fuel_slices.json");
  for (const char* id : {"cube_tilted_plane_0.45", "torus_tilted_0.2", "icosphere_L4_level_0"}) {
    SCOPED_TRACE(id);
    const json& c = golden_case(file, id);
    const std::string mesh =
        std::string(PGAMESH_GOLDEN_DIR) + "/" + c["input"]["mesh"].get<std::string>();
    const CliRun r = run_fuel(mesh + " --up " + vec_arg(c["input"]["up"]) + " --level " +
                              num_arg(c["input"]["level"].get<double>()) + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = parse_json(r.out);
    const json& e = c["expected"];
    for (const char* k : {"level", "volume", "fraction", "wetted_area", "surface_area"})
      EXPECT_NEAR(out[k].get<double>(), e[k].get<double>(),
                  1e-12 * (1 + std::abs(e[k].get<double>())))
          << k;
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(out["center_of_mass"][i].get<double>(), e["center_of_mass"][i].get<double>(),
                  1e-12);
    EXPECT_TRUE(out.contains("inertia_com"));
    EXPECT_TRUE(out.contains("conventions"));
    EXPECT_NEAR(out["ullage_volume"].get<double>() + out["volume"].get<double>(),
                out["tank_volume"].get<double>(), 1e-12);
  }
}

TEST(FuelCli, VolumeAndFractionSolveForTheLevel) {
  const json file = pgamesh::test::load_golden("fuel_slices.json");
  const json& c = golden_case(file, "inverse_icosphere_L4_1litre");
  const std::string mesh = golden_mesh("icosphere_L4.obj");
  CliRun r = run_fuel(mesh + " --up " + vec_arg(c["input"]["up"]) + " --volume 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  json out = parse_json(r.out);
  EXPECT_NEAR(out["level"].get<double>(), c["expected"]["level"].get<double>(), 1e-10);
  EXPECT_NEAR(out["volume"].get<double>(), 1.0, 1e-12);
  r = run_fuel(golden_mesh("cube_tilted.obj") + " --fraction 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  out = parse_json(r.out);
  EXPECT_NEAR(out["level"].get<double>(), 1.4475067636685255, 1e-10);
  // A list of volumes.
  r = run_fuel(golden_mesh("unit_cube.obj") + " --volumes 0.25,0.5,1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  out = parse_json(r.out);
  ASSERT_EQ(out["rows"].size(), 3u);
  EXPECT_NEAR(out["rows"][0]["level"].get<double>(), 0.25, 1e-12);
  EXPECT_NEAR(out["rows"][2]["level"].get<double>(), 1.0, 1e-12);
}

TEST(FuelCli, GaugeTableCsvMatchesGolden) {
  const json file = pgamesh::test::load_golden("fuel_slices.json");
  const json& c = golden_case(file, "gauge_cube_tilted");
  const CliRun r = run_fuel(golden_mesh("cube_tilted.obj") + " --up 0,0,1 --table 10 --csv");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::vector<std::vector<double>> rows;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      EXPECT_EQ(line.rfind("level,volume,fraction,com_x,com_y,com_z,wetted_area,surface_area", 0),
                0u);
      EXPECT_NE(line.find("ullage_length,ullage_volume"), std::string::npos);
      header = true;
      continue;
    }
    std::vector<double> row;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) row.push_back(cell.empty() ? NAN : std::stod(cell));
    rows.push_back(row);
  }
  const json& expected = c["expected"]["rows_level_volume"];
  ASSERT_EQ(rows.size(), expected.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i][0], expected[i][0].get<double>(), 1e-12);
    EXPECT_NEAR(rows[i][1], expected[i][1].get<double>(), 1e-12);
  }
  EXPECT_NE(r.out.find("# units"), std::string::npos);
}

TEST(FuelCli, AttitudeGridAndAcceleration) {
  const std::string mesh = std::string(PGAMESH_BUNDLED_MESHES_DIR) + "/tank.obj";
  if (!std::filesystem::exists(mesh)) GTEST_SKIP() << "no bundled tank.obj";
  CliRun r = run_fuel(mesh + " --pitch 10 --roll -5 --fraction 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  json out = parse_json(r.out);
  const double p = 10 * std::numbers::pi / 180, f = -5 * std::numbers::pi / 180;
  EXPECT_NEAR(out["up"][0].get<double>(), std::sin(p), 1e-15);
  EXPECT_NEAR(out["up"][1].get<double>(), std::sin(f) * std::cos(p), 1e-15);
  EXPECT_NEAR(out["up"][2].get<double>(), std::cos(f) * std::cos(p), 1e-15);
  EXPECT_NEAR(out["fraction"].get<double>(), 0.5, 1e-12);
  r = run_fuel(mesh + " --pitch 0,5 --roll 0,2,4 --table 4 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  out = parse_json(r.out);
  ASSERT_EQ(out["attitudes"].size(), 6u);
  EXPECT_EQ(out["attitudes"][5]["rows"].size(), 5u);
  EXPECT_EQ(out["attitudes"][5]["roll_deg"].get<double>(), 4);
  r = run_fuel(mesh + " --accel 0,0,-9.81 --level 0.3 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r.out)["up"][2].get<double>(), 1);
}

TEST(FuelCli, Errors) {
  // An open mesh: the unit cube without its top is refused, with the gap, unless --force.
  const TempFile open_file("_open.obj");
  const std::filesystem::path open_path = open_file.path();
  {
    std::ifstream in(golden_mesh("unit_cube.obj"));
    std::ofstream out(open_path);
    std::string line;
    while (std::getline(in, line))
      if (line != "f 5 6 8" && line != "f 5 8 7") out << line << "\n";
  }
  CliRun r = run_fuel(open_path.string() + " --level 0.5 --json");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("open"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("gap area 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(open_path.string()), std::string::npos) << r.err;
  r = run_fuel(open_path.string() + " --level 0.5 --json --force");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning"), std::string::npos);

  const std::string cube = golden_mesh("unit_cube.obj");
  r = run_fuel(cube + " --up 0,0,0 --level 0.5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("up vector must not be zero"), std::string::npos) << r.err;
  r = run_fuel(cube + " --up 0,nan,1 --level 0.5");
  EXPECT_EQ(r.status, 2);
  r = run_fuel(cube + " --level -0.5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("below"), std::string::npos);
  EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
  r = run_fuel(cube + " --level 1.5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("full"), std::string::npos) << r.err;
  r = run_fuel(cube + " --volume 2");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("exceeds the tank's volume 1"), std::string::npos) << r.err;
  r = run_fuel(cube + " --volume -1");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("negative"), std::string::npos) << r.err;
  r = run_fuel(cube + " --table 0");
  EXPECT_EQ(r.status, 2);
  r = run_fuel(cube);
  EXPECT_EQ(r.status, 2);
  r = run_fuel("/nonexistent/tank.obj --level 0");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/tank.obj"), std::string::npos) << r.err;
}

TEST(FuelCli, TopologyFromTheSharedReportRefusesInconsistentMeshes) {
  // The unit cube with one top triangle turned over: closed by its edges' count, but two edges
  // are used twice in one direction. Refused with the figures and notes of `pgamesh check`.
  const TempFile flipped_file("_flipped.obj");
  const std::filesystem::path path = flipped_file.path();
  {
    std::ifstream in(golden_mesh("unit_cube.obj"));
    std::ofstream out(path);
    std::string line;
    while (std::getline(in, line)) out << (line == "f 5 6 8" ? "f 5 8 6" : line) << "\n";
  }
  CliRun r = run_fuel(path.string() + " --level 0.5 --json");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("orientation INCONSISTENT"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("orientation inconsistent: 3 edges"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  r = run_fuel(path.string() + " --level 0.5 --json --force");
  ASSERT_EQ(r.status, 0) << r.err;
  json out = parse_json(r.out);
  EXPECT_TRUE(out["forced"].get<bool>());
  EXPECT_FALSE(out["topology"]["orientation_consistent"].get<bool>());
  EXPECT_EQ(out["topology"]["inconsistent_edges"].get<int>(), 3);

  // A good tank says so.
  r = run_fuel(golden_mesh("unit_cube.obj") + " --level 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  out = parse_json(r.out);
  EXPECT_FALSE(out["forced"].get<bool>());
  EXPECT_TRUE(out["topology"]["closed"].get<bool>());
  EXPECT_EQ(out["topology"]["boundary_edges"].get<int>(), 0);
  EXPECT_EQ(out["topology"]["gap_area"].get<double>(), 0);
}

TEST(FuelCli, DensityAndMassScaleMassAndInertia) {
  // Unit cube half full: volume 1/2, the box [0,1]×[0,1]×[0,½]: I_xx = ρ V (1 + ¼)/12 about its
  // centre of mass, I_zz = ρ V (1 + 1)/12.
  const std::string cube = golden_mesh("unit_cube.obj");
  for (const std::string& option : {std::string("--density 800"), std::string("--mass 800")}) {
    CliRun r = run_fuel(cube + " --level 0.5 --json " + option);
    ASSERT_EQ(r.status, 0) << r.err;
    const json out = parse_json(r.out);
    EXPECT_NEAR(out["density"].get<double>(), 800, 1e-12);
    EXPECT_NEAR(out["tank_mass"].get<double>(), 800, 1e-12);
    EXPECT_NEAR(out["mass"].get<double>(), 400, 1e-12);
    EXPECT_NEAR(out["inertia_com"][0][0].get<double>(), 400 * 1.25 / 12, 1e-10);
    EXPECT_NEAR(out["inertia_com"][2][2].get<double>(), 400 * 2.0 / 12, 1e-10);
    EXPECT_NEAR(out["inertia_com"][0][1].get<double>(), 0, 1e-10);
  }
  CliRun r = run_fuel(cube + " --table 2 --csv --density 2.5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("# density 2.5\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ullage_volume,mass\n"), std::string::npos) << r.out;
  // The middle row: volume 0.5, mass 1.25 in the last column.
  std::istringstream in(r.out);
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#' && line[0] != 'l') rows.push_back(line);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(std::stod(rows[1].substr(rows[1].rfind(',') + 1)), 1.25, 1e-12);
  r = run_fuel(cube + " --level 0.5 --density 1 --mass 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("not both"), std::string::npos) << r.err;
}
