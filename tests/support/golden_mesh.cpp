#include "support/golden_mesh.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace pgamesh::test {

Mesh load_obj_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Mesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3d v;
      s >> v.x >> v.y >> v.z;
      m.vertices.push_back(v);
    } else if (tag == "f") {
      std::string corner;  // i, i/t or i/t/n: std::stoul stops at the '/'
      while (s >> corner) m.corners.push_back(static_cast<std::uint32_t>(std::stoul(corner) - 1));
      m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
    }
  }
  return m;
}

Mesh load_golden_obj(const std::string& relative) {
  return load_obj_file(std::string(PGAMESH_GOLDEN_DIR) + "/" + relative);
}

Mesh golden_case_mesh(const json& input) {
  Mesh m;
  if (input.contains("vertices")) {
    for (const auto& v : input["vertices"])
      m.vertices.push_back({v[0].get<double>(), v[1].get<double>(), v[2].get<double>()});
    for (const auto& f : input["faces"]) {
      for (const auto& i : f) m.corners.push_back(i.get<std::uint32_t>());
      m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
    }
  } else {
    m = load_golden_obj(input["mesh_file"].get<std::string>());
  }
  if (input.contains("remove_faces")) {
    std::vector<bool> drop(m.face_count(), false);
    for (const auto& f : input["remove_faces"]) drop.at(f.get<std::size_t>()) = true;
    Mesh kept;
    kept.vertices = m.vertices;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      if (drop[f]) continue;
      kept.corners.insert(kept.corners.end(), m.face(f), m.face(f) + m.face_size(f));
      kept.face_offsets.push_back(static_cast<std::uint32_t>(kept.corners.size()));
    }
    m = std::move(kept);
  }
  return m;
}

}  // namespace pgamesh::test
