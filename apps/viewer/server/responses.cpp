#include "responses.hpp"

#include <charconv>
#include <cmath>
#include <memory>

#include "pgamesh/core/input_error.hpp"

namespace pgamesh::viewer {

void send_json(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  // With a charset, httplib does not brotli-compress it (slow at its default quality, and
  // pointless on loopback).
  res.set_content(body.dump(), "application/json; charset=utf-8");
}

void send_raw_json(httplib::Response& res, std::string body) {
  res.status = 200;
  res.set_header("Cache-Control", "no-store");
  res.set_content(std::move(body), "application/json; charset=utf-8");
}

void send_error_and_close(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_header("Connection", "close");
  // httplib keeps a connection open after any answer it wrote in full; it closes it when a
  // content provider fails. So the provider writes the whole answer and then reports failure.
  auto body = std::make_shared<const std::string>(nlohmann::json{{"error", message}}.dump());
  res.set_content_provider(body->size(), "application/json; charset=utf-8",
                           [body](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             sink.write(body->data() + offset, length);
                             return false;
                           });
}

bool parse_number(const std::string& text, double& out) {
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, out);
  return ec == std::errc() && p == end && !text.empty() && std::isfinite(out);
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, status, {{"error", message}});
}

std::shared_ptr<const StoredMesh> find_mesh(MeshStore& store, const std::string& id,
                                            httplib::Response& res) {
  try {
    auto stored = store.get(id);
    if (!stored)
      send_error(res, 404, "no mesh with id '" + id + "' (only the most recent uploads are kept)");
    return stored;
  } catch (const InputError& e) {
    send_error(res, 422, e.what());
    return nullptr;
  }
}

}  // namespace pgamesh::viewer
