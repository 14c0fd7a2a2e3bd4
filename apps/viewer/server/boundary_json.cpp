#include "boundary_json.hpp"

#include "json_writer.hpp"

namespace pgamesh::viewer {

namespace {

void vec(cli::JsonWriter& w, std::string_view key, const Vec3d& v) {
  w.begin_array(key).number(v.x).number(v.y).number(v.z).end_array();
}

}  // namespace

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
    vec(w, "vector_area", l.vector_area);
    w.end_object();
  }
  w.end_array();
  w.number("gap_area", t.gap_area);
  w.end_object();
  return w.str();
}

}  // namespace pgamesh::viewer
