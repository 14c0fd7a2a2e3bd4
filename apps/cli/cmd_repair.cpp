// `pgamesh repair FILE --output OUT [--weld-tolerance T] [--planarity R] [--force] [--no-caps]
// [--json]`: weld, remove the faces that bound nothing, cap the holes, orient by nesting
// (mesh/repair/repair.hpp, docs/topology.md "Repair"), write the result atomically and report
// every change and whether the result is a solid.
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <string>

#include "commands.hpp"
#include "json_text.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/repair/repair.hpp"
#include "repair_json.hpp"
#include "text_append.hpp"

namespace pgamesh::cli {

namespace {

struct RepairCliOptions {
  std::string path, output;
  bool json = false;
  RepairOptions repair;
  bool no_caps = false, keep_duplicates = false;
  unsigned long long list_cap = RepairOptions{}.list_cap;
  MeshFormat forced = MeshFormat::unknown;
};

void append_faces(std::string& out, const std::vector<std::uint32_t>& faces, std::size_t count) {
  if (faces.empty()) return;
  append(out, " (faces");
  for (std::uint32_t f : faces) append(out, " %u", f);
  append(out, "%s)", count > faces.size() ? " ..." : "");
}

std::string readable_report(const RepairCliOptions& o, const MeshSource& source,
                            const RepairReport& r, const Analysis& result) {
  std::string out;
  append(out, "%s (%s)\n", source.path.c_str(), format_name(source.format));
  append(out, "weld            %zu vertices -> %zu (%zu merged", r.input_vertices,
         r.input_vertices - r.merged_vertices, r.merged_vertices);
  if (r.weld_tolerance > 0)
    append(out, ", tolerance %.6g, moved at most %.6g", r.weld_tolerance, r.weld_max_moved);
  append(out, ")\n");
  const std::size_t removed = r.collapsed_faces + r.duplicate_faces + 2 * r.opposite_pairs;
  append(out, "removed faces   %zu: %zu collapsed, %zu duplicated, %zu double-wall pairs", removed,
         r.collapsed_faces, r.duplicate_faces, r.opposite_pairs);
  append_faces(out, r.removed_faces, removed);
  append(out, "\n");
  if (r.repeated_corners > 0)
    append(out, "merged corners  %zu (consecutive corners on one vertex)\n", r.repeated_corners);
  append(out, "reversed faces  %zu", r.reversed_faces);
  append_faces(out, r.reversed_list, r.reversed_faces);
  append(out, "\n");
  if (r.orientation_conflicts > 0)
    append(out, "not orientable  %zu edges (a one-sided surface)\n", r.orientation_conflicts);
  append(out, "holes           %zu: %zu capped with %zu triangles, %zu refused\n", r.holes.size(),
         r.holes_capped, r.cap_triangles, r.holes_refused);
  for (std::size_t i = 0; i < r.holes.size() && i < o.repair.list_cap; ++i) {
    const CappedHole& h = r.holes[i];
    append(out,
           "  hole %zu: %zu vertices from (%.9g, %.9g, %.9g), area %.9g, off its plane by %.3g: ",
           i + 1, h.rim_vertices, h.first_vertex.x, h.first_vertex.y, h.first_vertex.z, h.area,
           h.max_deviation);
    if (h.refused.empty())
      append(out, "capped (%zu triangles)\n", h.triangles);
    else
      append(out, "not capped: %s\n", h.refused.c_str());
  }
  if (r.unreferenced_vertices > 0)
    append(out, "unused vertices %zu dropped\n", r.unreferenced_vertices);
  const TopologyReport& t = *result.topology;
  append(out, "result          %zu vertices, %zu faces, %s", r.output_vertices, r.output_faces,
         t.closed ? "closed" : "open");
  if (result.volume_valid.value_or(false))
    append(out, ", a solid of volume %.17g\n", result.mass.volume);
  else
    append(out, ", not a solid\n");
  for (const auto& reason : result.reasons) append(out, "  - %s\n", reason.c_str());
  for (const auto& w : result.warnings) append(out, "warning: %s\n", w.c_str());
  append(out, "wrote %s\n", o.output.c_str());
  return out;
}

std::string json_report(const RepairCliOptions& o, const MeshSource& source, const RepairReport& r,
                        const Analysis& result) {
  return json_text(repair_fields(source, r, result, o.repair.list_cap, o.output)) + "\n";
}

int run_repair(RepairCliOptions o) {
  o.repair.list_cap = static_cast<std::size_t>(o.list_cap);
  o.repair.cap_holes = !o.no_caps;
  o.repair.remove_duplicate_faces = !o.keep_duplicates;
  try {
    MeshSource source;
    Mesh mesh = read_mesh(o.path, &source, o.forced);
    const MeshFormat output_format = format_for_extension(o.output, source.format);
    if (output_format == MeshFormat::unknown)
      throw UsageError("cannot tell the format of '" + o.output +
                       "' from its extension (.stl, .obj, .ply, .off)");
    const RepairReport report = repair(mesh, o.repair);
    AnalysisOptions analysis_options;
    analysis_options.topology_options.list_cap = 0;
    const Analysis result = analyze_mesh(mesh, source, analysis_options);
    // The report is built before the mesh is written (atomically) and printed after: a failure at
    // any step leaves stdout empty and the old OUT in place.
    const std::string out = o.json ? json_report(o, source, report, result)
                                   : readable_report(o, source, report, result);
    write_mesh(mesh, o.output, output_format);
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh repair: %s\n", e.what());
    return 1;
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh repair: %s: %s\n", o.path.c_str(), e.what());
    return 1;
  }
}

}  // namespace

void add_repair_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "repair", "weld, remove duplicate and collapsed faces, cap holes, orient by nesting",
      "Repairs a mesh into a solid and writes it: welds vertices (exactly, or within\n"
      "--weld-tolerance), merges repeated corners and removes faces that collapse, later copies\n"
      "of a face and both faces of a double wall, caps each hole in its best-fit plane (holes\n"
      "that are not planar within --planarity are left open unless --force; a rim that crosses\n"
      "itself never gets a cap), and orients every closed shell by its nesting (outer skins\n"
      "out, cavities in). Every change is reported, and whether the result is a solid.");
  sub->footer(
      "Exit status: 0 when the repaired mesh was written (the report says whether it is a\n"
      "solid); 1 when the file cannot be read or OUT cannot be written; 2 for bad options.");
  auto o = std::make_shared<RepairCliOptions>();
  add_file(*sub, o->path, "the mesh file; \"-\" reads standard input");
  sub->add_option("-o,--output", o->output,
                  "where to write the repaired mesh (format from OUT's extension:\n"
                  ".stl .obj .ply .off)")
      ->type_name("OUT")
      ->required();
  sub->add_flag("--json", o->json, "one JSON object on stdout (fields: docs/json.md)");
  add_number(*sub, "--weld-tolerance", o->repair.weld_tolerance,
             "also merge vertices closer than T (default 0: bitwise-equal\n"
             "coordinates only)",
             0.0)
      ->type_name("T");
  add_number(*sub, "--planarity", o->repair.hole.planarity,
             "cap a hole when its rim lies within R x (its size) of its\n"
             "best-fit plane (default 1e-6)",
             0.0)
      ->type_name("R");
  sub->add_flag("--force", o->repair.hole.force, "cap holes that are not planar too");
  sub->add_flag("--no-caps", o->no_caps, "leave holes open");
  sub->add_flag("--keep-duplicates", o->keep_duplicates, "keep duplicated faces and double walls");
  add_count(*sub, "--max-list", o->list_cap,
            "faces and holes listed (default 20; counts are complete)", 0,
            std::numeric_limits<std::size_t>::max());
  add_format(*sub, o->forced);
  on_run(*sub, [o] { return run_repair(*o); });
}

}  // namespace pgamesh::cli
