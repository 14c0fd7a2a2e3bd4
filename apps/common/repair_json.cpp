#include "repair_json.hpp"

#include "pgamesh/io/mesh_format.hpp"

namespace pgamesh::cli {

Json repair_fields(const MeshSource& source, const RepairReport& r, const Analysis& result,
                   std::size_t list_cap, const std::string& output) {
  Json holes = Json::array();
  for (std::size_t i = 0; i < r.holes.size() && i < list_cap; ++i) {
    const CappedHole& h = r.holes[i];
    holes.push_back(Json{{"vertices", h.rim_vertices},
                         {"first_vertex", json_vec3(h.first_vertex)},
                         {"area", json_number(h.area)},
                         {"max_deviation", json_number(h.max_deviation)},
                         {"capped", h.refused.empty()},
                         {"triangles", h.triangles},
                         {"refused", h.refused}});
  }
  const TopologyReport& t = *result.topology;
  Json j;
  j["file"] = source.path;
  j["format"] = format_name(source.format);
  j["output"] = output;
  j["weld"] = Json{{"input_vertices", r.input_vertices},
                   {"merged", r.merged_vertices},
                   {"tolerance", json_number(r.weld_tolerance)},
                   {"max_moved", json_number(r.weld_max_moved)}};
  j["removed_faces"] = Json{{"collapsed", r.collapsed_faces},
                            {"duplicated", r.duplicate_faces},
                            {"double_wall_pairs", r.opposite_pairs},
                            {"list", r.removed_faces}};
  j["merged_corners"] = r.repeated_corners;
  j["reversed_faces"] = Json{{"count", r.reversed_faces}, {"list", r.reversed_list}};
  j["orientation_conflicts"] = r.orientation_conflicts;
  j["holes"] = Json{{"count", r.holes.size()},
                    {"capped", r.holes_capped},
                    {"refused", r.holes_refused},
                    {"cap_triangles", r.cap_triangles},
                    {"list", holes}};
  j["unreferenced_vertices"] = r.unreferenced_vertices;
  j["result"] = Json{{"vertices", r.output_vertices},
                     {"faces", r.output_faces},
                     {"closed", t.closed},
                     {"volume_valid", result.volume_valid.value_or(false)},
                     {"volume", json_number(result.mass.volume)},
                     {"area", json_number(result.mass.area)},
                     {"reasons", json_strings(result.reasons)}};
  j["warnings"] = json_strings(result.warnings);
  return j;
}

}  // namespace pgamesh::cli
