// The JSON of `pgamesh props` (docs/json.md: stable fields first, then the additions).
#include "json_text.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "props_report.hpp"

namespace pgamesh::cli {

namespace {

Json products(const ProductsOfInertia& p) {
  if (!std::isfinite(p.xy) || !std::isfinite(p.yz) || !std::isfinite(p.zx)) return nullptr;
  return Json{{"xy", p.xy}, {"yz", p.yz}, {"zx", p.zx}};
}

// One part alone (Analysis::parts): the figures of the top level under the same names.
Json part_json(const PartAnalysis& p) {
  const MassProperties& m = p.mass;
  Json j;
  j["name"] = p.part.name;
  j["first_face"] = p.part.first_face;
  j["faces"] = m.faces;
  j["triangles"] = m.triangles;
  j["area"] = json_number(m.area);
  j["volume"] = json_number(m.volume);
  j["mass"] = json_number(m.mass);
  j["center_of_mass"] = json_vec3(m.center_of_mass);
  j["inertia_com"] = json_matrix3(m.inertia_com);
  j["gap_area"] = json_number(m.gap_area);
  if (p.topology) {
    j["closed"] = p.topology->closed;
    j["boundary_edges"] = p.topology->boundary_edges;
    j["nonmanifold_edges"] = p.topology->nonmanifold_edges;
    j["orientation_consistent"] = p.topology->orientation_consistent;
    j["components"] = p.topology->components;
  } else {
    for (const char* k :
         {"closed", "boundary_edges", "nonmanifold_edges", "orientation_consistent", "components"})
      j[k] = nullptr;
  }
  j["volume_valid"] = p.volume_valid ? Json(*p.volume_valid) : Json(nullptr);
  j["reasons"] = json_strings(p.reasons);
  return j;
}

}  // namespace

std::string props_json(const Analysis& r) {
  const MassProperties& m = r.mass;
  const bool solid = std::isfinite(m.center_of_mass.x);
  Json j;
  j["triangles"] = m.triangles;
  j["vertices"] = r.topology ? r.topology->vertices : m.vertices;
  j["area"] = json_number(m.area);
  j["volume"] = json_number(m.volume);
  j["density"] = json_number(m.density);
  j["mass"] = json_number(m.mass);
  j["center_of_mass"] = json_vec3(m.center_of_mass);
  j["inertia_com"] = json_matrix3(m.inertia_com);
  j["inertia_origin"] = json_matrix3(m.inertia_origin);
  const auto& pm = m.principal.moments;
  j["principal_moments"] = json_vec3({pm[0], pm[1], pm[2]});
  if (solid) {
    Json axes = Json::array();
    for (const Vec3d& a : m.principal.axes) axes.push_back(json_vec3(a));
    j["principal_axes"] = std::move(axes);
  } else {
    j["principal_axes"] = nullptr;
  }
  j["gap_area"] = json_number(m.gap_area);
  if (r.topology) {
    const TopologyReport& t = *r.topology;
    j["closed"] = t.closed;
    j["boundary_edges"] = t.boundary_edges;
    j["nonmanifold_edges"] = t.nonmanifold_edges;
    j["orientation_consistent"] = t.orientation_consistent;
  } else {
    j["closed"] = nullptr;
    j["boundary_edges"] = nullptr;
    j["nonmanifold_edges"] = nullptr;
    j["orientation_consistent"] = nullptr;
  }
  // Additions.
  j["file"] = r.file;
  j["format"] = format_name(r.format);
  j["unit"] = unit_name(r.unit);
  j["single_precision"] = r.single_precision;
  j["streamed"] = r.streamed;
  j["faces"] = m.faces;
  j["input_vertices"] = m.vertices;
  j["density_source"] = r.density_from_mass ? "mass" : "density";
  j["products_of_inertia_com"] = products(m.products_com);
  j["products_of_inertia_origin"] = products(m.products_origin);
  j["principal_degenerate"] = m.principal.degenerate;
  if (solid) {
    const auto& q = m.principal_motor;
    j["principal_motor"] = Json{{"1", q.s},     {"e01", q.e01}, {"e02", q.e02}, {"e03", q.e03},
                                {"e12", q.e12}, {"e31", q.e31}, {"e23", q.e23}, {"e0123", q.e0123}};
  } else {
    j["principal_motor"] = nullptr;
  }
  j["principal_motor_convention"] =
      "M = T R: M o ~M = centre of mass, M e_i ~M = principal axis i (directions); ~M takes the "
      "body into its principal frame";
  j["convention"] = inertia_convention;
  j["reference_point"] = json_vec3(m.reference_point);
  j["carrier_sum"] = json_plane(m.carrier_sum);
  if (r.topology) {
    const TopologyReport& t = *r.topology;
    j["topology"] = Json{{"edges", t.edges},
                         {"merged_vertices", t.merged_vertices},
                         {"inconsistent_edges", t.inconsistent_edges},
                         {"boundary_loop_count", t.boundary_loops.size()},
                         {"duplicated_faces", t.duplicated_faces},
                         {"zero_area_faces", t.zero_area_faces},
                         {"components", t.components},
                         {"closed_components", t.closed_components},
                         {"volume_range", json_range(t.volume_min, t.volume_max)}};
    j["topology"]["self_intersecting_pairs"] =
        t.self_intersections_checked ? Json(t.self_intersecting_pairs) : Json(nullptr);
  } else {
    j["topology"] = nullptr;
  }
  j["volume_valid"] = r.volume_valid ? Json(*r.volume_valid) : Json(nullptr);
  j["reasons"] = json_strings(r.reasons);
  j["warnings"] = json_strings(r.warnings);
  Json parts = Json::array();
  for (const PartAnalysis& p : r.parts) parts.push_back(part_json(p));
  j["parts"] = std::move(parts);
  return json_text(j);
}

}  // namespace pgamesh::cli
