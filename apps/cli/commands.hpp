// The registry of CLI commands. Each command lives in its own file (cmd_<name>.cpp), registers
// itself with a static RegisterCommand, and receives argv starting at its own name.
#pragma once

#include <algorithm>
#include <vector>

namespace pgamesh::cli {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);
  int order;  // position in `pgamesh --help` (ascending)
};

inline std::vector<Command>& command_registry() {
  static std::vector<Command> registry;
  return registry;
}

struct RegisterCommand {
  explicit RegisterCommand(Command c) {
    auto& r = command_registry();
    r.insert(std::upper_bound(r.begin(), r.end(), c,
                              [](const Command& a, const Command& b) { return a.order < b.order; }),
             c);
  }
};

inline const std::vector<Command>& commands() {
  return command_registry();
}

}  // namespace pgamesh::cli
