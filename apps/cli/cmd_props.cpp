// `pgamesh props FILE [options]`: mass properties with the topology summary (DESIGN.md §5).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "commands.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "props_report.hpp"

namespace pgamesh::cli {

namespace {

const char* const props_usage =
    "usage: pgamesh props FILE [options]\n"
    "\n"
    "Area, signed volume, mass, centre of mass, inertia (about the centre of mass and the\n"
    "origin), products of inertia, principal moments and axes, gap area, and the topology\n"
    "summary (closed, boundary and non-manifold edges, orientation) of a mesh file\n"
    "(STL ASCII/binary, OBJ, PLY, OFF). FILE \"-\" reads standard input.\n"
    "\n"
    "options:\n"
    "  --density RHO        mass per unit volume (default 1: mass = volume)\n"
    "  --mass M             total mass instead; the density is M / volume\n"
    "  --json               one JSON object on stdout (numbers %.17g)\n"
    "  --urdf               print the URDF <inertial> element\n"
    "  --mjcf               print the MJCF <inertial> element\n"
    "  --about-origin       also print the inertia tensor about the coordinate origin\n"
    "  --no-topology, --fast  skip the weld/edge pass (STL, binary or ASCII, is then streamed\n"
    "                       from the mapped file without building a mesh; a PLY's faces\n"
    "                       are summed as they are read, only its vertices kept)\n"
    "  --weld-tolerance T   weld vertices closer than T for the topology (default 0: exact)\n"
    "  --format F           force the reader: stl, obj, ply, off (default: from the content)\n"
    "  --threads N          threads for the accumulation (default: all; results do not\n"
    "                       depend on it)\n"
    "  --degeneracy-tolerance T  principal moments closer than T relative count as equal\n"
    "                       (default 1e-7)\n"
    "\n"
    "Convention: the inertia tensor's off-diagonal entries are MINUS the products of inertia\n"
    "(I_xy = -integral x y dm); principal moments ascending with right-handed unit axes.\n"
    "Exit status: 0 on success (also for open meshes: the report says so), 1 for unreadable\n"
    "input, 2 for bad usage.\n";

bool parse_number(const char* s, double& out) {
  char* end = nullptr;
  out = std::strtod(s, &end);
  return end != s && *end == '\0' && std::isfinite(out);
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "pgamesh props: %s\n(pgamesh props --help for the options)\n",
               message.c_str());
  return 2;
}

int run_props(int argc, char** argv) {
  AnalysisOptions options;
  std::string file;
  bool json = false, urdf = false, mjcf = false, about_origin = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&](double& out) {
      if (i + 1 >= argc) return false;
      return parse_number(argv[++i], out);
    };
    double v = 0;
    if (a == "--help" || a == "-h") {
      std::fputs(props_usage, stdout);
      return 0;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--urdf") {
      urdf = true;
    } else if (a == "--mjcf") {
      mjcf = true;
    } else if (a == "--about-origin") {
      about_origin = true;
    } else if (a == "--no-topology" || a == "--fast") {
      options.topology = false;
    } else if (a == "--density") {
      if (!value(v)) return usage_error("--density needs a finite number");
      options.mass.density = v;
    } else if (a == "--mass") {
      if (!value(v)) return usage_error("--mass needs a finite number");
      options.mass.mass = v;
    } else if (a == "--weld-tolerance") {
      if (!value(v) || v < 0) return usage_error("--weld-tolerance needs a number >= 0");
      options.topology_options.weld_tolerance = v;
    } else if (a == "--degeneracy-tolerance") {
      if (!value(v) || v < 0) return usage_error("--degeneracy-tolerance needs a number >= 0");
      options.mass.degeneracy_tolerance = v;
    } else if (a == "--threads") {
      if (!value(v) || v < 1 || v > 1024 || v != std::floor(v))
        return usage_error("--threads needs a whole number from 1 to 1024");
      options.mass.threads = static_cast<unsigned>(v);
    } else if (a == "--format") {
      if (i + 1 >= argc) return usage_error("--format needs a format name");
      const std::string name = argv[++i];
      if (name != "auto") {
        options.format = format_from_name(name);
        if (options.format == MeshFormat::unknown)
          return usage_error("unknown format '" + name + "'");
      }
    } else if (a.size() > 1 && a[0] == '-' && a != "-") {
      return usage_error("unknown option '" + a + "'");
    } else if (file.empty()) {
      file = a;
    } else {
      return usage_error("more than one FILE ('" + file + "', '" + a + "')");
    }
  }
  if (file.empty()) return usage_error("no FILE given");
  if (options.mass.density && options.mass.mass)
    return usage_error("give --density or --mass, not both");
  if (json + urdf + mjcf > 1) return usage_error("choose one of --json, --urdf, --mjcf");

  Analysis report;
  try {
    report = analyze_file(file, options);
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh props: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh props: %s: %s\n", file.c_str(), e.what());
    return 1;
  }
  if (json) {
    std::printf("%s\n", props_json(report).c_str());
  } else if (urdf || mjcf) {
    std::fputs((urdf ? props_urdf(report) : props_mjcf(report)).c_str(), stdout);
    for (const auto& w : report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (report.volume_valid.has_value() && !*report.volume_valid)
      for (const auto& r : report.reasons)
        std::fprintf(stderr, "pgamesh props: not meaningful: %s\n", r.c_str());
  } else {
    std::fputs(props_text(report, about_origin).c_str(), stdout);
  }
  return 0;
}

const RegisterCommand registered{
    {"props",
     "mass properties: volume, mass, centre of mass, inertia, principal axes (+ URDF/MJCF)",
     run_props, 10}};

}  // namespace

}  // namespace pgamesh::cli
