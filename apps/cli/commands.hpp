// The table of CLI commands. Each command lives in its own file (cmd_<name>.cpp) and receives
// argv starting at its own name.
#pragma once

#include <span>

namespace pgamesh::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);
};

int run_demo(int argc, char** argv);

// One entry per command, in the order `pgamesh --help` lists them.
inline std::span<const Command> commands() {
  static const Command table[] = {
      {"demo", "a short PGA demonstration: carriers, magnitudes and a motor", run_demo},
  };
  return table;
}

}  // namespace pgamesh::cli
