// `pgamesh serve [FILE...] [--port P] [--host H] [--max-upload BYTES]`: the viewer page and its
// JSON API on a local HTTP server (apps/viewer/server, docs/viewer.md).
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

#include "commands.hpp"

#ifdef PGAMESH_WITH_VIEWER
#include "server.hpp"
#endif

namespace pgamesh::cli {

namespace {

void print_serve_help(std::FILE* out) {
  std::fprintf(
      out,
      "usage: pgamesh serve [FILE...] [options]\n"
      "\n"
      "Starts the viewer: a local web page showing meshes, their mass properties and\n"
      "fuel, with a JSON API. Open the printed URL in a browser. Ctrl-C stops it.\n"
      "FILEs named here are listed on the page beside the bundled meshes.\n"
      "\n"
      "options:\n"
      "  --port P          TCP port (default 8080; 0 picks a free one)\n"
      "  --host H          address to bind (default 127.0.0.1, this machine only)\n"
      "  --max-upload N    largest accepted upload in bytes, suffix K, M or G allowed\n"
      "                    (default 64M)\n"
      "  --assets DIR      folder of the page (default: the source tree's apps/viewer/web)\n"
      "  --quiet           do not log each request on stderr\n");
}

#ifdef PGAMESH_WITH_VIEWER
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
#endif

int run_serve(int argc, char** argv) {
#ifndef PGAMESH_WITH_VIEWER
  // The usage still answers --help; everything else says why the command is missing.
  if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    print_serve_help(stdout);
    std::printf("\n(this build has no viewer)\n");
    return 0;
  }
  std::fprintf(stderr,
               "pgamesh serve: this build has no viewer (configure with "
               "-DPGAMESH_BUILD_VIEWER=ON and cpp-httplib installed)\n");
  return 2;
#else
  viewer::ServerOptions options;
  options.web_dir = PGAMESH_VIEWER_WEB_DIR;
  options.bundled_dir = PGAMESH_VIEWER_MESHES_DIR;
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
  return viewer::run_server(options);
#endif
}

const RegisterCommand registered{
    {"serve", "the viewer: a local web page with the mesh, its figures and fuel", run_serve, 80}};

}  // namespace

}  // namespace pgamesh::cli
