// Writing answers and reading parameters, shared by the server's route files.
#pragma once

#include <httplib.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "mesh_store.hpp"

namespace pgamesh::viewer {

/// A JSON answer with `status`, not cached.
void send_json(httplib::Response& res, int status, const nlohmann::json& body);

/// A 200 answer whose JSON text was written elsewhere (the CLI's JSON builders).
void send_raw_json(httplib::Response& res, std::string body);

/// {"error": message} with `status`.
void send_error(httplib::Response& res, int status, const std::string& message);

/// {"error": message} with `status`, then the connection is closed: for answers given before the
/// request's body was read whole, whose unread rest must not be taken for the next request.
void send_error_and_close(httplib::Response& res, int status, const std::string& message);

/// A whole query parameter as a finite double ("1e3", "-0.5"); false for anything else.
bool parse_number(const std::string& text, double& out);

/// The mesh of a route, or nullptr after answering 404 (unknown id) or 422 (unreadable file).
std::shared_ptr<const StoredMesh> find_mesh(MeshStore& store, const std::string& id,
                                            httplib::Response& res);

}  // namespace pgamesh::viewer
