// pgamesh — the command-line tool. `pgamesh <command> FILE [options]` (README.md, The command
// line). The commands are CLI11 sub-commands, each added by its cmd_NAME.cpp (commands.hpp says how
// to add one). Exit status: the command's (0 success, 1 unreadable input), 2 for bad usage.
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "commands.hpp"

namespace {

int command_status = 0;

// CLI11's help, with the list of commands showing the first line of each description (the summary
// of add_command); `pgamesh NAME --help` shows all of it.
class Formatter : public CLI::Formatter {
 public:
  std::string make_subcommand(const CLI::App* sub) const override {
    const std::string& description = sub->get_description();
    std::stringstream out;
    CLI::detail::format_help(out, sub->get_display_name(true),
                             description.substr(0, description.find('\n')), get_column_width());
    return out.str();
  }
};

// The sub-command being parsed (for messages), or nullptr.
const CLI::App* selected(const CLI::App& app) {
  const auto subs = app.get_subcommands();
  return subs.empty() ? nullptr : subs.front();
}

int usage_error(const CLI::App& app, const std::string& message) {
  const CLI::App* sub = selected(app);
  const std::string name = sub ? "pgamesh " + sub->get_name() : std::string("pgamesh");
  std::fprintf(stderr, "%s: %s\n(%s --help for the options)\n", name.c_str(), message.c_str(),
               name.c_str());
  return 2;
}

}  // namespace

namespace pgamesh::cli {

void on_run(CLI::App& sub, std::function<int()> run) {
  sub.callback([run = std::move(run)] { command_status = run(); });
}

}  // namespace pgamesh::cli

namespace {

using namespace pgamesh::cli;

// A command built on CLI11: its name and the function that adds it (commands.hpp).
struct CliCommand {
  const char* name;
  void (*add)(CLI::App& app);
};
// In the order of `pgamesh --help`.
constexpr CliCommand kCliCommands[] = {
    {"props", add_props_command},     {"check", add_check_command},
    {"repair", add_repair_command},   {"fuel", add_fuel_command},
    {"convert", add_convert_command}, {"cga", add_cga_command},
    {"quadric", add_quadric_command}, {"fit", add_fit_command},
    {"serve", add_serve_command},     {"demo", add_demo_command}};
// The commands that parse their own arguments (commands(): calc) are listed after this one.
constexpr std::string_view kBeforePassthroughs = "fit";

const CliCommand* find_cli_command(const char* name) {
  for (const CliCommand& c : kCliCommands)
    if (std::strcmp(name, c.name) == 0) return &c;
  return nullptr;
}

// Every command, `help` and `version`, for the help text and the messages that list them.
void add_all_commands(CLI::App& app) {
  for (const CliCommand& command : kCliCommands) {
    command.add(app);
    if (command.name == kBeforePassthroughs)
      for (const Command& c : commands()) add_passthrough(app, c.name, c.summary, c.run);
  }
  CLI::App* help = app.add_subcommand("help", "pgamesh help COMMAND: the options of COMMAND");
  on_run(*help, [&app] {
    // app.help() would give the help of the selected sub-command, `help` itself.
    const std::string text =
        app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
    std::fputs(text.c_str(), stdout);
    return 0;
  });
  CLI::App* version = app.add_subcommand("version", "print the version")->group("");
  on_run(*version, [] {
    std::printf("pgamesh %s\n", PGAMESH_VERSION);
    return 0;
  });
}

}  // namespace

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // Arrays above 128 KiB get mappings of their own, unmapped when freed. glibc otherwise raises
  // this threshold to the size of the largest mapped block freed so far (a reader's arrays), so
  // the weld's and the edge pass's arrays of a few MB then come from the heap, where a freed one
  // below a live one stays resident: measured on a 10^6-triangle PLY, 2 MB more at the peak of
  // props (docs/benchmarks.md).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  using namespace pgamesh::cli;
  CLI::App app("pgamesh: geometric-algebra mesh processing", "pgamesh");
  auto formatter = std::make_shared<Formatter>();
  formatter->column_width(26);
  app.formatter(formatter);
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // last one wins
  app.require_subcommand(0, 1);  // one command; its arguments are never taken for another
  app.set_version_flag("--version", std::string("pgamesh ") + PGAMESH_VERSION, "print the version");
  app.footer(
      "pgamesh <command> --help (or pgamesh help <command>) gives the options of one command.\n"
      "Every command writes errors on stderr; exit status 0 on success, 1 for unreadable input,\n"
      "2 for bad usage.");

  // A command that parses its own arguments gets them as given, without CLI11.
  if (argc >= 2)
    for (const Command& c : commands())
      if (std::strcmp(argv[1], c.name) == 0) return c.run(argc - 1, argv + 1);
  // `pgamesh NAME …` needs only NAME's options. Building all the commands costs about half a
  // millisecond of every start, a tenth of it (docs/benchmarks.md), so only help, the version
  // and usage errors build them all.
  const CliCommand* one = argc >= 2 ? find_cli_command(argv[1]) : nullptr;
  if (one)
    one->add(app);
  else
    add_all_commands(app);

  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return 2;
  }
  const auto known = [&app](const char* name) {
    try {
      app.get_subcommand(name);
      return true;
    } catch (const CLI::OptionNotFound&) {
      return false;
    }
  };
  if (argv[1][0] != '-' && !known(argv[1])) {
    std::fprintf(stderr, "pgamesh: unknown command '%s'\n\n%s", argv[1], app.help().c_str());
    return 2;
  }
  // `pgamesh help COMMAND` is `pgamesh COMMAND --help`, word for word.
  std::vector<char*> args(argv, argv + argc);
  static char help_flag[] = "--help";
  if (argc >= 3 && std::strcmp(argv[1], "help") == 0) {
    if (!known(argv[2]) || std::strcmp(argv[2], "help") == 0) {
      std::fprintf(stderr, "pgamesh help: unknown command '%s'\n\n%s", argv[2], app.help().c_str());
      return 2;
    }
    if (const PassthroughRun run = passthrough_run(argv[2])) {
      char* help_args[] = {argv[2], help_flag, nullptr};
      return run(2, help_args);
    }
    args = {argv[0], argv[2], help_flag};
  }

  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::CallForHelp&) {
    const CLI::App* sub = selected(app);
    std::fputs(sub ? sub->help(app.get_name()).c_str() : app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return 0;
  } catch (const CLI::ParseError& e) {
    return usage_error(app, e.what());
  } catch (const UsageError& e) {
    return usage_error(app, e.what());
  } catch (const std::exception& e) {
    const CLI::App* sub = selected(app);
    std::fprintf(stderr, "pgamesh%s%s: %s\n", sub ? " " : "", sub ? sub->get_name().c_str() : "",
                 e.what());
    return 1;
  }
  if (!selected(app)) {
    std::fputs(app.help().c_str(), stderr);
    return 2;
  }
  return command_status;
}
