#include "server.hpp"

#include <httplib.h>
#include <pthread.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <new>
#include <regex>
#include <stdexcept>
#include <thread>

#include "assets.hpp"
#include "boundary_json.hpp"
#include "bounded_body.hpp"
#include "fuel_routes.hpp"
#include "local_hosts.hpp"
#include "mesh_store.hpp"
#include "mesh_view.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/repair/repair.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "props_report.hpp"
#include "repair_json.hpp"
#include "request_deadlines.hpp"
#include "responses.hpp"

namespace pgamesh::viewer {

namespace {

using nlohmann::json;

constexpr std::size_t kWorkerThreads = 32;
// Connection limits (docs/viewer.md, "Limits"). Each read or write of a request or answer must
// progress within kReadWriteTimeoutSeconds; an idle keep-alive connection is closed after
// kKeepAliveSeconds and any connection after kKeepAliveRequests requests, so a client holds a
// worker only while it sends or reads; and a whole request must arrive within the deadlines of
// ServerOptions (request_deadlines.hpp), so a client that trickles bytes cannot hold it long.
constexpr time_t kReadWriteTimeoutSeconds = 5;
constexpr time_t kKeepAliveSeconds = 2;
constexpr std::size_t kKeepAliveRequests = 100;
// Pending connections the kernel holds before the accept loop takes them (httplib says 5).
constexpr int kListenBacklog = 1024;
constexpr std::size_t kMaxBoundarySegments = 100000;

// What a path may be asked with: "GET" (HEAD included), "POST", or nothing (unknown path).
const std::regex kMeshRoutes(
    R"(/api/mesh/[fu][0-9]{1,18}(/geometry|/props|/boundary|/check|/fuel|/fuel/table)?)");
const std::regex kRepairRoute(R"(/api/mesh/[fu][0-9]{1,18}/repair)");

std::string allowed_method(const AssetTable& assets, const std::string& path) {
  if (assets.by_url.count(path) || path == "/api/info" || path == "/api/meshes" ||
      std::regex_match(path, kMeshRoutes))
    return "GET";
  if (path == "/api/upload" || std::regex_match(path, kRepairRoute)) return "POST";
  return {};
}

// The declared Content-Length, 0 when there is none (or it is not a number: httplib refuses it).
std::uint64_t content_length(const httplib::Request& req) {
  const std::string text = req.get_header_value("Content-Length");
  std::uint64_t length = 0;
  std::from_chars(text.data(), text.data() + text.size(), length);
  return length;
}

bool has_body(const httplib::Request& req) {
  return req.has_header("Transfer-Encoding") || content_length(req) > 0;
}

bool changes_state(const std::string& method) {
  return method != "GET" && method != "HEAD" && method != "OPTIONS";
}

std::string upload_limit_message(std::size_t max_upload) {
  return "the request is larger than the upload limit of " + std::to_string(max_upload) +
         " bytes (pgamesh serve --max-upload)";
}

// An answer given before the body was read closes the connection: the unread rest of the body
// would otherwise be read as the next request.
httplib::Server::HandlerResponse refuse(const httplib::Request& req, httplib::Response& res,
                                        int status, const std::string& message) {
  if (has_body(req))
    send_error_and_close(res, status, message);
  else
    send_error(res, status, message);
  return httplib::Server::HandlerResponse::Handled;
}

// The bundled meshes: every mesh file directly in the folder, sorted by name.
std::vector<std::filesystem::path> bundled_meshes(const std::string& dir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  if (dir.empty() || !std::filesystem::is_directory(dir, ec)) return out;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.is_regular_file(ec) && has_mesh_extension(e.path().string())) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The name an upload is shown and reported under: the last path component the page sent, bounded.
std::string upload_name(const httplib::Request& req) {
  std::string name = req.has_param("name") ? req.get_param_value("name") : "";
  const auto slash = name.find_last_of("/\\");
  if (slash != std::string::npos) name.erase(0, slash + 1);
  name.erase(std::remove_if(name.begin(), name.end(),
                            [](unsigned char c) { return c < 0x20 || c == 0x7f; }),
             name.end());
  if (name.size() > 120) name.resize(120);
  return name.empty() ? "upload" : name;
}

void add_routes(httplib::Server& svr, const ServerOptions& options, const HostCheck& hosts,
                const AssetTable& assets, MeshStore& store) {
  // Every request passes here before its body is read: who may ask, what, and how much.
  svr.set_pre_routing_handler([&](const httplib::Request& req, httplib::Response& res) {
    RequestWatchdog::head_received();
    const std::string host = req.get_header_value("Host");
    if (!host_allowed(hosts, host))
      return refuse(req, res, 421,
                    "this server answers requests for http://" + hosts.hosts.front() +
                        "/ and the other names of this machine's loopback, not for Host '" + host +
                        "'");
    if (changes_state(req.method) && req.has_header("Origin") &&
        !origin_is_own(req.get_header_value("Origin"), host))
      return refuse(req, res, 403,
                    "cross-origin request refused: Origin '" + req.get_header_value("Origin") +
                        "' is not this server's");
    const std::string allowed = allowed_method(assets, req.path);
    if (allowed.empty()) return refuse(req, res, 404, "not found: " + req.path);
    const bool ok =
        allowed == "GET" ? (req.method == "GET" || req.method == "HEAD") : req.method == allowed;
    if (!ok) {
      res.set_header("Allow", allowed == "GET" ? "GET, HEAD" : allowed);
      return refuse(req, res, 405, "method " + req.method + " not allowed on " + req.path);
    }
    if (allowed == "GET" && has_body(req))
      return refuse(req, res, 413, req.path + " takes no request body");
    // A declared length up to kBodyDrainBytes over the limit is read and dropped by httplib
    // (set_payload_max_length) so the client reads the 413; beyond that it is not read at all.
    if (content_length(req) > options.max_upload + kBodyDrainBytes)
      return refuse(req, res, 413, upload_limit_message(options.max_upload));
    return httplib::Server::HandlerResponse::Unhandled;
  });

  for (const auto& [url, asset] : assets.by_url) {
    svr.Get(std::regex_replace(url, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"),
            [&asset = asset](const httplib::Request&, httplib::Response& res) {
              res.set_content(asset.body, asset.content_type);
            });
  }

  svr.Get("/api/info", [&options](const httplib::Request&, httplib::Response& res) {
    send_json(res, 200,
              {{"version", PGAMESH_VERSION},
               {"max_upload", options.max_upload},
               {"features", {{"props", true}, {"check", true}, {"fuel", true}}}});
  });

  svr.Get("/api/meshes", [&store](const httplib::Request&, httplib::Response& res) {
    json list = json::array();
    for (const FileEntry& f : store.files())
      list.push_back({{"id", f.id}, {"name", f.name}, {"origin", f.origin}});
    send_json(res, 200, {{"meshes", list}});
  });

  svr.Get(R"(/api/mesh/([fu][0-9]{1,18}))",
          [&store](const httplib::Request& req, httplib::Response& res) {
            if (auto m = find_mesh(store, req.matches[1], res))
              send_json(res, 200, mesh_summary_json(*m));
          });

  svr.Get(R"(/api/mesh/([fu][0-9]{1,18})/geometry)",
          [&store](const httplib::Request& req, httplib::Response& res) {
            if (auto m = find_mesh(store, req.matches[1], res)) {
              res.set_header("Cache-Control", "no-store");
              res.set_content(mesh_geometry_binary(m->mesh), "application/octet-stream");
            }
          });

  svr.Get(R"(/api/mesh/([fu][0-9]{1,18})/props)",
          [&store](const httplib::Request& req, httplib::Response& res) {
            AnalysisOptions options;
            if (req.has_param("density")) {
              double density = 0;
              if (!parse_number(req.get_param_value("density"), density) || !(density > 0))
                return send_error(res, 400, "density must be a positive finite number");
              options.mass.density = density;
            }
            if (auto m = find_mesh(store, req.matches[1], res)) {
              options.topology_options.weld_tolerance = m->weld_tolerance;
              try {
                // The same report and JSON as `pgamesh props --json` (apps/cli/props_report.hpp).
                send_raw_json(res, cli::props_json(analyze_mesh(m->mesh, m->source, options)));
              } catch (const std::invalid_argument& e) {
                send_error(res, 422, m->name + ": " + e.what());
              } catch (const std::out_of_range& e) {
                send_error(res, 422, m->name + ": " + e.what());
              } catch (const std::range_error& e) {  // figures beyond double's range
                send_error(res, 422, m->name + ": " + e.what());
              }
            }
          });

  // What check finds, to draw and list: boundary, non-manifold and inconsistent edges (at most
  // kMaxBoundarySegments of each), the faces of intersecting pairs (of as many pairs), the holes'
  // loops, the defects' counts. /boundary is its old name.
  svr.Get(R"(/api/mesh/([fu][0-9]{1,18})/(boundary|check))",
          [&store](const httplib::Request& req, httplib::Response& res) {
            if (auto m = find_mesh(store, req.matches[1], res)) {
              TopologyOptions options;
              options.list_cap = kMaxBoundarySegments;
              options.weld_tolerance = m->weld_tolerance;
              try {
                send_raw_json(res, boundary_json(analyze_topology(m->mesh, options), m->mesh));
              } catch (const std::exception& e) {
                send_error(res, 422, m->name + ": " + e.what());
              }
            }
          });

  // The Repair action: `pgamesh repair` on the mesh (welded within its tolerance), the result
  // stored as a new mesh; answers {mesh: its summary, repair: the report of repair --json}.
  svr.Post(R"(/api/mesh/([fu][0-9]{1,18})/repair)", [&store](const httplib::Request& req,
                                                             httplib::Response& res) {
    RepairOptions options;
    if (req.has_param("planarity")) {
      double r = 0;
      if (!parse_number(req.get_param_value("planarity"), r) || !(r >= 0))
        return send_error(res, 400, "planarity must be a finite number >= 0");
      options.hole.planarity = r;
    }
    options.hole.force = req.has_param("force") && req.get_param_value("force") == "1";
    const auto m = find_mesh(store, req.matches[1], res);
    if (!m) return;
    try {
      options.weld_tolerance = m->weld_tolerance;
      Mesh mesh = m->mesh;
      const RepairReport report = repair(mesh, options);
      AnalysisOptions analysis_options;
      analysis_options.topology_options.list_cap = 0;
      const Analysis result = analyze_mesh(mesh, m->source, analysis_options);
      const auto repaired = store.add_mesh(m->name + " (repaired)", std::move(mesh), m->source, 0);
      send_raw_json(res, "{\"mesh\":" + mesh_summary_json(*repaired).dump() + ",\"repair\":" +
                             cli::json_text(cli::repair_fields(m->source, report, result,
                                                               options.list_cap, repaired->id)) +
                             "}");
      res.status = 201;
    } catch (const std::exception& e) {
      send_error(res, 422, m->name + ": " + e.what());
    }
  });

  add_fuel_routes(svr, store);

  // The body is the file's bytes whatever its Content-Type (a form-urlencoded or multipart body is
  // not decoded), read through a content reader so the limit holds for every transfer encoding.
  svr.Post("/api/upload", [&store, &options](const httplib::Request& req, httplib::Response& res,
                                             const httplib::ContentReader& content_reader) {
    const std::string name = upload_name(req);
    std::string body;
    BodyRead read = read_bounded_body(content_reader, options.max_upload, body);
    // httplib itself drops a declared Content-Length over set_payload_max_length, with 413.
    if (read == BodyRead::unreadable && res.status == 413) read = BodyRead::too_large;
    switch (read) {
      case BodyRead::too_large:
        return send_error_and_close(res, 413, upload_limit_message(options.max_upload));
      case BodyRead::unreadable:
        return send_error_and_close(
            res, res.status == 415 ? 415 : 400,
            name +
                ": the request body could not be read (malformed chunks, cut short, or an "
                "unsupported Content-Encoding)");
      case BodyRead::complete:
        break;
    }
    if (body.empty()) return send_error(res, 400, name + ": the upload is empty");
    std::optional<double> weld_tolerance;
    if (req.has_param("weld_tolerance")) {
      double t = 0;
      if (!parse_number(req.get_param_value("weld_tolerance"), t) || !(t >= 0))
        return send_error(res, 400, "weld_tolerance must be a finite number >= 0");
      weld_tolerance = t;
    }
    try {
      const auto m = store.add_upload(name, {body.data(), body.size()}, weld_tolerance);
      send_json(res, 201, mesh_summary_json(*m));
    } catch (const InputError& e) {
      send_error(res, 400, e.what());
    }
  });

  // Errors raised by httplib itself (malformed request 400, request line too long 414, ...) get a
  // JSON body; the answers written here already have their type.
  svr.set_error_handler([&options](const httplib::Request&, httplib::Response& res) {
    if (res.has_header("Content-Type")) return;
    if (res.status == 413)
      send_error(res, 413, upload_limit_message(options.max_upload));
    else
      send_error(res, res.status, std::string("HTTP ") + std::to_string(res.status));
  });

  svr.set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
        try {
          std::rethrow_exception(ep);
        } catch (const std::bad_alloc&) {
          send_error(res, 500, "out of memory while handling the request");
        } catch (const std::exception& e) {
          send_error(res, 500, std::string("internal error: ") + e.what());
        } catch (...) {
          send_error(res, 500, "internal error");
        }
      });

  // Called once each answer is written: the next request's head deadline starts here.
  svr.set_logger(
      [log = options.log_requests](const httplib::Request& req, const httplib::Response& res) {
        RequestWatchdog::answer_sent();
        if (log)
          std::fprintf(stderr, "pgamesh serve: %s %s -> %d\n", req.method.c_str(), req.path.c_str(),
                       res.status);
      });
}

}  // namespace

int run_server(const ServerOptions& options) {
  const AssetTable assets = load_assets(options.web_dir);
  for (const std::string& m : assets.missing)
    std::fprintf(stderr, "pgamesh serve: warning: %s is missing (run scripts/setup.sh)\n",
                 m.c_str());

  MeshStore store(options.max_kept_uploads, options.weld_tolerance);
  // Files named on the command line are read now: a mistake there is reported before serving.
  for (const std::string& f : options.files) {
    try {
      store.get(store.add_file(f, std::filesystem::path(f).filename().string(), "command line"));
    } catch (const InputError& e) {
      std::fprintf(stderr, "pgamesh serve: %s\n", e.what());
      return 1;
    }
  }
  for (const auto& p : bundled_meshes(options.bundled_dir))
    store.add_file(p.string(), p.filename().string(), "bundled");

  // SIGINT/SIGTERM are taken by one waiting thread (blocked everywhere else, the server's worker
  // threads inherit the mask), which stops the server so it shuts down cleanly.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  const auto to_ms = [](double seconds) {
    return std::chrono::milliseconds(static_cast<long long>(seconds * 1000));
  };
  RequestWatchdog watchdog({to_ms(options.head_timeout), to_ms(options.request_timeout)});
  httplib::Server svr;
  // A declared Content-Length over the limit: read and dropped by httplib, then 413.
  svr.set_payload_max_length(options.max_upload);
  // A client asking before it sends (curl does for bodies over 1 MiB) is refused before sending.
  svr.set_expect_100_continue_handler(
      [&options](const httplib::Request& req, httplib::Response& res) {
        if (content_length(req) <= options.max_upload) return 100;
        send_error(res, 413, upload_limit_message(options.max_upload));
        return 413;
      });
  // Not httplib's default SO_REUSEPORT: a second server on a busy port must fail, not share it.
  // The socket is kept to widen its accept backlog after the bind (below).
  socket_t listening = INVALID_SOCKET;
  svr.set_socket_options([&listening](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    listening = sock;
  });
  // httplib gives each connection a worker thread while it is open, idle keep-alive included:
  // enough workers for a few browser tabs (6 connections each) and short idle keep-alives.
  svr.new_task_queue = [&watchdog] { return watchdog.new_task_queue(kWorkerThreads); };
  svr.set_read_timeout(kReadWriteTimeoutSeconds);
  svr.set_write_timeout(kReadWriteTimeoutSeconds);
  svr.set_keep_alive_timeout(kKeepAliveSeconds);
  svr.set_keep_alive_max_count(kKeepAliveRequests);
  svr.set_default_headers({{"X-Content-Type-Options", "nosniff"}});

  const int port = options.port == 0
                       ? svr.bind_to_any_port(options.host)
                       : (svr.bind_to_port(options.host, options.port) ? options.port : -1);
  if (port < 0) {
    std::fprintf(stderr, "pgamesh serve: cannot listen on %s:%d (in use, or not a local address)\n",
                 options.host.c_str(), options.port);
    return 1;
  }
  // httplib 0.11.4 listens with a backlog of 5: a burst of connections overflowed it, and the
  // kernel's SYN-cookie fallback then lost the first bytes of requests or left connections
  // without data until the 2 s keep-alive wait closed them (tests/viewer/load.test.mjs, 50 slow
  // clients connecting at once). Listening again on Linux only changes the backlog.
  if (listening != INVALID_SOCKET && ::listen(listening, kListenBacklog) != 0)
    std::fprintf(stderr, "pgamesh serve: could not widen the accept backlog; continuing\n");
  const HostCheck hosts = host_check_for(options.host, port, options.allow_remote);
  add_routes(svr, options, hosts, assets, store);
  const bool ipv6 = options.host.find(':') != std::string::npos;
  std::printf("pgamesh serve: listening on http://%s%s%s:%d/\n", ipv6 ? "[" : "",
              options.host.c_str(), ipv6 ? "]" : "", port);
  std::fflush(stdout);

  std::atomic<bool> signalled{false}, listen_over{false};
  std::thread stopper([&svr, &signalled, &listen_over, stop_signals] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    signalled = true;
    // httplib's stop() acts only once the accept loop runs: a signal right after the bind waits.
    while (!svr.is_running() && !listen_over)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    svr.stop();
  });
  svr.listen_after_bind();
  listen_over = true;
  if (!signalled) pthread_kill(stopper.native_handle(), SIGTERM);  // wake the waiter to end it
  stopper.join();
  std::fprintf(stderr, "pgamesh serve: stopped\n");
  return 0;
}

}  // namespace pgamesh::viewer
