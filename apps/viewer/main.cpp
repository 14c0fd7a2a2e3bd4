// `pgamesh-serve`: the executable behind `pgamesh serve [FILE...] [options]`
// (apps/cli/cmd_serve.cpp starts it with the command's arguments). Reads the options and runs the
// server (server/server.hpp, docs/viewer.md).
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "local_hosts.hpp"
#include "pgamesh/core/number_text.hpp"
#include "serve_help.hpp"
#include "server.hpp"

namespace {

// "64M" -> 67108864; false when the text is not a positive size.
bool parse_size(std::string_view text, std::size_t& out) {
  std::size_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || value == 0) return false;
  std::string_view rest(end, text.data() + text.size() - end);
  int shift = 0;
  if (rest == "K" || rest == "k")
    shift = 10;
  else if (rest == "M" || rest == "m")
    shift = 20;
  else if (rest == "G" || rest == "g")
    shift = 30;
  else if (!rest.empty())
    return false;
  if (value > (std::size_t{1} << 40) >> shift) return false;  // at most 1 TiB
  out = value << shift;
  return true;
}

bool parse_port(std::string_view text, int& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && out >= 0 && out <= 65535;
}

// A folder of the server's data: `installed` relative to the executable's folder when it exists
// there (an installed server: <prefix>/bin/pgamesh-serve and <prefix>/share/pgamesh/...), else
// `source`, the source tree the server was built from (a run from the build tree).
std::string data_dir(const char* installed, const char* source) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path dir = exe.parent_path() / installed;
    if (std::filesystem::is_directory(dir, ec)) return dir.lexically_normal().string();
  }
  return source;
}

}  // namespace

int main(int argc, char** argv) {
  using pgamesh::cli::print_serve_help;
  pgamesh::viewer::ServerOptions options;
  options.web_dir = data_dir("../share/pgamesh/web", PGAMESH_VIEWER_WEB_DIR);
  options.bundled_dir = data_dir("../share/pgamesh/meshes", PGAMESH_VIEWER_MESHES_DIR);
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--help" || arg == "-h") {
      print_serve_help(stdout);
      return 0;
    } else if (arg == "--port" && has_value) {
      if (!parse_port(argv[++i], options.port)) {
        std::fprintf(stderr, "pgamesh serve: --port wants 0..65535, got '%s'\n", argv[i]);
        return 2;
      }
    } else if (arg == "--host" && has_value) {
      options.host = argv[++i];
    } else if (arg == "--max-upload" && has_value) {
      if (!parse_size(argv[++i], options.max_upload)) {
        std::fprintf(stderr, "pgamesh serve: --max-upload wants a size like 64M, got '%s'\n",
                     argv[i]);
        return 2;
      }
    } else if (arg == "--assets" && has_value) {
      options.web_dir = argv[++i];
      std::error_code ec;
      if (!std::filesystem::is_directory(options.web_dir, ec)) {
        std::fprintf(stderr, "pgamesh serve: --assets wants a folder of the page, got '%s'\n",
                     argv[i]);
        return 2;
      }
    } else if (arg == "--weld-tolerance" && has_value) {
      const auto t = pgamesh::parse_number(argv[++i]);
      if (!t || *t < 0) {
        std::fprintf(stderr, "pgamesh serve: --weld-tolerance wants a number >= 0, got '%s'\n",
                     argv[i]);
        return 2;
      }
      options.weld_tolerance = *t;
    } else if ((arg == "--head-timeout" || arg == "--request-timeout") && has_value) {
      const auto t = pgamesh::parse_number(argv[++i]);
      if (!t || *t <= 0 || *t > 86400) {
        std::fprintf(stderr, "pgamesh serve: %s wants seconds in (0, 86400], got '%s'\n",
                     argv[i - 1], argv[i]);
        return 2;
      }
      (arg == "--head-timeout" ? options.head_timeout : options.request_timeout) = *t;
    } else if (arg == "--allow-remote") {
      options.allow_remote = true;
    } else if (arg == "--quiet") {
      options.log_requests = false;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "pgamesh serve: unknown option or missing value: '%s'\n\n", argv[i]);
      print_serve_help(stderr);
      return 2;
    } else {
      options.files.emplace_back(arg);
    }
  }
  // The server has no authentication: another machine may reach it only when the user says so.
  if (!pgamesh::viewer::is_loopback_host(options.host)) {
    if (!options.allow_remote) {
      std::fprintf(stderr,
                   "pgamesh serve: --host %s is not a loopback address: other machines could "
                   "read and upload meshes; add --allow-remote to serve it anyway\n",
                   options.host.c_str());
      return 2;
    }
    std::fprintf(stderr,
                 "pgamesh serve: warning: serving on %s without authentication: anyone who "
                 "reaches this address can read and upload meshes\n",
                 options.host.c_str());
  }
  return pgamesh::viewer::run_server(options);
}
