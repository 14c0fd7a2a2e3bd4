// glTF 2.0 writer (docs/formats.md, "glTF 2.0"): the specification stores positions as float32
// (componentType 5126), so coordinates are rounded to float32 here, as binary STL rounds them.
#include "io/write_gltf.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace pgamesh::detail {

namespace {

void put_le32(std::string& out, std::uint32_t v) {
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

std::string base64(const std::string& bytes) {
  static constexpr char digits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16 |
                            std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8 |
                            static_cast<unsigned char>(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += digits[(v >> s) & 63];
  }
  if (i < bytes.size()) {
    std::uint32_t v = std::uint32_t{static_cast<unsigned char>(bytes[i])} << 16;
    if (i + 1 < bytes.size()) v |= std::uint32_t{static_cast<unsigned char>(bytes[i + 1])} << 8;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

float to_float32(double x) {
  const float f = static_cast<float>(x);
  if (!std::isfinite(f))
    throw std::invalid_argument("write_mesh: coordinate " + std::to_string(x) +
                                " does not fit the float32 positions of glTF");
  return f;
}

}  // namespace

std::string write_gltf(const Mesh& mesh, bool binary) {
  using Json = nlohmann::json;
  // The buffer: positions (12 bytes a vertex), then the triangles' indices (4 bytes a corner) but
  // for a soup (below).
  std::string buffer;
  std::uint64_t triangles = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) >= 3) triangles += mesh.face_size(f) - 2;
  if (3 * triangles > std::numeric_limits<std::uint32_t>::max() ||
      mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max() / 12)
    throw std::invalid_argument("write_mesh: too large for one glTF buffer");
  buffer.reserve(12 * mesh.vertices.size() + 12 * triangles);
  float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                 std::numeric_limits<float>::infinity()};
  float hi[3] = {-lo[0], -lo[1], -lo[2]};
  for (const Vec3d& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      const float f = to_float32(v[k]);
      lo[k] = std::min(lo[k], f);
      hi[k] = std::max(hi[k], f);
      put_le32(buffer, std::bit_cast<std::uint32_t>(f));
    }
  // A triangle soup whose corners are its vertices in order (a binary STL read, three vertices a
  // triangle) is written without indices: they would say 0, 1, 2, … (glTF 2.0 §3.7.2.1, a
  // primitive without indices), and a GLB of them is then streamed like a binary STL
  // (docs/formats.md, "glTF 2.0").
  bool soup =
      mesh.vertices.size() == 3 * mesh.face_count() && mesh.corners.size() == mesh.vertices.size();
  for (std::size_t f = 0; soup && f < mesh.face_count(); ++f) soup = mesh.face_size(f) == 3;
  for (std::size_t i = 0; soup && i < mesh.corners.size(); ++i) soup = mesh.corners[i] == i;
  const std::size_t index_offset = buffer.size();
  for (std::size_t f = 0; f < mesh.face_count() && !soup; ++f) {
    const std::uint32_t* c = mesh.face(f);
    for (std::size_t k = 1; k + 1 < mesh.face_size(f); ++k)
      for (std::uint32_t i : {c[0], c[k], c[k + 1]}) put_le32(buffer, i);
  }

  Json doc = {{"asset", {{"version", "2.0"}, {"generator", "pgamesh"}}}, {"scene", 0}};
  if (triangles == 0 || mesh.vertices.empty()) {
    doc["scenes"] = Json::array({Json::object({{"nodes", Json::array()}})});
    buffer.clear();
  } else {
    doc["scenes"] = Json::array({Json::object({{"nodes", {0}}})});
    doc["nodes"] = Json::array({Json::object({{"mesh", 0}})});
    Json primitive = {{"attributes", {{"POSITION", 0}}}, {"mode", 4}};
    if (!soup) primitive["indices"] = 1;
    doc["meshes"] = Json::array({Json::object({{"primitives", Json::array({primitive})}})});
    Json min = Json::array(), max = Json::array();
    for (int k = 0; k < 3; ++k) {
      min.push_back(static_cast<double>(lo[k]));
      max.push_back(static_cast<double>(hi[k]));
    }
    doc["accessors"] = Json::array({Json::object({{"bufferView", 0},
                                                  {"componentType", 5126},
                                                  {"count", mesh.vertices.size()},
                                                  {"type", "VEC3"},
                                                  {"min", min},
                                                  {"max", max}})});
    doc["bufferViews"] = Json::array({Json::object(
        {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", index_offset}, {"target", 34962}})});
    if (!soup) {
      doc["accessors"].push_back(Json::object({{"bufferView", 1},
                                               {"componentType", 5125},
                                               {"count", 3 * triangles},
                                               {"type", "SCALAR"}}));
      doc["bufferViews"].push_back(Json::object({{"buffer", 0},
                                                 {"byteOffset", index_offset},
                                                 {"byteLength", buffer.size() - index_offset},
                                                 {"target", 34963}}));
    }
    Json b = {{"byteLength", buffer.size()}};
    if (!binary) b["uri"] = "data:application/octet-stream;base64," + base64(buffer);
    doc["buffers"] = Json::array({b});
  }
  std::string json = doc.dump();
  if (!binary) return json + "\n";

  // GLB: header (magic, version 2, length), the JSON chunk padded with spaces and the BIN chunk
  // padded with zeros to 4 bytes (glTF 2.0 §4.4).
  json.append((4 - json.size() % 4) % 4, ' ');
  buffer.append((4 - buffer.size() % 4) % 4, '\0');
  const std::uint64_t total = 12 + 8 + json.size() + (buffer.empty() ? 0 : 8 + buffer.size());
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("write_mesh: too large for a GLB file (4 GiB)");
  std::string out;
  out.reserve(total);
  out += "glTF";
  put_le32(out, 2);
  put_le32(out, static_cast<std::uint32_t>(total));
  put_le32(out, static_cast<std::uint32_t>(json.size()));
  put_le32(out, 0x4E4F534A);
  out += json;
  if (!buffer.empty()) {
    put_le32(out, static_cast<std::uint32_t>(buffer.size()));
    put_le32(out, 0x004E4942);
    out += buffer;
  }
  return out;
}

}  // namespace pgamesh::detail
