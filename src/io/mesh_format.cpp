#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh {

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
    case MeshFormat::unknown:
      break;
  }
  return "unknown";
}

}  // namespace pgamesh
