#include "boundary_json.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "json_text.hpp"

namespace pgamesh::viewer {

namespace {

cli::Json segments(const std::vector<EdgeLocation>& edges) {
  using cli::Json;
  Json out = Json::array();
  for (const EdgeLocation& e : edges)
    out.push_back(Json::array({cli::json_number(e.p0.x), cli::json_number(e.p0.y),
                               cli::json_number(e.p0.z), cli::json_number(e.p1.x),
                               cli::json_number(e.p1.y), cli::json_number(e.p1.z)}));
  return out;
}

// The faces of the listed intersecting pairs, each once in face order, as flat polygons.
cli::Json intersecting_faces(const TopologyReport& t, const Mesh& mesh) {
  using cli::Json;
  std::vector<std::uint32_t> faces;
  for (const SelfIntersection& x : t.self_intersection_list) {
    faces.push_back(x.face0);
    faces.push_back(x.face1);
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  Json out = Json::array();
  for (std::uint32_t f : faces) {
    if (f >= mesh.face_count()) continue;
    Json polygon = Json::array();
    const std::uint32_t* corner = mesh.face(f);
    for (std::size_t k = 0; k < mesh.face_size(f); ++k) {
      const Vec3d& p = mesh.vertices[corner[k]];
      polygon.push_back(cli::json_number(p.x));
      polygon.push_back(cli::json_number(p.y));
      polygon.push_back(cli::json_number(p.z));
    }
    out.push_back(std::move(polygon));
  }
  return out;
}

}  // namespace

std::string boundary_json(const TopologyReport& t, const Mesh& mesh) {
  using cli::Json;
  Json loops = Json::array();
  for (const BoundaryLoop& l : t.boundary_loops)
    loops.push_back(Json{{"area", cli::json_number(l.area)},
                         {"perimeter", cli::json_number(l.perimeter)},
                         {"vector_area", cli::json_vec3(l.vector_area)}});
  Json w;
  w["boundary_edges"] = t.boundary_edges;
  w["segments"] = segments(t.boundary_edge_list);
  w["loops"] = std::move(loops);
  w["gap_area"] = cli::json_number(t.gap_area);
  w["nonmanifold_edges"] = t.nonmanifold_edges;
  w["nonmanifold_segments"] = segments(t.nonmanifold_edge_list);
  w["inconsistent_edges"] = t.inconsistent_edges;
  w["inconsistent_segments"] = segments(t.inconsistent_edge_list);
  w["duplicated_faces"] = t.duplicated_faces;
  w["zero_area_faces"] = t.zero_area_faces;
  w["components"] = t.components;
  w["closed_components"] = t.closed_components;
  w["cavity_components"] = t.cavity_components;
  w["inward_components"] = t.inward_components;
  w["self_intersecting_pairs"] = t.self_intersecting_pairs;
  w["self_intersections_complete"] = t.self_intersections_complete;
  w["self_intersecting_faces"] = intersecting_faces(t, mesh);
  w["notes"] = cli::json_strings(t.notes);
  return cli::json_text(w);
}

}  // namespace pgamesh::viewer
