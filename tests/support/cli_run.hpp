// Running the pgamesh executable from a test: its exit status and what it wrote.
#pragma once

#include <string>

namespace pgamesh::test {

struct CliRun {
  int status = -1;  // the exit status, or −1 when the process did not exit normally
  std::string out, err;
};

// Runs `pgamesh ARGS` (ARGS passed to the shell as written, so quote paths in it), with the file
// `stdin_path` on standard input when it is not empty.
CliRun run_cli(const std::string& args, const std::string& stdin_path = "");

}  // namespace pgamesh::test
