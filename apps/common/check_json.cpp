#include "check_json.hpp"

#include <algorithm>
#include <stdexcept>

#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh::cli {

namespace {

Json edge_list(const std::vector<EdgeLocation>& list, std::size_t cap) {
  Json a = Json::array();
  for (std::size_t i = 0; i < list.size() && i < cap; ++i) {
    const EdgeLocation& e = list[i];
    a.push_back(Json{{"face", e.face},
                     {"vertices", Json::array({e.vertex0, e.vertex1})},
                     {"points", Json::array({json_vec3(e.p0), json_vec3(e.p1)})},
                     {"faces", e.face_count}});
  }
  return a;
}

Json face_list(const std::vector<FaceLocation>& list, std::size_t cap) {
  Json a = Json::array();
  for (std::size_t i = 0; i < list.size() && i < cap; ++i) {
    const FaceLocation& f = list[i];
    Json o;
    o["face"] = f.face;
    if (f.same_as != no_edge) o["same_as"] = f.same_as;
    o["centroid"] = json_vec3(f.centroid);
    o["area"] = json_number(f.area);
    a.push_back(std::move(o));
  }
  return a;
}

}  // namespace

Json check_fields(const Mesh& mesh, const MeshSource& source, const Analysis& analysis,
                  const OrientationFix* fix, const CheckJsonOptions& options) {
  if (!analysis.topology) throw std::invalid_argument("check_fields: no topology report");
  const TopologyReport& r = *analysis.topology;
  const std::size_t cap = options.list_cap;
  Json j;
  j["file"] = source.path;
  j["format"] = format_name(source.format);
  j["unit"] = unit_name(analysis.unit);
  // The summary fields shared with `pgamesh props`.
  j["triangles"] = r.triangles;
  j["faces"] = r.faces;
  j["vertices"] = r.vertices;
  j["area"] = json_number(r.area);
  j["volume"] = json_number(r.volume);
  j["volume_valid"] = analysis.volume_valid.value_or(false);
  j["gap_area"] = json_number(r.gap_area);
  j["closed"] = r.closed;
  j["boundary_edges"] = r.boundary_edges;
  j["nonmanifold_edges"] = r.nonmanifold_edges;
  j["orientation_consistent"] = r.orientation_consistent;
  j["carrier_sum"] = json_plane(r.carrier_sum);
  // Weld and edges.
  j["weld"] = Json{{"input_vertices", r.input_vertices},
                   {"merged_vertices", r.merged_vertices},
                   {"tolerance", json_number(r.weld_tolerance)},
                   {"max_moved", json_number(r.weld_max_moved)},
                   {"unreferenced_vertices", r.unreferenced_vertices}};
  j["edges"] = r.edges;
  j["inconsistent_edges"] = r.inconsistent_edges;
  j["reference_point"] = json_vec3(r.reference_point);
  // The gap and what it leaves open.
  j["gap_vector"] = json_vec3(r.gap_vector);
  j["volume_range"] = json_range(r.volume_min, r.volume_max);
  j["volume_ambiguity"] = json_number(r.volume_ambiguity());
  j["boundary_loop_count"] = r.boundary_loops.size();
  j["boundary_loops_area"] = json_number(r.loops_area);
  Json loops = Json::array();
  for (std::size_t i = 0; i < r.boundary_loops.size() && i < cap; ++i) {
    const BoundaryLoop& loop = r.boundary_loops[i];
    Json points = Json::array();
    for (std::size_t k = 0; k < loop.half_edges.size() && k < options.loop_point_cap; ++k)
      points.push_back(json_vec3(mesh.vertices[mesh.corners[loop.half_edges[k]]]));
    loops.push_back(Json{{"edges", loop.half_edges.size()},
                         {"closed", loop.closed},
                         {"vector_area", json_vec3(loop.vector_area)},
                         {"area", json_number(loop.area)},
                         {"perimeter", json_number(loop.perimeter)},
                         {"points", std::move(points)}});
  }
  j["boundary_loops"] = std::move(loops);
  j["boundary_edge_list"] = edge_list(r.boundary_edge_list, cap);
  j["nonmanifold_edge_list"] = edge_list(r.nonmanifold_edge_list, cap);
  j["inconsistent_edge_list"] = edge_list(r.inconsistent_edge_list, cap);
  // Faces.
  j["degenerate_faces"] = Json{{"zero_area", r.zero_area_faces},
                               {"collapsed", r.collapsed_faces},
                               {"small_area", r.small_area_faces},
                               {"area_threshold", json_number(r.area_threshold)},
                               {"zero_area_list", face_list(r.zero_area_list, cap)},
                               {"small_area_list", face_list(r.small_area_list, cap)}};
  j["duplicated_faces"] = r.duplicated_faces;
  j["duplicated_face_list"] = face_list(r.duplicated_list, cap);
  // Self-intersections: null when not looked for.
  if (r.self_intersections_checked) {
    j["self_intersecting_pairs"] = r.self_intersecting_pairs;
    j["self_intersections_complete"] = r.self_intersections_complete;
    Json pairs = Json::array();
    for (std::size_t i = 0; i < r.self_intersection_list.size() && i < cap; ++i) {
      const SelfIntersection& s = r.self_intersection_list[i];
      pairs.push_back(Json{{"face0", s.face0}, {"face1", s.face1}, {"point", json_vec3(s.point)}});
    }
    j["self_intersection_list"] = std::move(pairs);
  } else {
    j["self_intersecting_pairs"] = nullptr;
    j["self_intersections_complete"] = nullptr;
    j["self_intersection_list"] = Json::array();
  }
  // Components.
  j["components"] = r.components;
  j["closed_components"] = r.closed_components;
  j["cavity_components"] = r.cavity_components;
  j["inward_components"] = r.inward_components;
  Json components = Json::array();
  for (std::size_t i = 0; i < r.component_list.size() && i < cap; ++i) {
    const ComponentSummary& c = r.component_list[i];
    components.push_back(Json{{"first_face", c.first_face},
                              {"faces", c.faces},
                              {"area", json_number(c.area)},
                              {"volume", json_number(c.volume)},
                              {"closed", c.closed},
                              {"depth", c.depth},
                              {"cavity", c.cavity},
                              {"inward", c.inward},
                              {"boundary_edges", c.boundary_edges},
                              {"nonmanifold_edges", c.nonmanifold_edges},
                              {"inconsistent_edges", c.inconsistent_edges}});
  }
  j["component_list"] = std::move(components);
  if (fix) {
    Json parts = Json::array();
    for (std::size_t i = 0; i < fix->components.size() && i < cap; ++i) {
      const ComponentOrientation& c = fix->components[i];
      Json flipped = Json::array();
      for (std::size_t k = 0; k < c.flipped_faces.size() && k < cap; ++k)
        flipped.push_back(c.flipped_faces[k]);
      parts.push_back(Json{{"component", c.component},
                           {"first_face", c.first_face},
                           {"faces", c.faces},
                           {"flipped", c.flipped},
                           {"closed", c.closed},
                           {"depth", c.depth},
                           {"volume", json_number(c.volume)},
                           {"conflicts", c.conflicts},
                           {"flipped_faces", std::move(flipped)}});
    }
    j["orientation_fix"] = Json{{"flipped_faces", fix->flipped},
                                {"conflicts", fix->conflicts},
                                {"components", std::move(parts)}};
  }
  j["list_cap"] = cap;
  j["notes"] = json_strings(r.notes);
  j["reasons"] = json_strings(analysis.reasons);
  j["warnings"] = json_strings(analysis.warnings);
  return j;
}

std::string check_json(const Mesh& mesh, const MeshSource& source, const Analysis& analysis,
                       const OrientationFix* fix, const CheckJsonOptions& options) {
  return json_text(check_fields(mesh, source, analysis, fix, options)) + "\n";
}

}  // namespace pgamesh::cli
