// Running the pgamesh executable from a test: its exit status and what it wrote.
#pragma once

#include <string>

namespace pgamesh::test {

struct CliRun {
  int status = -1;  // the exit status, or −1 when the process did not exit normally
  std::string out, err;
};

// A path in the temporary folder unique to the running test and process, ending in `suffix`:
// ctest runs the cases of a file in parallel processes, so names carry both.
std::string test_temp_path(const std::string& suffix);

// Runs `pgamesh ARGS` (ARGS passed to the shell as written, so quote paths in it), with the file
// `stdin_path` on standard input when it is not empty.
CliRun run_cli(const std::string& args, const std::string& stdin_path = "");

}  // namespace pgamesh::test
