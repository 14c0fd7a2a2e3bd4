// `pgamesh serve [FILE...] [options]`: the viewer page and its JSON API on a local HTTP server
// (apps/viewer, docs/viewer.md). The server is the executable `pgamesh-serve` installed beside
// `pgamesh`; this command replaces the process with it (same process id, so signals and exit
// status reach the server directly), which keeps the HTTP, TLS and compression libraries out of
// every other command.
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "commands.hpp"
#include "serve_help.hpp"

namespace pgamesh::cli {

namespace {

// The path of `pgamesh-serve` in the folder of the running executable, or "" when unknown.
std::string server_executable() {
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return {};
  std::string path(self, static_cast<std::size_t>(n));
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string{} : path.substr(0, slash + 1) + "pgamesh-serve";
}

int run_serve(int argc, char** argv) {
  const std::string server = server_executable();
  if (server.empty() || access(server.c_str(), X_OK) != 0) {
    // The usage still answers --help; everything else says why the command is missing.
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
      print_serve_help(stdout);
      std::printf("\n(this build has no viewer)\n");
      return 0;
    }
    std::fprintf(stderr,
                 "pgamesh serve: this build has no viewer: %s is missing (configure with "
                 "-DPGAMESH_BUILD_VIEWER=ON and cpp-httplib installed)\n",
                 server.empty() ? "pgamesh-serve" : server.c_str());
    return 2;
  }
  std::vector<char*> args;
  args.reserve(static_cast<std::size_t>(argc) + 1);
  static char name[] = "pgamesh-serve";
  args.push_back(name);
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  std::fflush(nullptr);
  execv(server.c_str(), args.data());
  std::fprintf(stderr, "pgamesh serve: cannot start %s: %s\n", server.c_str(),
               std::strerror(errno));
  return 2;
}

}  // namespace

// The server parses its own options (apps/viewer/main.cpp): they pass through unchanged, --help
// included, so `pgamesh serve --help` and `pgamesh help serve` print the server's usage.
void add_serve_command(CLI::App& app) {
  add_passthrough(app, "serve", "the viewer: a local web page with the mesh, its figures and fuel",
                  run_serve);
}

}  // namespace pgamesh::cli
