// Helpers shared by the tank tests: golden OBJ meshes and comparisons.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "pgamesh/mesh/mesh.hpp"

namespace pgamesh::test {

// Plain `v x y z` / `f i j k` OBJ files (1-based indices; `i/t/n` corners keep i).
inline Mesh load_obj_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Mesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Vec3d v;
      ls >> v.x >> v.y >> v.z;
      m.vertices.push_back(v);
    } else if (tag == "f") {
      std::string tok;
      while (ls >> tok) m.corners.push_back(static_cast<std::uint32_t>(std::stoul(tok) - 1));
      m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
    }
  }
  return m;
}

// A mesh of tests/data/golden (relative path).
inline Mesh load_golden_obj(const std::string& relative) {
  return load_obj_file(std::string(PGAMESH_GOLDEN_DIR) + "/" + relative);
}

}  // namespace pgamesh::test
