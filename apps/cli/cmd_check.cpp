// `pgamesh check FILE [--json] [--weld-tolerance T] [--area-threshold R] [--max-list N]
// [--fix-orientation [--output OUT]]`: the topology of a mesh (docs/topology.md). The report is the
// result, so an open or broken mesh still exits 0; unreadable input exits 1 with the reader's
// error.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
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

namespace pgamesh::cli {

namespace {

void print_check_help(std::FILE* out) {
  std::fprintf(
      out,
      "usage: pgamesh check FILE [options]\n"
      "\n"
      "Topology of a mesh: welds coincident vertices, then reports boundary edges and loops\n"
      "(each with its vector area, area and perimeter), the gap 1/2|sum F| and the range of\n"
      "volumes that closing the holes could give, non-manifold and inconsistently oriented\n"
      "edges, zero-area and duplicated faces, connected components, and whether volume,\n"
      "centre of mass and inertia are meaningful. Exit code 0 whatever the mesh is like;\n"
      "1 when the file cannot be read; 2 for bad options.\n"
      "\n"
      "options:\n"
      "  --json                 one JSON object on stdout (fields: docs/topology.md)\n"
      "  --weld-tolerance T     also merge vertices closer than T (default 0: bitwise-equal\n"
      "                         coordinates only); reports how many merged and how far\n"
      "  --area-threshold R     faces with area <= R x (longest side)^2 are reported as nearly\n"
      "                         zero-area (default 1e-9)\n"
      "  --max-list N           locations listed per list (default 20; counts are complete)\n"
      "  --fix-orientation      reverse faces to agree with their neighbours and turn closed\n"
      "                         parts outward; reports the faces flipped, then the repaired mesh\n"
      "  --output OUT           with --fix-orientation: write the repaired mesh (format from\n"
      "                         OUT's extension: .stl .obj .ply .off)\n"
      "  --format F             read FILE as F (stl, obj, ply, off; default: detect)\n");
}

bool parse_double(std::string_view text, double& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

bool parse_count(std::string_view text, std::size_t& out) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

bool ends_with_ci(std::string_view s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    char c = s[s.size() - suffix.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != suffix[i]) return false;
  }
  return true;
}

// The format to write OUT in: the input's own encoding when OUT has the same family, else the
// binary (or only) encoding of the extension's family.
MeshFormat output_format(std::string_view path, MeshFormat input) {
  auto same_family = [&](MeshFormat a, MeshFormat b) { return a == input || b == input; };
  if (ends_with_ci(path, ".stl"))
    return same_family(MeshFormat::stl_ascii, MeshFormat::stl_binary) ? input
                                                                      : MeshFormat::stl_binary;
  if (ends_with_ci(path, ".ply")) {
    if (input == MeshFormat::ply_ascii || input == MeshFormat::ply_binary_le ||
        input == MeshFormat::ply_binary_be)
      return input;
    return MeshFormat::ply_binary_le;
  }
  if (ends_with_ci(path, ".obj")) return MeshFormat::obj;
  if (ends_with_ci(path, ".off")) return MeshFormat::off;
  return MeshFormat::unknown;
}

const char* yes_no(bool b) {
  return b ? "yes" : "no";
}

void print_vec(Vec3d v) {
  std::printf("(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
}

void print_readable(const Mesh& mesh, const MeshSource& source, const TopologyReport& r,
                    const OrientationFix* fix, std::size_t cap) {
  std::printf("%s (%s)\n", source.path.c_str(), format_name(source.format));
  std::printf("  faces               %zu (%zu triangles)\n", r.faces, r.triangles);
  std::printf("  vertices            %zu welded from %zu (%zu merged", r.vertices, r.input_vertices,
              r.merged_vertices);
  if (r.weld_tolerance > 0)
    std::printf(", tolerance %.6g, moved at most %.6g", r.weld_tolerance, r.weld_max_moved);
  std::printf(")\n");
  std::printf("  edges               %zu: %zu boundary, %zu non-manifold, %zu inconsistent\n",
              r.edges, r.boundary_edges, r.nonmanifold_edges, r.inconsistent_edges);
  std::printf("  closed              %s\n", yes_no(r.closed));
  std::printf("  orientation         %s\n",
              r.orientation_consistent ? "consistent" : "INCONSISTENT");
  std::printf("  area                %.17g\n", r.area);
  std::printf("  volume              %.17g%s\n", r.volume,
              r.volume_valid ? "" : "   (NOT MEANINGFUL: see notes)");
  std::printf("  gap area            %.17g\n", r.gap_area);
  if (r.boundary_edges > 0) {
    std::printf("  volume if capped    %.17g .. %.17g (ambiguity %.6g)\n", r.volume_min,
                r.volume_max, r.volume_ambiguity());
    std::printf("  boundary loops      %zu, total area %.17g\n", r.boundary_loops.size(),
                r.loops_area);
    for (std::size_t i = 0; i < r.boundary_loops.size() && i < cap; ++i) {
      const BoundaryLoop& l = r.boundary_loops[i];
      std::printf("    loop %zu: %zu edges%s, perimeter %.9g, area %.9g, vector area ", i + 1,
                  l.half_edges.size(), l.closed ? "" : " (open chain)", l.perimeter, l.area);
      print_vec(l.vector_area);
      std::printf(", from ");
      print_vec(mesh.vertices[mesh.corners[l.half_edges.front()]]);
      std::printf("\n");
    }
    if (r.boundary_loops.size() > cap) std::printf("    ...\n");
  }
  auto edges = [&](const char* what, const std::vector<EdgeLocation>& list, std::size_t count) {
    if (count == 0) return;
    std::printf("  %s edges (%zu):\n", what, count);
    for (const EdgeLocation& e : list) {
      std::printf("    face %u, vertices %u-%u ", e.face, e.vertex0, e.vertex1);
      print_vec(e.p0);
      std::printf(" - ");
      print_vec(e.p1);
      std::printf(", %u faces\n", e.face_count);
    }
    if (count > list.size()) std::printf("    ...\n");
  };
  edges("non-manifold", r.nonmanifold_edge_list, r.nonmanifold_edges);
  edges("inconsistent", r.inconsistent_edge_list, r.inconsistent_edges);
  auto faces = [&](const char* what, const std::vector<FaceLocation>& list, std::size_t count) {
    if (count == 0) return;
    std::printf("  %s faces (%zu):\n", what, count);
    for (const FaceLocation& f : list) {
      std::printf("    face %u", f.face);
      if (f.same_as != no_edge) std::printf(" = face %u", f.same_as);
      std::printf(" at ");
      print_vec(f.centroid);
      std::printf(", area %.6g\n", f.area);
    }
    if (count > list.size()) std::printf("    ...\n");
  };
  faces("zero-area", r.zero_area_list, r.zero_area_faces);
  faces("nearly zero-area", r.small_area_list, r.small_area_faces);
  faces("duplicated", r.duplicated_list, r.duplicated_faces);
  std::printf("  components          %zu (%zu closed", r.components, r.closed_components);
  if (r.negative_components) std::printf(", %zu inward", r.negative_components);
  std::printf(")\n");
  if (r.components > 1)
    for (const ComponentSummary& c : r.component_list)
      std::printf("    from face %u: %zu faces, area %.9g, volume %.9g%s\n", c.first_face, c.faces,
                  c.area, c.volume, c.closed ? "" : " (not closed)");
  if (fix) {
    std::printf("  orientation fix     %zu faces flipped", fix->flipped);
    if (fix->conflicts) std::printf(", %zu edges could not be made consistent", fix->conflicts);
    std::printf("\n");
    for (const ComponentOrientation& c : fix->components) {
      std::printf("    component from face %u: %zu of %zu flipped%s:", c.first_face, c.flipped,
                  c.faces, c.closed ? ", now outward" : "");
      for (std::uint32_t f : c.flipped_faces) std::printf(" %u", f);
      if (c.flipped > c.flipped_faces.size()) std::printf(" ...");
      std::printf("\n");
    }
  }
  if (!r.notes.empty()) {
    std::printf("notes:\n");
    for (const auto& n : r.notes) std::printf("  - %s\n", n.c_str());
  }
  for (const auto& w : source.warnings) std::printf("warning: %s\n", w.c_str());
}

int run_check(int argc, char** argv) {
  std::string path, output;
  bool json = false, fix = false;
  TopologyOptions options;
  MeshFormat forced = MeshFormat::unknown;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "pgamesh check: %s needs a value\n", name);
        return nullptr;
      }
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h") {
      print_check_help(stdout);
      return 0;
    } else if (arg == "--json") {
      json = true;
    } else if (arg == "--fix-orientation") {
      fix = true;
    } else if (arg == "--weld-tolerance") {
      const char* v = value("--weld-tolerance");
      if (!v) return 2;
      if (!parse_double(v, options.weld_tolerance) || options.weld_tolerance < 0) {
        std::fprintf(stderr, "pgamesh check: --weld-tolerance needs a number >= 0, got '%s'\n", v);
        return 2;
      }
    } else if (arg == "--area-threshold") {
      const char* v = value("--area-threshold");
      if (!v) return 2;
      if (!parse_double(v, options.area_threshold) || options.area_threshold < 0) {
        std::fprintf(stderr, "pgamesh check: --area-threshold needs a number >= 0, got '%s'\n", v);
        return 2;
      }
    } else if (arg == "--max-list") {
      const char* v = value("--max-list");
      if (!v) return 2;
      if (!parse_count(v, options.list_cap)) {
        std::fprintf(stderr, "pgamesh check: --max-list needs a count, got '%s'\n", v);
        return 2;
      }
    } else if (arg == "--output" || arg == "-o") {
      const char* v = value("--output");
      if (!v) return 2;
      output = v;
    } else if (arg == "--format") {
      const char* v = value("--format");
      if (!v) return 2;
      forced = format_from_name(v);
      if (forced == MeshFormat::unknown && std::string_view(v) != "auto") {
        std::fprintf(stderr, "pgamesh check: unknown format '%s'\n", v);
        return 2;
      }
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      std::fprintf(stderr, "pgamesh check: unknown option '%s' (see pgamesh check --help)\n",
                   argv[i]);
      return 2;
    } else if (path.empty()) {
      path = arg;
    } else {
      std::fprintf(stderr, "pgamesh check: more than one FILE ('%s', '%s')\n", path.c_str(),
                   argv[i]);
      return 2;
    }
  }
  if (path.empty()) {
    print_check_help(stderr);
    return 2;
  }
  if (!output.empty() && !fix) {
    std::fprintf(stderr, "pgamesh check: --output writes the repaired mesh of --fix-orientation\n");
    return 2;
  }

  try {
    MeshSource source;
    Mesh mesh = read_mesh(path, &source, forced);
    OrientationFix repair;
    if (fix) {
      OrientationOptions o;
      o.weld_tolerance = options.weld_tolerance;
      o.list_cap = options.list_cap;
      repair = fix_orientation(mesh, o);
    }
    const TopologyReport report = analyze_topology(mesh, options);
    if (!output.empty()) {
      const MeshFormat format = output_format(output, source.format);
      if (format == MeshFormat::unknown) {
        std::fprintf(stderr,
                     "pgamesh check: cannot tell the format of '%s' (use .stl, .obj, .ply or "
                     ".off)\n",
                     output.c_str());
        return 2;
      }
      write_mesh(mesh, output, format);
    }
    if (json) {
      CheckJsonOptions jo;
      jo.list_cap = options.list_cap;
      jo.loop_point_cap = options.list_cap;
      const std::string doc = check_json(mesh, source, report, fix ? &repair : nullptr, jo);
      std::fwrite(doc.data(), 1, doc.size(), stdout);
    } else {
      print_readable(mesh, source, report, fix ? &repair : nullptr, options.list_cap);
      if (!output.empty()) std::printf("wrote %s\n", output.c_str());
    }
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh check: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh check: %s: %s\n", path.c_str(), e.what());
    return 1;
  }
}

const RegisterCommand registered{
    {"check", "topology: weld, boundary loops and gap, orientation, defects, components", run_check,
     20}};

}  // namespace

}  // namespace pgamesh::cli
