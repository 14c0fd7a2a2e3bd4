// A command that fails writes nothing on stdout: its whole output is built first and printed only
// on success, so a script never reads half a report or a gauge table cut short.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"
#include "support/cube_file.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

TEST(FailedCommandsPrintNothing, FuelOutsideTheTank) {
  const TempFile tank(".obj", cube_obj(1));
  const std::string path = "fuel \"" + tank.path() + "\" ";
  for (const char* args : {"--level 5", "--level 5 --json", "--level 5 --csv", "--level -1",
                           "--volume 9", "--volumes 0.5,9 --csv", "--volumes 0.5,9 --json",
                           "--volumes 0.5,9", "--volume 0.5 --pitch 0,5 --roll 0,90,180 --csv"}) {
    SCOPED_TRACE(args);
    const CliRun r = run_cli(path + args);
    if (std::string(args).find("--pitch") != std::string::npos) {
      EXPECT_EQ(r.status, 0) << r.err;  // the control: every attitude of a grid succeeds
      continue;
    }
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(r.err.empty());
  }
  const CliRun level = run_cli(path + "--level 5");
  EXPECT_NE(level.err.find("the tank would be full"), std::string::npos) << level.err;
}

TEST(FailedCommandsPrintNothing, FuelRefusesAnOpenTankUnlessForced) {
  const TempFile tank(".obj", cube_obj(1, 0, CubeDefect::open));
  const std::string path = "fuel \"" + tank.path() + "\" --table 2 --csv";
  const CliRun refused = run_cli(path);
  EXPECT_EQ(refused.status, 1);
  EXPECT_EQ(refused.out, "");
  EXPECT_NE(refused.err.find("not a tank"), std::string::npos) << refused.err;
  // Forced, the table carries the reasons inside it.
  const CliRun forced = run_cli(path + " --force");
  ASSERT_EQ(forced.status, 0) << forced.err;
  EXPECT_NE(
      forced.out.find("# warning: forced (--force), not a valid tank: open: 4 boundary edges"),
      std::string::npos)
      << forced.out;
}

TEST(FailedCommandsPrintNothing, CheckWithAnOutputItCannotWrite) {
  const TempFile mesh(".obj", cube_obj(1, 0, CubeDefect::one_flip));
  const TempFile folder("_folder");
  std::filesystem::create_directory(folder.path());
  const std::string missing = folder.path() + "/no/such/folder/out.obj";
  const CliRun r =
      run_cli("check \"" + mesh.path() + "\" --fix-orientation --output \"" + missing + "\"");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  // A folder in the way of the output is left as it was, and no temporary file is left beside it.
  const std::string in_the_way = folder.path() + "/out.obj";
  std::filesystem::create_directory(in_the_way);
  const CliRun blocked = run_cli("check \"" + mesh.path() +
                                 "\" --fix-orientation --json --output \"" + in_the_way + "\"");
  EXPECT_EQ(blocked.status, 1);
  EXPECT_EQ(blocked.out, "");
  EXPECT_TRUE(std::filesystem::is_directory(in_the_way));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(folder.path()))
    ++entries;
  EXPECT_EQ(entries, 1u);
  std::filesystem::remove(in_the_way);
}

}  // namespace
}  // namespace pgamesh::test
