// `pgamesh props` end to end: runs the built CLI (PGAMESH_CLI_PATH) on golden and real meshes,
// parses its JSON and checks it against golden/mesh_props.json; URDF/MJCF output; errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/solids.hpp"
#include "support/stl_bytes.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::flatten;
using pgamesh::test::json;
using pgamesh::test::near_group;
using pgamesh::test::near_scalar;
using pgamesh::test::parse_json;
using pgamesh::test::run_cli;
using pgamesh::test::TempFile;

namespace {

std::string golden_mesh(const std::string& name) {
  return std::string(PGAMESH_GOLDEN_DIR) + "/meshes/" + name;
}

const json* golden_case(const json& file, const std::string& id) {
  for (const json& c : file["cases"])
    if (c["id"] == id) return &c;
  return nullptr;
}

}  // namespace

TEST(MassCli, JsonMatchesGolden) {
  const json file = pgamesh::test::load_golden("mesh_props.json");
  for (const char* id : {"unit_cube", "ellipsoid_L3", "torus", "ellipsoid_L3_far"}) {
    SCOPED_TRACE(id);
    const json* c = golden_case(file, id);
    ASSERT_NE(c, nullptr);
    const CliRun r = run_cli("props \"" + golden_mesh(std::string(id) + ".obj") + "\" --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const json got = parse_json(r.out);
    const json& e = (*c)["expected"];
    const auto tol = pgamesh::test::tolerance_of(file, *c);
    EXPECT_EQ(got["triangles"], e["triangles"]);
    EXPECT_EQ(got["vertices"], e["vertices"]);
    EXPECT_EQ(got["closed"], e["closed"]);
    EXPECT_EQ(got["boundary_edges"], e["boundary_edges"]);
    EXPECT_EQ(got["nonmanifold_edges"], e["nonmanifold_edges"]);
    EXPECT_EQ(got["orientation_consistent"], e["orientation_consistent"]);
    for (const char* k : {"area", "volume", "density", "mass", "gap_area"}) {
      EXPECT_TRUE(near_scalar(got[k].get<double>(), e[k].get<double>(), tol)) << k;
    }
    for (const char* k : {"center_of_mass", "inertia_com", "inertia_origin", "principal_moments"}) {
      EXPECT_TRUE(near_group(flatten(got[k]), flatten(e[k]), tol)) << k;
    }
    if (!e["principal_axes"].is_null()) {
      EXPECT_TRUE(
          near_group(flatten(got["principal_axes"]), flatten(e["principal_axes"]), {1e-9, 1e-9}));
    }
    EXPECT_EQ(got["principal_degenerate"], e["principal_axes"].is_null());
    EXPECT_EQ(got["volume_valid"], true);
    // Products of inertia are named as such: minus the tensor's off-diagonals.
    EXPECT_DOUBLE_EQ(got["products_of_inertia_com"]["xy"].get<double>(),
                     -got["inertia_com"][0][1].get<double>());
    EXPECT_NE(got["convention"].get<std::string>().find("minus the products of inertia"),
              std::string::npos);
  }
}

TEST(MassCli, DensityAndMassOptions) {
  const std::string cube = "props \"" + golden_mesh("unit_cube.obj") + "\" --json";
  const json d = parse_json(run_cli(cube + " --density 2.5").out);
  EXPECT_DOUBLE_EQ(d["mass"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(d["inertia_com"][0][0].get<double>(), 2.5 / 6);
  const json m = parse_json(run_cli(cube + " --mass 4").out);
  EXPECT_DOUBLE_EQ(m["density"].get<double>(), 4);
  EXPECT_EQ(m["density_source"], "mass");
  const CliRun both = run_cli(cube + " --mass 4 --density 2");
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("not both"), std::string::npos);
}

TEST(MassCli, OpenMeshIsNotMeaningful) {
  // The unit cube without its top quad, written as OBJ: gap = missing area 1.
  const TempFile file("_open.obj",
                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                      "f 1 4 3 2\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n");
  const std::filesystem::path path = file.path();
  const CliRun r = run_cli("props \"" + path.string() + "\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json got = parse_json(r.out);
  EXPECT_EQ(got["closed"], false);
  EXPECT_EQ(got["boundary_edges"], 4);
  EXPECT_DOUBLE_EQ(got["gap_area"].get<double>(), 1);
  EXPECT_EQ(got["volume_valid"], false);
  EXPECT_FALSE(got["reasons"].empty());
  const CliRun text = run_cli("props \"" + path.string() + "\"");
  EXPECT_NE(text.out.find("NOT MEANINGFUL"), std::string::npos);
}

TEST(MassCli, StreamedStlMatchesTopologyPath) {
  const pgamesh::Mesh m = pgamesh::test::uv_sphere(1.5, 16, 24);
  const std::vector<char> bytes = pgamesh::test::binary_stl_bytes(m);
  const TempFile file("_sphere.stl", {bytes.data(), bytes.size()});
  const std::filesystem::path path = file.path();
  const json fast = parse_json(run_cli("props \"" + path.string() + "\" --json --fast").out);
  const json full = parse_json(run_cli("props \"" + path.string() + "\" --json").out);
  EXPECT_EQ(fast["streamed"], true);
  EXPECT_EQ(full["streamed"], false);
  EXPECT_TRUE(fast["closed"].is_null());
  EXPECT_TRUE(fast["volume_valid"].is_null());
  EXPECT_EQ(full["closed"], true);
  EXPECT_EQ(full["vertices"], m.vertices.size());  // welded
  EXPECT_EQ(fast["input_vertices"], 3 * fast["triangles"].get<int>());
  EXPECT_DOUBLE_EQ(fast["volume"].get<double>(), full["volume"].get<double>());
  EXPECT_TRUE(
      near_group(flatten(fast["inertia_com"]), flatten(full["inertia_com"]), {1e-15, 1e-15}));
}

TEST(MassCli, FusedAsciiStlMatchesTopologyPathAndKeepsErrorPositions) {
  const pgamesh::Mesh m = pgamesh::test::triangulated(pgamesh::test::uv_sphere(1.5, 16, 24));
  const std::string text = pgamesh::write_mesh_bytes(m, pgamesh::MeshFormat::stl_ascii);
  const TempFile file("_ascii.stl", text);
  const std::filesystem::path path = file.path();
  const json fast = parse_json(run_cli("props \"" + path.string() + "\" --json --fast").out);
  const json full = parse_json(run_cli("props \"" + path.string() + "\" --json").out);
  EXPECT_EQ(fast["streamed"], true);
  EXPECT_EQ(fast["format"], "stl-ascii");
  EXPECT_EQ(full["streamed"], false);
  EXPECT_EQ(fast["triangles"], full["triangles"]);
  EXPECT_EQ(fast["input_vertices"], 3 * fast["triangles"].get<int>());
  EXPECT_DOUBLE_EQ(fast["volume"].get<double>(), full["volume"].get<double>());
  EXPECT_TRUE(
      near_group(flatten(fast["inertia_com"]), flatten(full["inertia_com"]), {1e-15, 1e-15}));
  // A bad number in facet 3: the fused pass declines and the reader names line:column.
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) at = text.find("facet normal", at) + 1;
  const auto vertex = text.find("vertex ", at) + 7;
  const std::string bad = text.substr(0, vertex) + "x" + text.substr(vertex);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bad;
  const auto line = 1 + std::count(bad.begin(), bad.begin() + static_cast<long>(vertex), '\n');
  const std::string where = ":" + std::to_string(line) + ":10";
  for (const char* flags : {"--fast", ""}) {
    const CliRun r = run_cli("props \"" + path.string() + "\" " + flags);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(path.string() + where), std::string::npos) << r.err;
  }
}

TEST(MassCli, UrdfAndMjcf) {
  const std::string box = "props \"" + golden_mesh("unit_cube.obj") + "\" --density 2";
  const CliRun urdf = run_cli(box + " --urdf");
  ASSERT_EQ(urdf.status, 0);
  EXPECT_NE(urdf.out.find("<inertial>"), std::string::npos);
  EXPECT_NE(urdf.out.find("<origin xyz=\"0.5 0.5 0.5\""), std::string::npos);
  EXPECT_NE(urdf.out.find("<mass value=\"2\"/>"), std::string::npos);
  EXPECT_NE(urdf.out.find("ixx=\"0.33333333333333"), std::string::npos);
  EXPECT_NE(urdf.out.find("-integral x y dm"), std::string::npos);  // convention stated
  const CliRun mjcf = run_cli(box + " --mjcf");
  ASSERT_EQ(mjcf.status, 0);
  EXPECT_NE(mjcf.out.find("<inertial pos=\"0.5 0.5 0.5\""), std::string::npos);
  EXPECT_NE(mjcf.out.find("diaginertia=\"0.33333333333333"), std::string::npos);
  EXPECT_NE(mjcf.out.find("quat=\""), std::string::npos);
  // XML comments must not contain "--".
  const auto body = mjcf.out.substr(4, mjcf.out.find("-->") - 4);
  EXPECT_EQ(body.find("--"), std::string::npos);
}

TEST(MassCli, OwnInwardCubeReportsNegativeVolume) {
  // Our own inward mesh: the unit cube with every face wound clockwise seen from outside.
  const pgamesh::test::TempFile obj(".obj",
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                    "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\n"
                                    "f 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n");
  const CliRun r = run_cli("props \"" + obj.path() + "\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json got = parse_json(r.out);
  EXPECT_EQ(got["volume"].get<double>(), -1);  // integer corners: exact
  EXPECT_EQ(got["volume_valid"], false);
}

TEST(MassCli, InwardMeshReportsNegativeVolume) {
  // Extra: the inward mushroom of geomview (GPL, not bundled).
  EXTRA_WITH_REAL_MESHES("geomview/mushroom.off");
  const std::string dir = pgamesh::test::shared_meshes_dir();
  const CliRun r = run_cli("props \"" + dir + "/geomview/mushroom.off\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json got = parse_json(r.out);
  EXPECT_LT(got["volume"].get<double>(), 0);
  EXPECT_EQ(got["volume_valid"], false);
}

TEST(MassCli, ErrorsNameTheFileAndPosition) {
  const std::string dir = pgamesh::test::shared_meshes_dir();
  if (!dir.empty()) {
    const CliRun r = run_cli("props \"" + dir + "/stl-models/incorrectFaceCounter.bin.stl\"");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("incorrectFaceCounter.bin.stl"), std::string::npos);
    EXPECT_NE(r.err.find("byte"), std::string::npos);
    EXPECT_TRUE(r.out.empty());
    const CliRun fast =
        run_cli("props \"" + dir + "/stl-models/incorrectFaceCounter.bin.stl\" --fast --json");
    EXPECT_NE(fast.status, 0);
    EXPECT_NE(fast.err.find("byte"), std::string::npos);
  }
  const CliRun missing = run_cli("props /nonexistent/part.stl");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("/nonexistent/part.stl"), std::string::npos);
  EXPECT_EQ(run_cli("props").status, 2);
  EXPECT_EQ(run_cli("props a.stl --density").status, 2);
  EXPECT_EQ(run_cli("props a.stl --density nan").status, 2);
  EXPECT_EQ(run_cli("props a.stl --bogus").status, 2);
}

TEST(MassCli, ReadableOutputStatesTheConvention) {
  const CliRun r = run_cli("props \"" + golden_mesh("ellipsoid_L3.obj") + "\" --about-origin");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("MINUS the products of inertia"), std::string::npos);
  EXPECT_NE(r.out.find("inertia about the origin"), std::string::npos);
  EXPECT_NE(r.out.find("principal moments (ascending)"), std::string::npos);
  EXPECT_NE(r.out.find("closed"), std::string::npos);
}

TEST(MassCli, MjcfQuaternionTurnsTheMeshFrameOntoThePrincipalAxes) {
  const std::string mesh = "props \"" + golden_mesh("ellipsoid_L3_far.obj") + "\"";
  const json got = parse_json(run_cli(mesh + " --json").out);
  const std::string mjcf = run_cli(mesh + " --mjcf").out;
  const auto at = mjcf.find("quat=\"");
  ASSERT_NE(at, std::string::npos);
  std::array<double, 4> q{};
  std::sscanf(mjcf.c_str() + at + 6, "%lf %lf %lf %lf", &q[0], &q[1], &q[2], &q[3]);
  // Hamilton rotation of e_i by (w, x, y, z): column i of the rotation matrix.
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(r[k][i], got["principal_axes"][i][k].get<double>(), 1e-12) << i << "," << k;
}
