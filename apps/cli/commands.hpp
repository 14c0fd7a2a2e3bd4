// The commands of `pgamesh` and what they share: CLI11 sub-commands, one number rule, one way to
// report bad usage.
//
// HOW TO ADD A COMMAND `pgamesh NAME`:
//   1. Write apps/cli/cmd_NAME.cpp (CMake picks it up by its glob) defining
//        void add_NAME_command(CLI::App& app) {
//          CLI::App* sub = add_command(app, "NAME", "one line for the list of `pgamesh --help`",
//                                      "the paragraph that opens `pgamesh NAME --help`");
//          sub->footer("...");                               // conventions, exit status
//          auto o = std::make_shared<Options>();             // the parsed options live here
//          add_file(*sub, o->file, "the mesh file");         // FILE, when the command reads one
//          add_number(*sub, "--level", o->level, "...");     // numbers only through the helpers
//          sub->add_flag("--json", o->json, "...");          // flags and strings: CLI11 directly
//          on_run(*sub, [o] { return run(*o); });           // runs after a successful parse
//        }
//      `run` returns the exit status: 0 success, 1 unreadable input (InputError), 2 bad usage —
//      throw UsageError for a problem between options (the message names them); CLI11 reports
//      unknown options, missing values and bad numbers itself (exit 2, naming the option).
//   2. Declare add_NAME_command below and add {"NAME", add_NAME_command} to kCliCommands in
//      main.cpp, whose order is the order of `pgamesh --help` (mesh commands after fuel, before
//      calc). `pgamesh NAME …` builds only NAME's sub-command, so the name must be the same.
//   3. Test it in tests/cli/ (CliRun: exit status, stdout, stderr); document it in README.md, its
//      doc page, and docs/json.md for --json (the vocabulary of props, check and fuel).
// `pgamesh help NAME` and `pgamesh NAME --help` then print the same text. A command that parses its
// own arguments (`calc` still does) registers itself with RegisterCommand instead and receives
// argv from its own name on, unchanged.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::cli {

// ---- the commands, in the order of `pgamesh --help` ---------------------------------------------
void add_props_command(CLI::App& app);    // cmd_props.cpp
void add_check_command(CLI::App& app);    // cmd_check.cpp
void add_repair_command(CLI::App& app);   // cmd_repair.cpp
void add_fuel_command(CLI::App& app);     // cmd_fuel.cpp
void add_convert_command(CLI::App& app);  // cmd_convert.cpp
void add_cga_command(CLI::App& app);      // cmd_cga.cpp
void add_quadric_command(CLI::App& app);  // cmd_quadric.cpp
void add_fit_command(CLI::App& app);      // cmd_fit.cpp
void add_serve_command(CLI::App& app);    // cmd_serve.cpp
void add_demo_command(CLI::App& app);     // cmd_demo.cpp

// ---- what the commands share (options.cpp) -----------------------------------------------------

// Bad usage found after parsing (options that exclude each other, …): exit status 2, the message
// printed as "pgamesh NAME: message".
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The sub-command NAME: `summary` is its line in `pgamesh --help`; `pgamesh NAME --help` starts
// with the summary and then `details`.
CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& summary,
                      const std::string& details = "");

// Runs `run` when the sub-command `sub` was given and parsed; its result is the exit status.
void on_run(CLI::App& sub, std::function<int()> run);

// A sub-command whose arguments are not parsed here: `run` gets argv = {NAME, arguments as given}
// (`pgamesh NAME --help` included, so it prints its own help).
CLI::App* add_passthrough(CLI::App& app, const std::string& name, const std::string& summary,
                          int (*run)(int argc, char** argv));
// The run function of the pass-through command NAME, or nullptr: main.cpp hands it argv as given,
// before CLI11 could read anything of it (a "--" included).
using PassthroughRun = int (*)(int argc, char** argv);
PassthroughRun passthrough_run(const std::string& name);

// The one positional FILE ("-" reads standard input); required.
CLI::Option* add_file(CLI::App& sub, std::string& file, const std::string& description);

// Numbers: parse_number / parse_count of pgamesh/core/number_text.hpp (std::from_chars, whatever
// the C locale, the whole text or nothing); a bad value is a usage error naming the option.
// `at_least`: the smallest value allowed.
CLI::Option* add_number(CLI::App& sub, const std::string& name, double& out,
                        const std::string& description,
                        std::optional<double> at_least = std::nullopt);
CLI::Option* add_number(CLI::App& sub, const std::string& name, std::optional<double>& out,
                        const std::string& description);
// A finite number > 0 (densities and masses).
CLI::Option* add_positive_number(CLI::App& sub, const std::string& name, std::optional<double>& out,
                                 const std::string& description);
// A whole number in [low, high].
CLI::Option* add_count(CLI::App& sub, const std::string& name, unsigned long long& out,
                       const std::string& description, unsigned long long low,
                       unsigned long long high);
// Comma-separated numbers "A,B,..."; `size` > 0 asks for exactly that many.
CLI::Option* add_numbers(CLI::App& sub, const std::string& name, std::vector<double>& out,
                         const std::string& description, std::size_t size = 0);
CLI::Option* add_vec3(CLI::App& sub, const std::string& name, Vec3d& out,
                      const std::string& description);
// --format F: stl, obj, ply, off, 3mf, gltf, glb, slp or auto (MeshFormat::unknown: from the
// content).
CLI::Option* add_format(CLI::App& sub, MeshFormat& out);
// --unit U: mm, cm, m, in, ft or um (units.hpp, unit_from_name).
CLI::Option* add_unit(CLI::App& sub, LengthUnit& out, const std::string& description);

// ---- commands that parse their own argv (calc) --------------------------------------------------

struct Command {
  const char* name;
  const char* summary;
  int (*run)(int argc, char** argv);  // argv[0] is the command's name
  int order;                          // position among these commands (ascending)
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
