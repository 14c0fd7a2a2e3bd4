// The JSON of `pgamesh props` (DESIGN.md §5 stable fields first, then the additions).
#include "json_writer.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "props_report.hpp"

namespace pgamesh::cli {

namespace {

void products(JsonWriter& w, std::string_view key, const ProductsOfInertia& p) {
  w.begin_object(key).number("xy", p.xy).number("yz", p.yz).number("zx", p.zx).end_object();
}

}  // namespace

std::string props_json(const Analysis& r) {
  const MassProperties& m = r.mass;
  const bool solid = std::isfinite(m.center_of_mass.x);
  JsonWriter w;
  w.begin_object();
  w.integer("triangles", m.triangles);
  w.integer("vertices", r.topology ? r.topology->vertices : m.vertices);
  w.number("area", m.area);
  w.number("volume", m.volume);
  w.number("density", m.density);
  w.number("mass", m.mass);
  w.vec3("center_of_mass", m.center_of_mass);
  w.matrix3("inertia_com", m.inertia_com);
  w.matrix3("inertia_origin", m.inertia_origin);
  w.begin_array("principal_moments");
  for (double v : m.principal.moments) w.number(v);
  w.end_array();
  if (solid) {
    w.begin_array("principal_axes");
    for (const Vec3d& a : m.principal.axes) w.vec3(a);
    w.end_array();
  } else {
    w.null("principal_axes");
  }
  w.number("gap_area", m.gap_area);
  if (r.topology) {
    const TopologyReport& t = *r.topology;
    w.boolean("closed", t.closed);
    w.integer("boundary_edges", t.boundary_edges);
    w.integer("nonmanifold_edges", t.nonmanifold_edges);
    w.boolean("orientation_consistent", t.orientation_consistent);
  } else {
    w.null("closed")
        .null("boundary_edges")
        .null("nonmanifold_edges")
        .null("orientation_consistent");
  }
  // Additions.
  w.string("file", r.file);
  w.string("format", format_name(r.format));
  w.boolean("single_precision", r.single_precision);
  w.boolean("streamed", r.streamed);
  w.integer("faces", m.faces);
  w.integer("input_vertices", m.vertices);
  w.string("density_source", r.density_from_mass ? "mass" : "density");
  products(w, "products_of_inertia_com", m.products_com);
  products(w, "products_of_inertia_origin", m.products_origin);
  w.boolean("principal_degenerate", m.principal.degenerate);
  if (solid) {
    const auto& q = m.principal_motor;
    w.begin_object("principal_motor")
        .number("1", q.s)
        .number("e01", q.e01)
        .number("e02", q.e02)
        .number("e03", q.e03)
        .number("e12", q.e12)
        .number("e31", q.e31)
        .number("e23", q.e23)
        .number("e0123", q.e0123)
        .end_object();
  } else {
    w.null("principal_motor");
  }
  w.string("principal_motor_convention",
           "M = T R: M o ~M = centre of mass, M e_i ~M = principal axis i (directions); ~M takes "
           "the body into its principal frame");
  w.string("convention", inertia_convention);
  w.vec3("reference_point", m.reference_point);
  w.plane("carrier_sum", m.carrier_sum);
  if (r.topology) {
    const TopologyReport& t = *r.topology;
    w.begin_object("topology")
        .integer("edges", t.edges)
        .integer("merged_vertices", t.merged_vertices)
        .integer("inconsistent_edges", t.inconsistent_edges)
        .integer("boundary_loops", t.boundary_loops.size())
        .integer("duplicated_faces", t.duplicated_faces)
        .integer("zero_area_faces", t.zero_area_faces)
        .integer("components", t.components)
        .integer("closed_components", t.closed_components)
        .number("volume_min", t.volume_min)
        .number("volume_max", t.volume_max)
        .end_object();
  } else {
    w.null("topology");
  }
  if (r.volume_valid)
    w.boolean("meaningful", *r.volume_valid);
  else
    w.null("meaningful");
  w.strings("meaningful_reasons", r.reasons);
  w.strings("warnings", r.warnings);
  w.end_object();
  return w.str();
}

}  // namespace pgamesh::cli
