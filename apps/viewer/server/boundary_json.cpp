#include "boundary_json.hpp"

#include "json_writer.hpp"

namespace pgamesh::viewer {

std::string boundary_json(const TopologyReport& t) {
  cli::JsonWriter w;
  w.begin_object();
  w.integer("boundary_edges", t.boundary_edges);
  w.begin_array("segments");
  for (const EdgeLocation& e : t.boundary_edge_list)
    w.begin_array()
        .number(e.p0.x)
        .number(e.p0.y)
        .number(e.p0.z)
        .number(e.p1.x)
        .number(e.p1.y)
        .number(e.p1.z)
        .end_array();
  w.end_array();
  w.begin_array("loops");
  for (const BoundaryLoop& l : t.boundary_loops) {
    w.begin_object().number("area", l.area).number("perimeter", l.perimeter);
    w.vec3("vector_area", l.vector_area);
    w.end_object();
  }
  w.end_array();
  w.number("gap_area", t.gap_area);
  w.end_object();
  return w.str();
}

}  // namespace pgamesh::viewer
