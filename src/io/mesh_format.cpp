#include "pgamesh/io/mesh_format.hpp"

#include <string>

namespace pgamesh {

namespace {

std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

bool is_ply(MeshFormat f) {
  return f == MeshFormat::ply_ascii || f == MeshFormat::ply_binary_le ||
         f == MeshFormat::ply_binary_be;
}

bool is_stl(MeshFormat f) {
  return f == MeshFormat::stl_ascii || f == MeshFormat::stl_binary;
}

}  // namespace

const char* format_name(MeshFormat f) {
  switch (f) {
    case MeshFormat::stl_ascii:
      return "stl-ascii";
    case MeshFormat::stl_binary:
      return "stl-binary";
    case MeshFormat::obj:
      return "obj";
    case MeshFormat::ply_ascii:
      return "ply-ascii";
    case MeshFormat::ply_binary_le:
      return "ply-binary-little-endian";
    case MeshFormat::ply_binary_be:
      return "ply-binary-big-endian";
    case MeshFormat::off:
      return "off";
    case MeshFormat::threemf:
      return "3mf";
    case MeshFormat::gltf:
      return "gltf";
    case MeshFormat::glb:
      return "glb";
    case MeshFormat::slp:
      return "slp";
    case MeshFormat::unknown:
      break;
  }
  return "unknown";
}

MeshFormat format_from_name(std::string_view name) {
  const std::string n = lower_case(name);
  if (n == "stl" || n == "stl-binary" || n == "stl_binary") return MeshFormat::stl_binary;
  if (n == "stl-ascii" || n == "stl_ascii") return MeshFormat::stl_ascii;
  if (n == "obj") return MeshFormat::obj;
  if (n == "ply" || n == "ply-ascii" || n == "ply_ascii") return MeshFormat::ply_ascii;
  if (n == "ply-binary-little-endian" || n == "ply-le" || n == "ply_binary_le")
    return MeshFormat::ply_binary_le;
  if (n == "ply-binary-big-endian" || n == "ply-be" || n == "ply_binary_be")
    return MeshFormat::ply_binary_be;
  if (n == "off") return MeshFormat::off;
  if (n == "3mf") return MeshFormat::threemf;
  if (n == "gltf") return MeshFormat::gltf;
  if (n == "glb") return MeshFormat::glb;
  if (n == "slp") return MeshFormat::slp;
  return MeshFormat::unknown;
}

MeshFormat format_for_extension(std::string_view path, MeshFormat preferred) {
  const std::size_t dot = path.find_last_of("./");
  if (dot == std::string_view::npos || path[dot] != '.') return MeshFormat::unknown;
  const std::string ext = lower_case(path.substr(dot + 1));
  if (ext == "stl") return is_stl(preferred) ? preferred : MeshFormat::stl_binary;
  if (ext == "ply") return is_ply(preferred) ? preferred : MeshFormat::ply_binary_le;
  if (ext == "obj") return MeshFormat::obj;
  if (ext == "off") return MeshFormat::off;
  if (ext == "3mf") return MeshFormat::threemf;
  if (ext == "gltf") return MeshFormat::gltf;
  if (ext == "glb") return MeshFormat::glb;
  if (ext == "slp") return MeshFormat::slp;
  return MeshFormat::unknown;
}

}  // namespace pgamesh
