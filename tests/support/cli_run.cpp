#include "support/cli_run.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace pgamesh::test {

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

std::string test_temp_path(const std::string& suffix) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return (std::filesystem::temp_directory_path() /
          (std::string("pgamesh_") + (test ? test->test_suite_name() : "") + "_" +
           (test ? test->name() : "") + "_" + std::to_string(::getpid()) + suffix))
      .string();
}

CliRun run_cli(const std::string& args, const std::string& stdin_path) {
  const std::string out = test_temp_path(".out"), err = test_temp_path(".err");
  std::string cmd = std::string("\"") + PGAMESH_CLI_PATH + "\" " + args;
  if (!stdin_path.empty()) cmd += " < \"" + stdin_path + "\"";
  cmd += " > \"" + out + "\" 2> \"" + err + "\"";
  CliRun r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace pgamesh::test
