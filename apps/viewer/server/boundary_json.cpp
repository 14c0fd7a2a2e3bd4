#include "boundary_json.hpp"

#include "json_text.hpp"

namespace pgamesh::viewer {

std::string boundary_json(const TopologyReport& t) {
  using cli::Json;
  Json segments = Json::array();
  for (const EdgeLocation& e : t.boundary_edge_list)
    segments.push_back(Json::array({cli::json_number(e.p0.x), cli::json_number(e.p0.y),
                                    cli::json_number(e.p0.z), cli::json_number(e.p1.x),
                                    cli::json_number(e.p1.y), cli::json_number(e.p1.z)}));
  Json loops = Json::array();
  for (const BoundaryLoop& l : t.boundary_loops)
    loops.push_back(Json{{"area", cli::json_number(l.area)},
                         {"perimeter", cli::json_number(l.perimeter)},
                         {"vector_area", cli::json_vec3(l.vector_area)}});
  Json w;
  w["boundary_edges"] = t.boundary_edges;
  w["segments"] = std::move(segments);
  w["loops"] = std::move(loops);
  w["gap_area"] = cli::json_number(t.gap_area);
  return cli::json_text(w);
}

}  // namespace pgamesh::viewer
