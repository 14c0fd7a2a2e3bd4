// `pgamesh props FILE [options]`: mass properties with the topology summary
// (docs/mass-properties.md).
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "commands.hpp"
#include "pgamesh/core/input_error.hpp"
#include "props_report.hpp"

namespace pgamesh::cli {

namespace {

struct PropsOptions {
  AnalysisOptions analysis;
  std::string file;
  bool json = false, urdf = false, mjcf = false, sdf = false, about_origin = false, fast = false,
       force = false;
  unsigned long long threads = 0;
};

int run_props(const PropsOptions& o) {
  AnalysisOptions options = o.analysis;
  if (o.fast) options.topology = false;
  options.mass.threads = static_cast<unsigned>(o.threads);
  if (options.mass.density && options.mass.mass)
    throw UsageError("give --density or --mass, not both");
  if (o.json + o.urdf + o.mjcf + o.sdf > 1)
    throw UsageError("choose one of --json, --urdf, --mjcf, --sdf");

  Analysis report;
  try {
    report = analyze_file(o.file, options);
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh props: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh props: %s: %s\n", o.file.c_str(), e.what());
    return 1;
  }
  // A URDF or MJCF file is read by a simulator that cannot tell a body from garbage: only a valid
  // solid is exported (the front door's verdict, Analysis::volume_valid), unless --force, which
  // writes the reasons into the file as an XML comment (props_urdf, props_mjcf).
  const bool export_xml = o.urdf || o.mjcf || o.sdf;
  const char* export_name = o.urdf ? "URDF" : o.mjcf ? "MJCF" : "SDF";
  const bool valid = report.volume_valid.value_or(false);
  if (export_xml && !valid && !o.force) {
    for (const auto& r : report.reasons)
      std::fprintf(stderr, "pgamesh props: %s: not a valid solid: %s\n", o.file.c_str(), r.c_str());
    std::fprintf(stderr, "pgamesh props: %s: no %s written (--force writes it with a warning)\n",
                 o.file.c_str(), export_name);
    return 1;
  }
  // A flat or empty body has no centre of mass or inertia (nan): there is nothing to write, even
  // forced, since no output prints nan as if it were a result.
  if (export_xml && report.mass.volume == 0) {
    std::fprintf(stderr,
                 "pgamesh props: %s: zero volume: no centre of mass or inertia to write, even with "
                 "--force\n",
                 o.file.c_str());
    return 1;
  }
  std::string out;
  if (o.json)
    out = props_json(report) + "\n";
  else if (export_xml)
    out = o.urdf ? props_urdf(report) : o.mjcf ? props_mjcf(report) : props_sdf(report);
  else
    out = props_text(report, o.about_origin);
  std::fwrite(out.data(), 1, out.size(), stdout);
  if (export_xml) {
    // The exports are in SI: a file without a unit is taken to be in metres, and said so.
    if (report.unit == LengthUnit::unspecified)
      std::fprintf(stderr,
                   "pgamesh props: warning: %s: no unit (give --unit): the %s figures assume "
                   "metres\n",
                   o.file.c_str(), export_name);
    for (const auto& w : report.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!valid)
      for (const auto& r : report.reasons)
        std::fprintf(stderr, "pgamesh props: warning: %s: not a valid solid (--force): %s\n",
                     o.file.c_str(), r.c_str());
  }
  return 0;
}

}  // namespace

void add_props_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "props",
      "mass properties: volume, mass, centre of mass, inertia, principal axes (+ URDF/MJCF)",
      "Area, signed volume, mass, centre of mass, inertia (about the centre of mass and the\n"
      "origin), products of inertia, principal moments and axes, gap area, and the topology\n"
      "summary (closed, boundary and non-manifold edges, orientation) of a mesh file\n"
      "(STL ASCII/binary, OBJ, PLY, OFF, 3MF, glTF/GLB, SLP), in the file's unit. A 3MF\n"
      "file's build items are also reported each alone.");
  sub->footer(
      "Convention: the inertia tensor's off-diagonal entries are MINUS the products of inertia\n"
      "(I_xy = -integral x y dm); principal moments ascending with right-handed unit axes.\n"
      "JSON fields: docs/json.md.\n"
      "Units: figures are in the file's unit (3MF and glTF state theirs; --unit names it for\n"
      "the others; \"unitless\" otherwise). --urdf, --mjcf and --sdf are always in SI (m, kg,\n"
      "kg m^2) with --density in kg/m^3: lengths are scaled by the metres of the file's unit\n"
      "(metres assumed, with a warning, when it has none).\n"
      "Exit status: 0 on success (also for open meshes: the report says so), 1 for unreadable\n"
      "input or a --urdf/--mjcf of a body that is not a valid solid (without --force), 2 for\n"
      "bad usage. Nothing is written on stdout when the command fails.");
  auto o = std::make_shared<PropsOptions>();
  add_file(*sub, o->file, "the mesh file; \"-\" reads standard input");
  add_positive_number(*sub, "--density", o->analysis.mass.density,
                      "mass per unit volume (default 1: mass = volume); in kg/m^3\n"
                      "for --urdf, --mjcf, --sdf")
      ->type_name("RHO");
  add_positive_number(*sub, "--mass", o->analysis.mass.mass,
                      "total mass instead; the density is M / volume")
      ->type_name("M");
  sub->add_flag("--json", o->json, "one JSON object on stdout (numbers %.17g; docs/json.md)");
  sub->add_flag("--urdf", o->urdf, "print the URDF <inertial> and <mesh> elements (SI)");
  sub->add_flag("--mjcf", o->mjcf, "print the MJCF <inertial> element and <mesh> asset (SI)");
  sub->add_flag("--sdf", o->sdf, "print an SDFormat 1.7 model: link, inertial, mesh (SI)");
  add_unit(*sub, o->analysis.unit,
           "the unit of a file that states none: mm, cm, m, in, ft, um\n"
           "(a file's own unit differing from U is an error)");
  sub->add_flag("--force", o->force,
                "with --urdf/--mjcf/--sdf: write it even when the mesh is not a\n"
                "valid solid (open, inconsistent, inward, flat, or --fast), with the\n"
                "reasons in an XML comment");
  sub->add_flag("--about-origin", o->about_origin,
                "also print the inertia tensor about the coordinate origin");
  sub->add_flag("--no-topology,--fast", o->fast,
                "skip the weld/edge pass (STL, binary or ASCII, and a GLB of one\n"
                "non-indexed triangle list are then streamed from the file\n"
                "without building a mesh; a PLY's faces are summed as they are\n"
                "read, only its vertices kept)");
  sub->add_flag_callback(
      "--no-self-intersections", [o] { o->analysis.topology_options.self_intersections = false; },
      "do not look for intersecting faces (the longest step of the\n"
      "topology on large meshes): the volume is judged without it");
  add_number(*sub, "--weld-tolerance", o->analysis.topology_options.weld_tolerance,
             "weld vertices closer than T for the topology (default 0: exact)", 0.0)
      ->type_name("T");
  add_format(*sub, o->analysis.format);
  add_count(*sub, "--threads", o->threads,
            "threads for the accumulation (default: all; results do not\ndepend on it)", 1, 1024);
  add_number(*sub, "--degeneracy-tolerance", o->analysis.mass.degeneracy_tolerance,
             "principal moments closer than T relative count as equal\n(default 1e-7)", 0.0)
      ->type_name("T");
  on_run(*sub, [o] { return run_props(*o); });
}

}  // namespace pgamesh::cli
