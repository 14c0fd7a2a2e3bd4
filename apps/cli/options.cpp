// What the commands share (commands.hpp): the number options, FILE, --format, the run hook and the
// pass-through commands.
#include <map>
#include <string_view>
#include <utility>

#include "commands.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh::cli {

namespace {

double number_or_throw(const std::string& name, std::string_view text) {
  const auto v = parse_number(text);
  if (!v) throw CLI::ValidationError(name, "'" + std::string(text) + "' is not a finite number");
  return *v;
}

// The comma-separated numbers of `text`.
std::vector<double> number_list(const std::string& name, std::string_view text) {
  std::vector<double> list;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    list.push_back(number_or_throw(name, text.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return list;
}

std::map<std::string, PassthroughRun>& passthroughs() {
  static std::map<std::string, PassthroughRun> runs;
  return runs;
}

// The option's long name (for messages), e.g. "--level".
std::string option_name(const std::string& names) {
  std::string longest;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = names.find(',', start);
    const std::string part = names.substr(start, comma - start);
    if (part.size() > longest.size()) longest = part;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return longest;
}

}  // namespace

CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& summary,
                      const std::string& details) {
  // The list of commands shows the description's first line (main.cpp's formatter).
  return app.add_subcommand(name, details.empty() ? summary : summary + "\n\n" + details);
}

CLI::App* add_passthrough(CLI::App& app, const std::string& name, const std::string& summary,
                          int (*run)(int argc, char** argv)) {
  passthroughs()[name] = run;
  CLI::App* sub = app.add_subcommand(name, summary);
  sub->prefix_command();
  sub->set_help_flag();  // --help reaches the command
  on_run(*sub, [sub, name, run] {
    std::vector<std::string> args = sub->remaining();
    args.insert(args.begin(), name);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    return run(static_cast<int>(args.size()), argv.data());
  });
  return sub;
}

PassthroughRun passthrough_run(const std::string& name) {
  const auto it = passthroughs().find(name);
  return it == passthroughs().end() ? nullptr : it->second;
}

CLI::Option* add_file(CLI::App& sub, std::string& file, const std::string& description) {
  return sub.add_option("FILE", file, description)->required()->type_name("");
}

CLI::Option* add_number(CLI::App& sub, const std::string& name, double& out,
                        const std::string& description, std::optional<double> at_least) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name,
          [&out, n, at_least](const std::string& text) {
            const double v = number_or_throw(n, text);
            if (at_least && v < *at_least)
              throw CLI::ValidationError(
                  n, "needs a number >= " + format_number(*at_least) + ", got '" + text + "'");
            out = v;
          },
          description)
      ->type_name("X");
}

CLI::Option* add_number(CLI::App& sub, const std::string& name, std::optional<double>& out,
                        const std::string& description) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name, [&out, n](const std::string& text) { out = number_or_throw(n, text); }, description)
      ->type_name("X");
}

CLI::Option* add_positive_number(CLI::App& sub, const std::string& name, std::optional<double>& out,
                                 const std::string& description) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name,
          [&out, n](const std::string& text) {
            const double v = number_or_throw(n, text);
            // A density or a mass of zero or less describes no body: refused here, before any
            // file is read, rather than turned into negative masses and inertias.
            if (!(v > 0))
              throw CLI::ValidationError(n, "needs a positive number, got '" + text + "'");
            out = v;
          },
          description)
      ->type_name("X");
}

CLI::Option* add_count(CLI::App& sub, const std::string& name, unsigned long long& out,
                       const std::string& description, unsigned long long low,
                       unsigned long long high) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name,
          [&out, n, low, high](const std::string& text) {
            const auto v = parse_count(text);
            if (!v || *v < low || *v > high)
              throw CLI::ValidationError(n, "needs a whole number from " + std::to_string(low) +
                                                " to " + std::to_string(high) + ", got '" + text +
                                                "'");
            out = *v;
          },
          description)
      ->type_name("N");
}

CLI::Option* add_numbers(CLI::App& sub, const std::string& name, std::vector<double>& out,
                         const std::string& description, std::size_t size) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name,
          [&out, n, size](const std::string& text) {
            std::vector<double> list = number_list(n, text);
            if (size && list.size() != size)
              throw CLI::ValidationError(n, "needs " + std::to_string(size) +
                                                " comma-separated numbers, got '" + text + "'");
            out = std::move(list);
          },
          description)
      ->type_name("A,B,...");
}

CLI::Option* add_vec3(CLI::App& sub, const std::string& name, Vec3d& out,
                      const std::string& description) {
  const std::string n = option_name(name);
  return sub
      .add_option_function<std::string>(
          name,
          [&out, n](const std::string& text) {
            const std::vector<double> v = number_list(n, text);
            if (v.size() != 3) throw CLI::ValidationError(n, "needs three numbers X,Y,Z");
            out = {v[0], v[1], v[2]};
          },
          description)
      ->type_name("X,Y,Z");
}

CLI::Option* add_format(CLI::App& sub, MeshFormat& out) {
  return sub
      .add_option_function<std::string>(
          "--format",
          [&out](const std::string& name) {
            if (name == "auto") {
              out = MeshFormat::unknown;
              return;
            }
            out = format_from_name(name);
            if (out == MeshFormat::unknown)
              throw CLI::ValidationError("--format", "unknown format '" + name +
                                                         "' (stl, obj, ply, off, 3mf, gltf, glb, "
                                                         "slp or auto)");
          },
          "read FILE as F: stl, obj, ply, off, 3mf, gltf, glb, slp (default\nauto: from the "
          "content)")
      ->type_name("F");
}

CLI::Option* add_unit(CLI::App& sub, LengthUnit& out, const std::string& description) {
  return sub
      .add_option_function<std::string>(
          "--unit",
          [&out](const std::string& name) {
            const auto u = unit_from_name(name);
            if (!u)
              throw CLI::ValidationError("--unit",
                                         "unknown unit '" + name + "' (mm, cm, m, in, ft, um)");
            out = *u;
          },
          description)
      ->type_name("U");
}

}  // namespace pgamesh::cli
