// The command line itself: help for every command (`pgamesh help X` = `pgamesh X --help`), usage
// errors exit 2 naming the option, numbers read the same whatever the locale, and the one JSON
// vocabulary of props, check and fuel (docs/json.md).
#include <gtest/gtest.h>

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

// The golden mesh NAME, quoted for the shell.
std::string quoted_golden_mesh(const std::string& name) {
  std::string quoted =
      "\"";  // built in steps: GCC 12 misreads "\"" + std::string(...) (-Wrestrict)
  quoted += PGAMESH_GOLDEN_DIR;
  quoted += "/meshes/";
  quoted += name;
  quoted += "\"";
  return quoted;
}

const char* const flat_triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

}  // namespace

TEST(CliUsage, HelpCommandPrintsTheCommandsHelp) {
  for (const char* command : {"props", "check", "fuel", "demo", "calc"}) {
    SCOPED_TRACE(command);
    const CliRun direct = run_cli(std::string(command) + " --help");
    const CliRun via_help = run_cli(std::string("help ") + command);
    EXPECT_EQ(direct.status, 0) << direct.err;
    EXPECT_EQ(via_help.status, 0) << via_help.err;
    EXPECT_FALSE(direct.out.empty());
    EXPECT_EQ(direct.out, via_help.out);
  }
  // demo --help is help, not the demo.
  const CliRun demo = run_cli("demo --help");
  EXPECT_EQ(demo.out.find("tetra o v a v b v c"), std::string::npos) << demo.out;
  EXPECT_NE(demo.out.find("pgamesh demo"), std::string::npos) << demo.out;
  // Every option of today is in the help.
  const std::string props = run_cli("props --help").out;
  for (const char* option : {"--density", "--mass", "--json", "--urdf", "--mjcf", "--force",
                             "--about-origin", "--no-topology", "--fast", "--weld-tolerance",
                             "--format", "--threads", "--degeneracy-tolerance"})
    EXPECT_NE(props.find(option), std::string::npos) << option;
  const std::string check = run_cli("check --help").out;
  for (const char* option : {"--json", "--weld-tolerance", "--area-threshold", "--max-list",
                             "--fix-orientation", "--output", "--format"})
    EXPECT_NE(check.find(option), std::string::npos) << option;
  const std::string fuel = run_cli("fuel --help").out;
  for (const char* option :
       {"--level", "--volume", "--fraction", "--table", "--volumes", "--up", "--pitch", "--roll",
        "--accel", "--density", "--mass", "--json", "--csv", "--force"})
    EXPECT_NE(fuel.find(option), std::string::npos) << option;
  // The list of commands.
  const CliRun top = run_cli("--help");
  EXPECT_EQ(top.status, 0);
  for (const char* command : {"props", "check", "fuel", "calc", "serve", "demo", "help"})
    EXPECT_NE(top.out.find(command), std::string::npos) << command;
  EXPECT_EQ(run_cli("help").out, top.out);
  EXPECT_EQ(run_cli("").status, 2);
  EXPECT_EQ(run_cli("bogus").status, 2);
  EXPECT_EQ(run_cli("help bogus").status, 2);
  const CliRun version = run_cli("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("pgamesh ", 0), 0u) << version.out;
}

TEST(CliUsage, BadUsageExitsTwoNamingTheOption) {
  const std::string cube = quoted_golden_mesh("unit_cube.obj");
  struct Case {
    std::string args, named;
  };
  for (const Case& c :
       std::initializer_list<Case>{{"props " + cube + " --density abc", "--density"},
                                   {"props " + cube + " --density", "--density"},
                                   {"props " + cube + " --threads 0", "--threads"},
                                   {"props " + cube + " --threads 2.5", "--threads"},
                                   {"props " + cube + " --weld-tolerance -1", "--weld-tolerance"},
                                   {"props " + cube + " --format xyz", "--format"},
                                   {"props " + cube + " --bogus", "--bogus"},
                                   {"check " + cube + " --max-list -3", "--max-list"},
                                   {"check " + cube + " --area-threshold inf", "--area-threshold"},
                                   {"fuel " + cube + " --level 0x1p-1", "--level"},
                                   {"fuel " + cube + " --up 0,0 --level 0.5", "--up"},
                                   {"fuel " + cube + " --pitch 1,,2 --level 0.5", "--pitch"},
                                   {"fuel " + cube + " --table 1e3", "--table"},
                                   {"fuel " + cube + " --level 0.5 --volume 0.5", "--volume"},
                                   {"fuel " + cube + " --level 0.5 --json --csv", "--csv"}}) {
    SCOPED_TRACE(c.args);
    const CliRun r = run_cli(c.args);
    EXPECT_EQ(r.status, 2);
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_NE(r.err.find(c.named), std::string::npos) << r.err;
  }
}

TEST(CliUsage, NumbersFollowOneRule) {
  // parse_number (std::from_chars: no locale, the whole text): decimals, exponents, a '+'.
  const std::string cube = quoted_golden_mesh("unit_cube.obj");
  const CliRun r = run_cli("fuel " + cube + " --level 0.25 --json --density 25e-1");
  ASSERT_EQ(r.status, 0) << r.err;
  const json a = parse_json(r.out);
  EXPECT_EQ(a["volume"], 0.25);
  EXPECT_EQ(a["mass"], 0.625);
  // --option=value is the same as --option value.
  EXPECT_EQ(parse_json(run_cli("fuel " + cube + " --level=0.25 --json --density=+2.5").out), a);
  // Negative values and a leading '+' are numbers, not options.
  const CliRun neg = run_cli("fuel " + cube + " --pitch -5 --roll +2 --level 0.5 --json");
  ASSERT_EQ(neg.status, 0) << neg.err;
  EXPECT_EQ(parse_json(neg.out)["pitch_deg"], -5.0);
  EXPECT_EQ(parse_json(neg.out)["roll_deg"], 2.0);
}

TEST(CliUsage, OneVocabularyAcrossPropsCheckAndFuel) {
  const TempFile flat("_flat.obj", flat_triangle);
  const std::string path = "\"" + flat.path() + "\"";
  const json props = parse_json(run_cli("props " + path + " --json").out);
  const json check = parse_json(run_cli("check " + path + " --json").out);
  // Undefined vectors and matrices are null as a whole.
  EXPECT_TRUE(props["center_of_mass"].is_null()) << props["center_of_mass"];
  EXPECT_TRUE(props["inertia_com"].is_null());
  EXPECT_TRUE(props["principal_moments"].is_null());
  EXPECT_TRUE(props["products_of_inertia_com"].is_null());
  // volume_valid and reasons, in all three.
  EXPECT_EQ(props["volume_valid"], false);
  EXPECT_EQ(check["volume_valid"], false);
  EXPECT_FALSE(props["reasons"].empty());
  EXPECT_FALSE(check["reasons"].empty());
  EXPECT_FALSE(props.contains("meaningful"));
  EXPECT_FALSE(props.contains("meaningful_reasons"));
  for (const json* j : {&props, &check})
    for (const char* key : {"file", "format", "triangles", "faces", "warnings"})
      EXPECT_TRUE(j->contains(key)) << key;
  EXPECT_EQ(props["topology"]["boundary_loop_count"], check["boundary_loop_count"]);
  EXPECT_EQ(props["topology"]["volume_range"], check["volume_range"]);

  const json fuel = parse_json(
      run_cli("fuel " + quoted_golden_mesh("unit_cube.obj") + " --level 0.5 --json").out);
  for (const char* key : {"file", "format", "triangles", "faces", "warnings", "volume_valid",
                          "reasons", "topology", "forced"})
    EXPECT_TRUE(fuel.contains(key)) << key;
  EXPECT_EQ(fuel["format"], "obj");
  EXPECT_EQ(fuel["faces"], 12);
  EXPECT_EQ(fuel["volume_valid"], true);
  EXPECT_TRUE(fuel["reasons"].empty());
  EXPECT_FALSE(fuel["topology"].contains("volume_valid"));
  // An empty tank: the fuel's centre of mass is null, as in props.
  const json empty =
      parse_json(run_cli("fuel " + quoted_golden_mesh("unit_cube.obj") + " --level 0 --json").out);
  EXPECT_TRUE(empty["center_of_mass"].is_null()) << empty["center_of_mass"];
}
