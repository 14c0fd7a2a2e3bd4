#include "support/cli_run.hpp"

#include <sys/wait.h>

#include <cstdlib>

#include "support/file_bytes.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {

CliRun run_cli(const std::string& args, const std::string& stdin_path) {
  const TempFile out(".out"), err(".err");
  std::string cmd = std::string("\"") + PGAMESH_CLI_PATH + "\" " + args;
  if (!stdin_path.empty()) cmd += " < \"" + stdin_path + "\"";
  cmd += " > \"" + out.path() + "\" 2> \"" + err.path() + "\"";
  CliRun r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = file_bytes(out.path());
  r.err = file_bytes(err.path());
  return r;
}

}  // namespace pgamesh::test
