// `pgamesh serve`: a local HTTP server for the viewer page and its JSON API, backed by the library
// in-process. Routes, limits and behaviour on bad requests are described in docs/viewer.md.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pgamesh::viewer {

struct ServerOptions {
  std::string host = "127.0.0.1";  // loopback unless the user asks otherwise (docs/viewer.md)
  bool allow_remote = false;       // --allow-remote: the user accepts a non-loopback host
  int port = 8080;                 // 0: any free port (the URL printed says which)
  std::size_t max_upload = std::size_t{64} << 20;  // bytes; bigger request bodies get 413
  std::size_t max_kept_uploads = 8;                // uploads kept in memory, oldest dropped first
  double weld_tolerance = 0;  // meshes are analysed welded within it (an upload may name its own)
  std::string web_dir;        // folder of index.html and node_modules/three
  std::string bundled_dir;    // folder of the bundled meshes (data/meshes)
  std::vector<std::string> files;  // meshes named on the command line
  bool log_requests = true;        // one line per request on stderr
  // Whole-request deadlines (request_deadlines.hpp): a request's head must arrive within
  // head_timeout seconds of the connection or of the previous answer, and its body be read and
  // answered within request_timeout seconds of the head.
  double head_timeout = 10;
  double request_timeout = 60;
};

/// Serves until SIGINT or SIGTERM. Prints "pgamesh serve: listening on http://HOST:PORT/" on stdout
/// once the socket is bound. Returns the process exit status (0 after a signal, 1 when a file named
/// on the command line cannot be read or the address cannot be bound).
int run_server(const ServerOptions& options);

}  // namespace pgamesh::viewer
