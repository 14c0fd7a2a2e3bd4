#include "props_json.hpp"

#include "json_writer.hpp"

namespace pgamesh::viewer {

namespace {

void vec(cli::JsonWriter& w, std::string_view key, const Vec3d& v) {
  w.begin_array(key).number(v.x).number(v.y).number(v.z).end_array();
}

void mat(cli::JsonWriter& w, std::string_view key, const Mat3& m) {
  w.begin_array(key);
  for (const auto& row : m)
    w.begin_array().number(row[0]).number(row[1]).number(row[2]).end_array();
  w.end_array();
}

}  // namespace

std::string props_json(const MassProperties& p, const TopologyReport* topology) {
  cli::JsonWriter w;
  w.begin_object();
  w.integer("triangles", p.triangles).integer("faces", p.faces).integer("vertices", p.vertices);
  w.number("area", p.area).number("volume", p.volume);
  w.number("density", p.density).number("mass", p.mass);
  vec(w, "center_of_mass", p.center_of_mass);
  mat(w, "inertia_com", p.inertia_com);
  mat(w, "inertia_origin", p.inertia_origin);
  w.begin_object("products_of_inertia_com")
      .number("xy", p.products_com.xy)
      .number("yz", p.products_com.yz)
      .number("zx", p.products_com.zx)
      .end_object();
  w.begin_array("principal_moments");
  for (const double m : p.principal.moments) w.number(m);
  w.end_array();
  w.begin_array("principal_axes");
  for (const Vec3d& a : p.principal.axes)
    w.begin_array().number(a.x).number(a.y).number(a.z).end_array();
  w.end_array();
  w.boolean("principal_degenerate", p.principal.degenerate);
  w.number("gap_area", p.gap_area);
  w.string("inertia_convention",
           "tensor I = integral of rho (|r|^2 1 - r r^T) dV; off-diagonals are minus the "
           "products of inertia (I_xy = -integral of x y dm)");
  w.begin_array("warnings");
  for (const std::string& s : p.warnings) w.string(s);
  w.end_array();
  if (topology) {
    w.boolean("closed", topology->closed);
    w.integer("boundary_edges", topology->boundary_edges);
    w.integer("nonmanifold_edges", topology->nonmanifold_edges);
    w.boolean("orientation_consistent", topology->orientation_consistent);
    w.boolean("volume_valid", topology->volume_valid);
    w.begin_array("notes");
    for (const std::string& s : topology->notes) w.string(s);
    w.end_array();
  }
  w.end_object();
  return w.str();
}

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
