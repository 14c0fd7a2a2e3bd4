// `pgamesh props --urdf/--mjcf` exports only valid solids: an open, inconsistent, inward, flat or
// unchecked (--fast) body is refused with the front door's reasons and nothing on stdout, unless
// --force, which writes the element with the reasons in an XML comment inside it.
#include <gtest/gtest.h>

#include <string>

#include "support/cli_run.hpp"
#include "support/cube_file.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

struct Refusal {
  const char* name;
  std::string bytes;
  const char* suffix;
  const char* flags;
  const char* reason;  // a piece of the reason the refusal names
};

std::vector<Refusal> refusals() {
  return {
      {"open", cube_obj(1, 0, CubeDefect::open), ".obj", "", "open: 4 boundary edges"},
      {"inconsistent", cube_obj(1, 0, CubeDefect::one_flip), ".obj", "",
       "orientation inconsistent"},
      {"inward", cube_obj(1, 0, CubeDefect::inward), ".obj", "", "negative volume"},
      {"no facets", "solid empty\nendsolid empty\n", ".stl", "", "zero volume"},
      {"unchecked", cube_obj(1), ".obj", "--fast", "topology not computed"},
  };
}

TEST(PropsExportRefusal, InvalidBodiesAreRefusedWithNothingOnStdout) {
  for (const Refusal& c : refusals())
    for (const char* format : {"--urdf", "--mjcf"}) {
      SCOPED_TRACE(std::string(c.name) + " " + format);
      const TempFile file(c.suffix, c.bytes);
      const CliRun r = run_cli("props \"" + file.path() + "\" --mass 2 " + format + " " + c.flags);
      EXPECT_EQ(r.status, 1);
      EXPECT_EQ(r.out, "");
      EXPECT_NE(r.err.find(file.path() + ": not a valid solid: "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
    }
}

TEST(PropsExportRefusal, ForceWritesTheReasonsIntoTheFile) {
  const TempFile file(".obj", cube_obj(1, 0, CubeDefect::inward));
  for (const char* format : {"--urdf", "--mjcf"}) {
    SCOPED_TRACE(format);
    const CliRun r = run_cli("props \"" + file.path() + "\" " + format + " --force");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto comment = r.out.find("<!-- WARNING: forced output, not a valid solid");
    ASSERT_NE(comment, std::string::npos) << r.out;
    const auto end = r.out.find("-->", comment);
    ASSERT_NE(end, std::string::npos);
    const std::string text = r.out.substr(comment + 4, end - comment - 4);
    EXPECT_NE(text.find("negative volume"), std::string::npos) << text;
    EXPECT_EQ(text.find("--"), std::string::npos) << text;  // not allowed inside an XML comment
    EXPECT_LT(comment, r.out.find("<inertial"));
    EXPECT_NE(r.err.find("not a valid solid (--force)"), std::string::npos) << r.err;
  }
}

TEST(PropsExportRefusal, ForceWritesNoBodyOfZeroVolume) {
  // No centre of mass or inertia exists: nothing to write, even forced (never "nan").
  const TempFile file(".stl", "solid empty\nendsolid empty\n");
  const CliRun r = run_cli("props \"" + file.path() + "\" --mjcf --force");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("zero volume: no centre of mass or inertia to write"), std::string::npos)
      << r.err;
}

TEST(PropsExportRefusal, AValidSolidCarriesNoWarning) {
  const TempFile file(".obj", cube_obj(1));
  const CliRun r = run_cli("props \"" + file.path() + "\" --urdf --mass 6");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("WARNING"), std::string::npos);
  EXPECT_NE(r.out.find("<mass value=\"6\"/>"), std::string::npos) << r.out;
  // The unit cube of mass 6: I = m (1² + 1²) / 12 = 1 on the diagonal.
  EXPECT_NE(r.out.find("ixx=\"1\""), std::string::npos) << r.out;
}

TEST(PropsExportRefusal, DensityAndMassMustBePositiveAndFinite) {
  const TempFile file(".obj", cube_obj(1));
  for (const char* command : {"props", "fuel"})
    for (const char* option : {"--density", "--mass"})
      for (const char* value : {"-1", "0", "-0", "-5e-300", "inf", "nan"}) {
        const std::string args = std::string(command) + " \"" + file.path() + "\" " + option + "=" +
                                 value + (std::string(command) == "fuel" ? " --level 0.5" : "");
        SCOPED_TRACE(args);
        const CliRun r = run_cli(args);
        EXPECT_EQ(r.status, 2);
        EXPECT_EQ(r.out, "");
        EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
      }
}

}  // namespace
}  // namespace pgamesh::test
