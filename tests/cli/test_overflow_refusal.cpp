// Coordinates so large that the area, volume or inertia overflow a double are refused, naming the
// file, by every command: no inf or nan is ever printed as if it were a result.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/cli_run.hpp"
#include "support/cube_file.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

void expect_refused(const std::string& bytes) {
  const TempFile file(".obj", bytes);
  const std::string path = "\"" + file.path() + "\"";
  for (const std::string& args :
       {"props " + path, "props " + path + " --json", "props " + path + " --fast --json",
        "props " + path + " --urdf --force", "check " + path, "check " + path + " --json",
        "fuel " + path + " --fraction 0.5", "fuel " + path + " --table 3 --csv --force"}) {
    SCOPED_TRACE(args);
    const CliRun r = run_cli(args);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(file.path()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("too large for double precision"), std::string::npos) << r.err;
  }
}

TEST(OverflowRefusal, CubeOfSide1e120) {
  // area 6e240 fits, the volume 1e360 does not.
  expect_refused(cube_obj(1e120, 1e120));
}

TEST(OverflowRefusal, CubeOfSide1e100) {
  // volume 1e300 fits, the inertia side⁵/6 = 1.7e499 does not.
  expect_refused(cube_obj(1e100));
}

TEST(OverflowRefusal, LargeButRepresentableFiguresAreComputed) {
  // side 2^200: volume 2^600, inertia about the centre 2^1000 / 6, all exact in binary.
  const double side = std::ldexp(1.0, 200);
  const TempFile file(".obj", cube_obj(side));
  const CliRun r = run_cli("props \"" + file.path() + "\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["volume"].get<double>(), std::ldexp(1.0, 600));
  EXPECT_EQ(j["area"].get<double>(), 6 * std::ldexp(1.0, 400));
  EXPECT_EQ(j["center_of_mass"][0].get<double>(), std::ldexp(1.0, 199));
  EXPECT_DOUBLE_EQ(j["inertia_com"][0][0].get<double>(), std::ldexp(1.0, 1000) / 6);
  EXPECT_EQ(j["volume_valid"], true);
}

}  // namespace
}  // namespace pgamesh::test
