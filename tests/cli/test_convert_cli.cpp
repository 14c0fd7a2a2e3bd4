// `pgamesh convert` through every format it writes, the units of props/check/fuel, and the SI
// robot-description exports (URDF, MJCF, SDF) against the closed forms of a cube.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <string>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/cube_file.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

std::string shell_quoted(const std::string& path) {
  return "\"" + path + "\"";
}

bool same_figure(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The mass properties of two analyses agree bit for bit.
void expect_same_mass_properties(const Analysis& got, const Analysis& want) {
  EXPECT_TRUE(same_figure(got.mass.volume, want.mass.volume))
      << got.mass.volume << " vs " << want.mass.volume;
  EXPECT_TRUE(same_figure(got.mass.area, want.mass.area));
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(same_figure(got.mass.center_of_mass[k], want.mass.center_of_mass[k])) << k;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_TRUE(same_figure(got.mass.inertia_com[i][j], want.mass.inertia_com[i][j])) << i << j;
}

// A triangulated box with float32-representable corners (dyadic fractions) off the origin.
std::string float_box_obj() {
  return "v 0.5 -1.25 2\nv 3 -1.25 2\nv 3 0.75 2\nv 0.5 0.75 2\n"
         "v 0.5 -1.25 2.375\nv 3 -1.25 2.375\nv 3 0.75 2.375\nv 0.5 0.75 2.375\n"
         "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
         "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
}

TEST(ConvertCli, EveryFormatGivesTheSameMassPropertiesBitForBit) {
  const TempFile input(".obj", float_box_obj());
  const Analysis want = analyze_file(input.path());
  EXPECT_DOUBLE_EQ(want.mass.volume, 2.5 * 2 * 0.375);
  for (const char* ext : {".stl", ".obj", ".ply", ".off", ".gltf", ".glb", ".slp"}) {
    SCOPED_TRACE(ext);
    const TempFile out(ext);
    const CliRun r =
        run_cli("convert " + shell_quoted(input.path()) + " " + shell_quoted(out.path()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + out.path()), std::string::npos) << r.out;
    expect_same_mass_properties(analyze_file(out.path()), want);
  }
  for (const char* format : {"stl-ascii", "ply-be", "ply"}) {
    SCOPED_TRACE(format);
    const TempFile out(".mesh");
    const CliRun r = run_cli("convert " + shell_quoted(input.path()) + " " +
                             shell_quoted(out.path()) + " --format " + format);
    ASSERT_EQ(r.status, 0) << r.err;
    expect_same_mass_properties(analyze_file(out.path()), want);
  }
}

TEST(ConvertCli, DoubleFormatsKeepCoordinatesThatFloat32WouldRound) {
  const TempFile input(".obj", cube_obj(0.1, 1.0 / 3.0));
  const Mesh want = read_mesh(input.path());
  for (const char* ext : {".obj", ".ply", ".off"}) {
    SCOPED_TRACE(ext);
    const TempFile out(ext);
    ASSERT_EQ(
        run_cli("convert " + shell_quoted(input.path()) + " " + shell_quoted(out.path())).status,
        0);
    EXPECT_EQ(read_mesh(out.path()).vertices, want.vertices);
  }
  // glTF stores float32: the coordinates come back rounded, as documented.
  const TempFile gltf(".gltf");
  ASSERT_EQ(
      run_cli("convert " + shell_quoted(input.path()) + " " + shell_quoted(gltf.path())).status, 0);
  const Mesh back = read_mesh(gltf.path());
  ASSERT_EQ(back.vertices.size(), want.vertices.size());
  EXPECT_EQ(back.vertices[0].x, static_cast<double>(static_cast<float>(want.vertices[0].x)));
}

TEST(ConvertCli, UnitsAreConvertedByTheExactFactorAndSaidSo) {
  const TempFile input(".obj", float_box_obj());
  const TempFile metres(".glb");
  // A unitless file said to be in millimetres, written as glTF: metres by definition.
  CliRun r = run_cli("convert " + shell_quoted(input.path()) + " " + shell_quoted(metres.path()) +
                     " --unit mm");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("from mm to m"), std::string::npos) << r.out;
  MeshSource source;
  const Mesh in_metres = read_mesh(metres.path(), &source);
  EXPECT_EQ(source.unit, LengthUnit::meter);
  EXPECT_EQ(in_metres.vertices[1].x, static_cast<double>(static_cast<float>(3 * 1e-3)));
  // Back from metres to millimetres: the factor 1 / 1e-3 = 1000.
  const TempFile mm(".obj");
  r = run_cli("convert " + shell_quoted(metres.path()) + " " + shell_quoted(mm.path()) +
              " --unit mm");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("scaled the coordinates by 1000 from m to mm"), std::string::npos) << r.out;
  EXPECT_EQ(read_mesh(mm.path()).vertices[1].x,
            static_cast<double>(static_cast<float>(3 * 1e-3)) * 1000);
}

TEST(ConvertCli, ErrorsNameTheFile) {
  const TempFile input(".obj", float_box_obj());
  CliRun r = run_cli("convert " + shell_quoted(input.path()) + " out.unknown-extension");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("out.unknown-extension"), std::string::npos) << r.err;
  const TempFile broken(".gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"mesh\": 4}]}");
  const TempFile out(".obj");
  r = run_cli("convert " + shell_quoted(broken.path()) + " " + shell_quoted(out.path()));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(broken.path()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nodes[0].mesh"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(run_cli("convert --help").status, 0);
}

TEST(UnitsCli, OutputsNameTheUnitOrSayUnitless) {
  const TempFile cube(".obj", cube_obj(10));
  CliRun r = run_cli("props " + shell_quoted(cube.path()) + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_json(r.out)["unit"], "unitless");
  r = run_cli("props " + shell_quoted(cube.path()) + " --json --unit mm");
  EXPECT_EQ(parse_json(r.out)["unit"], "mm");
  r = run_cli("props " + shell_quoted(cube.path()) + " --unit mm");
  EXPECT_NE(r.out.find("volume            1000 mm^3"), std::string::npos) << r.out;
  r = run_cli("check " + shell_quoted(cube.path()) + " --json --unit in");
  EXPECT_EQ(parse_json(r.out)["unit"], "in");
  // A glTF states metres: another --unit is refused, naming the file.
  const TempFile gltf(".gltf");
  ASSERT_EQ(run_cli("convert " + shell_quoted(cube.path()) + " " + shell_quoted(gltf.path()) +
                    " --unit m")
                .status,
            0);
  r = run_cli("props " + shell_quoted(gltf.path()) + " --json");
  EXPECT_EQ(parse_json(r.out)["unit"], "m");
  r = run_cli("props " + shell_quoted(gltf.path()) + " --unit mm");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(gltf.path()), std::string::npos) << r.err;
  EXPECT_EQ(run_cli("props " + shell_quoted(cube.path()) + " --unit furlong").status, 2);
}

// The value after `key` (an attribute key=" or an element <key>) in `xml`.
double xml_value(const std::string& xml, const std::string& key) {
  const auto at = xml.find(key);
  if (at == std::string::npos) {
    ADD_FAILURE() << key << " not in " << xml;
    return NAN;
  }
  return std::strtod(xml.c_str() + at + key.size(), nullptr);
}

// A cube of side 10 mm and density 1000 kg/m³: a = 0.01 m, m = 1000 a³ = 1e-3 kg, centre
// (0.005, 0.005, 0.005) m, I = m (a² + a²) / 12 about its centre; the same part given in metres
// exports the same figures.
TEST(ExportsCli, SiFiguresOfAMillimetreCubeMatchTheClosedForm) {
  const double a = 0.01, mass = 1000 * a * a * a, inertia = mass * (a * a + a * a) / 12;
  const TempFile mm(".obj", cube_obj(10));
  const TempFile m(".obj", cube_obj(0.01));
  for (const auto& [file, unit] : {std::pair{&mm, "mm"}, std::pair{&m, "m"}}) {
    SCOPED_TRACE(unit);
    const std::string args =
        "props " + shell_quoted(file->path()) + " --density 1000 --unit " + std::string(unit);
    const CliRun sdf = run_cli(args + " --sdf");
    ASSERT_EQ(sdf.status, 0) << sdf.err;
    EXPECT_NE(sdf.out.find("<sdf version=\"1.7\">"), std::string::npos);
    EXPECT_NEAR(xml_value(sdf.out, "<mass>"), mass, 1e-13 * mass);
    EXPECT_NEAR(xml_value(sdf.out, "<ixx>"), inertia, 1e-11 * inertia);
    EXPECT_NEAR(xml_value(sdf.out, "<izz>"), inertia, 1e-11 * inertia);
    EXPECT_NEAR(xml_value(sdf.out, "<ixy>"), 0, 1e-11 * inertia);
    EXPECT_NEAR(xml_value(sdf.out, "<pose>"), a / 2, 1e-15);
    EXPECT_NE(sdf.out.find("<uri>file://" + file->path() + "</uri>"), std::string::npos) << sdf.out;
    EXPECT_NEAR(xml_value(sdf.out, "<scale>"), unit == std::string("mm") ? 1e-3 : 1, 0);

    const CliRun urdf = run_cli(args + " --urdf");
    ASSERT_EQ(urdf.status, 0) << urdf.err;
    EXPECT_NEAR(xml_value(urdf.out, "<mass value=\""), mass, 1e-13 * mass);
    EXPECT_NEAR(xml_value(urdf.out, "ixx=\""), inertia, 1e-11 * inertia);
    EXPECT_NEAR(xml_value(urdf.out, "<origin xyz=\""), a / 2, 1e-15);
    EXPECT_NE(urdf.out.find("<mesh filename=\"file://" + file->path() + "\" scale=\""),
              std::string::npos)
        << urdf.out;

    const CliRun mjcf = run_cli(args + " --mjcf");
    ASSERT_EQ(mjcf.status, 0) << mjcf.err;
    EXPECT_NEAR(xml_value(mjcf.out, "mass=\""), mass, 1e-13 * mass);
    EXPECT_NEAR(xml_value(mjcf.out, "diaginertia=\""), inertia, 1e-11 * inertia);
    EXPECT_NE(mjcf.out.find("file=\"" + file->path() + "\" scale=\""), std::string::npos)
        << mjcf.out;
    EXPECT_EQ(sdf.err.find("assume"), std::string::npos) << sdf.err;
  }
  // Without a unit: metres are assumed, with a warning.
  const CliRun r = run_cli("props " + shell_quoted(m.path()) + " --density 1000 --sdf");
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("assume metres"), std::string::npos) << r.err;
  EXPECT_NEAR(xml_value(r.out, "<mass>"), mass, 1e-13 * mass);
}

}  // namespace
}  // namespace pgamesh::test
