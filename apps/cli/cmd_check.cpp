// `pgamesh check FILE [--json] [--weld-tolerance T] [--area-threshold R] [--max-list N]
// [--no-self-intersections] [--fix-orientation] [--output OUT]]`: the topology of a mesh
// (docs/topology.md). The report is the result, so an open or broken mesh still exits 0; unreadable
// input exits 1 with the reader's error.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "check_json.hpp"
#include "commands.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"
#include "text_append.hpp"

namespace pgamesh::cli {

namespace {

const char* yes_no(bool b) {
  return b ? "yes" : "no";
}

void print_vec(std::string& out, Vec3d v) {
  append(out, "(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
}

// The readable report, built whole before anything is printed.
std::string readable_report(const Mesh& mesh, const MeshSource& source, const Analysis& analysis,
                            const OrientationFix* fix, std::size_t cap) {
  std::string out;
  const TopologyReport& r = *analysis.topology;
  append(out, "%s (%s, %s)\n", source.path.c_str(), format_name(source.format),
         unit_name(analysis.unit));
  append(out, "  faces               %zu (%zu triangles)\n", r.faces, r.triangles);
  append(out, "  vertices            %zu welded from %zu (%zu merged", r.vertices, r.input_vertices,
         r.merged_vertices);
  if (r.weld_tolerance > 0)
    append(out, ", tolerance %.6g, moved at most %.6g", r.weld_tolerance, r.weld_max_moved);
  append(out, ")\n");
  append(out, "  edges               %zu: %zu boundary, %zu non-manifold, %zu inconsistent\n",
         r.edges, r.boundary_edges, r.nonmanifold_edges, r.inconsistent_edges);
  append(out, "  closed              %s\n", yes_no(r.closed));
  append(out, "  orientation         %s\n",
         r.orientation_consistent ? "consistent" : "INCONSISTENT");
  append(out, "  area                %.17g\n", r.area);
  append(out, "  volume              %.17g%s\n", r.volume,
         analysis.volume_valid.value_or(false) ? "" : "   (NOT MEANINGFUL: see notes)");
  append(out, "  gap area            %.17g\n", r.gap_area);
  if (r.boundary_edges > 0) {
    append(out, "  volume if capped    %.17g .. %.17g (ambiguity %.6g)\n", r.volume_min,
           r.volume_max, r.volume_ambiguity());
    append(out, "  boundary loops      %zu, total area %.17g\n", r.boundary_loops.size(),
           r.loops_area);
    for (std::size_t i = 0; i < r.boundary_loops.size() && i < cap; ++i) {
      const BoundaryLoop& l = r.boundary_loops[i];
      append(out, "    loop %zu: %zu edges%s, perimeter %.9g, area %.9g, vector area ", i + 1,
             l.half_edges.size(), l.closed ? "" : " (open chain)", l.perimeter, l.area);
      print_vec(out, l.vector_area);
      append(out, ", from ");
      print_vec(out, mesh.vertices[mesh.corners[l.half_edges.front()]]);
      append(out, "\n");
    }
    if (r.boundary_loops.size() > cap) append(out, "    ...\n");
  }
  auto edges = [&](const char* what, const std::vector<EdgeLocation>& list, std::size_t count) {
    if (count == 0) return;
    append(out, "  %s edges (%zu):\n", what, count);
    for (const EdgeLocation& e : list) {
      append(out, "    face %u, vertices %u-%u ", e.face, e.vertex0, e.vertex1);
      print_vec(out, e.p0);
      append(out, " - ");
      print_vec(out, e.p1);
      append(out, ", %u faces\n", e.face_count);
    }
    if (count > list.size()) append(out, "    ...\n");
  };
  edges("non-manifold", r.nonmanifold_edge_list, r.nonmanifold_edges);
  edges("inconsistent", r.inconsistent_edge_list, r.inconsistent_edges);
  auto faces = [&](const char* what, const std::vector<FaceLocation>& list, std::size_t count) {
    if (count == 0) return;
    append(out, "  %s faces (%zu):\n", what, count);
    for (const FaceLocation& f : list) {
      append(out, "    face %u", f.face);
      if (f.same_as != no_edge) append(out, " = face %u", f.same_as);
      append(out, " at ");
      print_vec(out, f.centroid);
      append(out, ", area %.6g\n", f.area);
    }
    if (count > list.size()) append(out, "    ...\n");
  };
  faces("zero-area", r.zero_area_list, r.zero_area_faces);
  faces("nearly zero-area", r.small_area_list, r.small_area_faces);
  faces("duplicated", r.duplicated_list, r.duplicated_faces);
  if (r.self_intersections_checked) {
    append(out, "  self-intersections  %s%zu face pairs\n",
           r.self_intersections_complete ? "" : "at least ", r.self_intersecting_pairs);
    for (const SelfIntersection& s : r.self_intersection_list) {
      append(out, "    faces %u and %u near ", s.face0, s.face1);
      print_vec(out, s.point);
      append(out, "\n");
    }
    if (r.self_intersecting_pairs > r.self_intersection_list.size()) append(out, "    ...\n");
  }
  append(out, "  components          %zu (%zu closed", r.components, r.closed_components);
  if (r.cavity_components)
    append(out, ", %zu %s", r.cavity_components, r.cavity_components == 1 ? "cavity" : "cavities");
  if (r.inward_components) append(out, ", %zu inward", r.inward_components);
  append(out, ")\n");
  if (r.components > 1)
    for (const ComponentSummary& c : r.component_list)
      append(out, "    from face %u: %zu faces, area %.9g, volume %.9g%s%s%s\n", c.first_face,
             c.faces, c.area, c.volume, c.closed ? "" : " (not closed)",
             c.cavity ? " (cavity)" : "", c.inward ? " (wrong way)" : "");
  if (fix) {
    append(out, "  orientation fix     %zu faces flipped", fix->flipped);
    if (fix->conflicts) append(out, ", %zu edges could not be made consistent", fix->conflicts);
    append(out, "\n");
    for (const ComponentOrientation& c : fix->components) {
      append(out, "    component from face %u: %zu of %zu flipped%s:", c.first_face, c.flipped,
             c.faces,
             !c.closed ? "" : (c.depth % 2 == 1 ? ", now a cavity facing in" : ", now outward"));
      for (std::uint32_t f : c.flipped_faces) append(out, " %u", f);
      if (c.flipped > c.flipped_faces.size()) append(out, " ...");
      append(out, "\n");
    }
  }
  // The topology's notes, then the reasons the volume is not valid that they do not already give.
  std::vector<std::string> notes = r.notes;
  for (const auto& reason : analysis.reasons)
    if (std::find(notes.begin(), notes.end(), reason) == notes.end()) notes.push_back(reason);
  if (!notes.empty()) {
    append(out, "notes:\n");
    for (const auto& n : notes) append(out, "  - %s\n", n.c_str());
  }
  for (const auto& w : analysis.warnings) append(out, "warning: %s\n", w.c_str());
  return out;
}

struct CheckOptions {
  std::string path, output;
  bool json = false, fix = false;
  TopologyOptions topology;
  unsigned long long list_cap = TopologyOptions{}.list_cap;
  MeshFormat forced = MeshFormat::unknown;
  LengthUnit unit = LengthUnit::unspecified;  // --unit: of a file that states none
};

int run_check(const CheckOptions& o) {
  TopologyOptions options = o.topology;
  options.list_cap = static_cast<std::size_t>(o.list_cap);
  const std::string& path = o.path;
  const std::string& output = o.output;
  const bool fix = o.fix, json = o.json;

  try {
    MeshSource source;
    Mesh mesh = read_mesh(path, &source, o.forced);
    OrientationFix repair;
    if (fix) {
      OrientationOptions fix_options;
      fix_options.weld_tolerance = options.weld_tolerance;
      fix_options.list_cap = options.list_cap;
      repair = fix_orientation(mesh, fix_options);
    }
    // The topology report with the mass properties' judgement of it (volume_valid, reasons,
    // warnings: the same as `pgamesh props`).
    AnalysisOptions analysis_options;
    analysis_options.topology_options = options;
    analysis_options.unit = o.unit;
    const Analysis analysis = analyze_mesh(mesh, source, analysis_options);
    const MeshFormat output_format =
        output.empty() ? MeshFormat::unknown : format_for_extension(output, source.format);
    if (!output.empty()) {
      if (output_format == MeshFormat::unknown) {
        std::fprintf(stderr,
                     "pgamesh check: cannot tell the format of '%s' (use .stl, .obj, .ply, "
                     ".off, .gltf, .glb or .slp)\n",
                     output.c_str());
        return 2;
      }
    }
    // The report is built before the repaired mesh is written (atomically, write_mesh), and
    // printed after: a failure at any step leaves stdout empty.
    std::string out;
    if (json) {
      CheckJsonOptions jo;
      jo.list_cap = options.list_cap;
      jo.loop_point_cap = options.list_cap;
      out = check_json(mesh, source, analysis, fix ? &repair : nullptr, jo);
    } else {
      out = readable_report(mesh, source, analysis, fix ? &repair : nullptr, options.list_cap);
      if (!output.empty()) append(out, "wrote %s\n", output.c_str());
    }
    // What was analysed: the mesh welded as the report saw it (and reoriented by
    // --fix-orientation).
    if (!output.empty()) write_mesh(weld(mesh, options.weld_tolerance).mesh, output, output_format);
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh check: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh check: %s: %s\n", path.c_str(), e.what());
    return 1;
  }
}

}  // namespace

void add_check_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "check", "topology: weld, boundary loops and gap, orientation, defects, components",
      "Topology of a mesh: welds coincident vertices, then reports boundary edges and loops\n"
      "(each with its vector area, area and perimeter), the gap 1/2|sum F| and the range of\n"
      "volumes that closing the holes could give, non-manifold and inconsistently oriented\n"
      "edges, zero-area and duplicated faces, intersecting faces, connected components, and\n"
      "whether volume, centre of mass and inertia are meaningful.");
  sub->footer(
      "Exit status: 0 whatever the mesh is like; 1 when the file cannot be read; 2 for bad\n"
      "options.");
  auto o = std::make_shared<CheckOptions>();
  add_file(*sub, o->path, "the mesh file; \"-\" reads standard input");
  sub->add_flag("--json", o->json, "one JSON object on stdout (fields: docs/json.md)");
  add_number(*sub, "--weld-tolerance", o->topology.weld_tolerance,
             "also merge vertices closer than T (default 0: bitwise-equal\n"
             "coordinates only); reports how many merged and how far",
             0.0)
      ->type_name("T");
  add_number(*sub, "--area-threshold", o->topology.area_threshold,
             "faces with area <= R x (longest side)^2 are reported as nearly\n"
             "zero-area (default 1e-9)",
             0.0)
      ->type_name("R");
  add_count(*sub, "--max-list", o->list_cap,
            "locations listed per list (default 20; counts are complete)", 0,
            std::numeric_limits<std::size_t>::max());
  sub->add_flag_callback(
      "--no-self-intersections", [o] { o->topology.self_intersections = false; },
      "do not look for intersecting faces (the longest step of the\n"
      "topology on large meshes): the volume is judged without it");
  sub->add_flag("--fix-orientation", o->fix,
                "reverse faces to agree with their neighbours and turn closed\n"
                "parts outward; reports the faces flipped, then the repaired mesh");
  sub->add_option("-o,--output", o->output,
                  "write the mesh as analysed: welded (within --weld-tolerance),\n"
                  "and reoriented with --fix-orientation (format from OUT's\n"
                  "extension: .stl .obj .ply .off .3mf .gltf .glb .slp)")
      ->type_name("OUT");
  add_format(*sub, o->forced);
  add_unit(*sub, o->unit,
           "the unit of a file that states none: mm, cm, m, in, ft, um\n"
           "(named in the output; a file's own unit differing from U is an error)");
  on_run(*sub, [o] { return run_check(*o); });
}

}  // namespace pgamesh::cli
