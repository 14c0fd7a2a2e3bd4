#include "check_json.hpp"

#include <algorithm>

#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh::cli {

namespace {

void edge_list(JsonWriter& j, std::string_view key, const std::vector<EdgeLocation>& list,
               std::size_t cap) {
  j.begin_array(key);
  for (std::size_t i = 0; i < list.size() && i < cap; ++i) {
    const EdgeLocation& e = list[i];
    j.begin_object();
    j.integer("face", e.face);
    j.begin_array("vertices").integer({}, e.vertex0).integer({}, e.vertex1).end_array();
    j.begin_array("points");
    j.vec3(e.p0);
    j.vec3(e.p1);
    j.end_array();
    j.integer("faces", e.face_count);
    j.end_object();
  }
  j.end_array();
}

void face_list(JsonWriter& j, std::string_view key, const std::vector<FaceLocation>& list,
               std::size_t cap) {
  j.begin_array(key);
  for (std::size_t i = 0; i < list.size() && i < cap; ++i) {
    const FaceLocation& f = list[i];
    j.begin_object();
    j.integer("face", f.face);
    if (f.same_as != no_edge) j.integer("same_as", f.same_as);
    j.vec3("centroid", f.centroid);
    j.number("area", f.area);
    j.end_object();
  }
  j.end_array();
}

}  // namespace

void write_check_fields(JsonWriter& j, const Mesh& mesh, const MeshSource& source,
                        const TopologyReport& r, const OrientationFix* fix,
                        const CheckJsonOptions& options) {
  const std::size_t cap = options.list_cap;
  j.string("file", source.path);
  j.string("format", format_name(source.format));
  // The summary fields shared with `pgamesh props`.
  j.integer("triangles", r.triangles);
  j.integer("faces", r.faces);
  j.integer("vertices", r.vertices);
  j.number("area", r.area);
  j.number("volume", r.volume);
  j.boolean("volume_valid", r.volume_valid);
  j.number("gap_area", r.gap_area);
  j.boolean("closed", r.closed);
  j.integer("boundary_edges", r.boundary_edges);
  j.integer("nonmanifold_edges", r.nonmanifold_edges);
  j.boolean("orientation_consistent", r.orientation_consistent);
  j.plane("carrier_sum", r.carrier_sum);
  // Weld and edges.
  j.begin_object("weld")
      .integer("input_vertices", r.input_vertices)
      .integer("merged_vertices", r.merged_vertices)
      .number("tolerance", r.weld_tolerance)
      .number("max_moved", r.weld_max_moved)
      .integer("unreferenced_vertices", r.unreferenced_vertices)
      .end_object();
  j.integer("edges", r.edges);
  j.integer("inconsistent_edges", r.inconsistent_edges);
  j.vec3("reference_point", r.reference_point);
  // The gap and what it leaves open.
  j.vec3("gap_vector", r.gap_vector);
  j.begin_array("volume_range").number(r.volume_min).number(r.volume_max).end_array();
  j.number("volume_ambiguity", r.volume_ambiguity());
  j.integer("boundary_loop_count", r.boundary_loops.size());
  j.number("boundary_loops_area", r.loops_area);
  j.begin_array("boundary_loops");
  for (std::size_t i = 0; i < r.boundary_loops.size() && i < cap; ++i) {
    const BoundaryLoop& loop = r.boundary_loops[i];
    j.begin_object();
    j.integer("edges", loop.half_edges.size());
    j.boolean("closed", loop.closed);
    j.vec3("vector_area", loop.vector_area);
    j.number("area", loop.area);
    j.number("perimeter", loop.perimeter);
    j.begin_array("points");
    for (std::size_t k = 0; k < loop.half_edges.size() && k < options.loop_point_cap; ++k)
      j.vec3(mesh.vertices[mesh.corners[loop.half_edges[k]]]);
    j.end_array();
    j.end_object();
  }
  j.end_array();
  edge_list(j, "boundary_edge_list", r.boundary_edge_list, cap);
  edge_list(j, "nonmanifold_edge_list", r.nonmanifold_edge_list, cap);
  edge_list(j, "inconsistent_edge_list", r.inconsistent_edge_list, cap);
  // Faces.
  j.begin_object("degenerate_faces")
      .integer("zero_area", r.zero_area_faces)
      .integer("collapsed", r.collapsed_faces)
      .integer("small_area", r.small_area_faces)
      .number("area_threshold", r.area_threshold);
  face_list(j, "zero_area_list", r.zero_area_list, cap);
  face_list(j, "small_area_list", r.small_area_list, cap);
  j.end_object();
  j.integer("duplicated_faces", r.duplicated_faces);
  face_list(j, "duplicated_face_list", r.duplicated_list, cap);
  // Components.
  j.integer("components", r.components);
  j.integer("closed_components", r.closed_components);
  j.integer("negative_components", r.negative_components);
  j.begin_array("component_list");
  for (std::size_t i = 0; i < r.component_list.size() && i < cap; ++i) {
    const ComponentSummary& c = r.component_list[i];
    j.begin_object()
        .integer("first_face", c.first_face)
        .integer("faces", c.faces)
        .number("area", c.area)
        .number("volume", c.volume)
        .boolean("closed", c.closed)
        .integer("boundary_edges", c.boundary_edges)
        .integer("nonmanifold_edges", c.nonmanifold_edges)
        .integer("inconsistent_edges", c.inconsistent_edges)
        .end_object();
  }
  j.end_array();
  if (fix) {
    j.begin_object("orientation_fix");
    j.integer("flipped_faces", fix->flipped);
    j.integer("conflicts", fix->conflicts);
    j.begin_array("components");
    for (std::size_t i = 0; i < fix->components.size() && i < cap; ++i) {
      const ComponentOrientation& c = fix->components[i];
      j.begin_object()
          .integer("component", c.component)
          .integer("first_face", c.first_face)
          .integer("faces", c.faces)
          .integer("flipped", c.flipped)
          .boolean("closed", c.closed)
          .number("volume", c.volume)
          .integer("conflicts", c.conflicts);
      j.begin_array("flipped_faces");
      for (std::size_t k = 0; k < c.flipped_faces.size() && k < cap; ++k)
        j.integer({}, c.flipped_faces[k]);
      j.end_array().end_object();
    }
    j.end_array().end_object();
  }
  j.integer("list_cap", cap);
  j.strings("notes", r.notes);
  j.strings("warnings", source.warnings);
}

std::string check_json(const Mesh& mesh, const MeshSource& source, const TopologyReport& report,
                       const OrientationFix* fix, const CheckJsonOptions& options) {
  JsonWriter j;
  j.begin_object();
  write_check_fields(j, mesh, source, report, fix, options);
  j.end_object();
  return j.str() + "\n";
}

}  // namespace pgamesh::cli
