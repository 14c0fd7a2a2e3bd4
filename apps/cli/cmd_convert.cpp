// `pgamesh convert IN OUT [--format F] [--unit U]`: a mesh from one format into another, vertices
// and faces as read (docs/formats.md, "Converting").
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/core/units.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh::cli {

namespace {

struct ConvertOptions {
  std::string input, output;
  MeshFormat read_format = MeshFormat::unknown;
  MeshFormat write_format = MeshFormat::unknown;
  LengthUnit unit = LengthUnit::unspecified;
  std::optional<double> weld_tolerance;
  bool single_precision = false;
};

bool is_gltf(MeshFormat f) {
  return f == MeshFormat::gltf || f == MeshFormat::glb;
}

int run_convert(const ConvertOptions& o) {
  const MeshFormat target =
      o.write_format != MeshFormat::unknown ? o.write_format : format_for_extension(o.output);
  if (target == MeshFormat::unknown)
    throw UsageError("cannot tell the format of '" + o.output +
                     "' from its extension: give --format (stl, stl-ascii, obj, ply, ply-le, "
                     "ply-be, off, gltf, glb, slp)");
  std::string report;
  try {
    MeshSource source;
    Mesh mesh = read_mesh(o.input, &source, o.read_format);
    if (o.weld_tolerance) mesh = weld(std::move(mesh), *o.weld_tolerance).mesh;

    // The unit: the file's own, else --unit; a file's unit differing from --unit is converted by
    // the exact ratio of their metres. glTF is in metres by definition: other units become metres.
    const LengthUnit from = source.unit != LengthUnit::unspecified ? source.unit : o.unit;
    LengthUnit to = o.unit != LengthUnit::unspecified ? o.unit : from;
    if (is_gltf(target) && to != LengthUnit::unspecified) to = LengthUnit::meter;
    if (from != to && from != LengthUnit::unspecified) {
      const double factor = metres_per_unit(from) / metres_per_unit(to);
      for (Vec3d& v : mesh.vertices) v = v * factor;
      report += "scaled the coordinates by " + format_number(factor) + " from " + unit_name(from) +
                " to " + unit_name(to) + "\n";
    }
    if (is_gltf(target) && to == LengthUnit::unspecified)
      std::fprintf(stderr,
                   "pgamesh convert: warning: %s: no unit (give --unit): glTF states metres, so "
                   "the coordinates are read as metres\n",
                   o.input.c_str());
    WriteOptions options;
    options.unit = to;
    options.single_precision = o.single_precision;
    write_mesh(mesh, o.output, target, options);
    report += "wrote " + o.output + " (" + format_name(target) + ", " +
              std::to_string(mesh.vertices.size()) + " vertices, " +
              std::to_string(mesh.face_count()) + " faces, unit " + unit_name(to) + ")\n";
  } catch (const InputError& e) {
    std::fprintf(stderr, "pgamesh convert: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pgamesh convert: %s -> %s: %s\n", o.input.c_str(), o.output.c_str(),
                 e.what());
    return 1;
  }
  std::fwrite(report.data(), 1, report.size(), stdout);
  return 0;
}

}  // namespace

void add_convert_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "convert", "write a mesh in another format (STL, OBJ, PLY, OFF, glTF/GLB, SLP, ...)",
      "Reads IN (any format pgamesh reads, detected from the content) and writes OUT in the\n"
      "format of --format or of OUT's extension, atomically. Vertices and faces are kept as\n"
      "read (no weld unless --weld-tolerance). Formats that keep doubles (OBJ, OFF, PLY double)\n"
      "give back the same coordinates bit for bit; STL, glTF and float PLY store float32.");
  sub->footer(
      "Units: a file that states its unit (3MF, glTF: metres) keeps it; --unit states the unit\n"
      "of a file that has none, or converts a file's coordinates to U by the exact factor\n"
      "(metres per unit of the file / metres per unit of U). glTF is in metres by definition:\n"
      "a mesh with a unit is written in metres.\n"
      "Exit status: 0 on success, 1 for unreadable input or an unwritable OUT, 2 for bad usage.");
  auto o = std::make_shared<ConvertOptions>();
  sub->add_option("IN", o->input, "the mesh file to read; \"-\" reads standard input")
      ->required()
      ->type_name("");
  sub->add_option("OUT", o->output, "the file to write (replaced atomically)")
      ->required()
      ->type_name("");
  sub->add_option_function<std::string>(
         "--format",
         [o](const std::string& name) {
           o->write_format = format_from_name(name);
           if (o->write_format == MeshFormat::unknown)
             throw CLI::ValidationError("--format", "unknown format '" + name + "'");
         },
         "write OUT as F: stl (binary), stl-ascii, obj, ply (ASCII), ply-le,\n"
         "ply-be, off, gltf, glb, slp (default: from OUT's extension)")
      ->type_name("F");
  sub->add_option_function<std::string>(
         "--input-format",
         [o](const std::string& name) {
           o->read_format = name == "auto" ? MeshFormat::unknown : format_from_name(name);
           if (name != "auto" && o->read_format == MeshFormat::unknown)
             throw CLI::ValidationError("--input-format", "unknown format '" + name + "'");
         },
         "read IN as F (default auto: from the content)")
      ->type_name("F");
  add_unit(*sub, o->unit,
           "the unit of IN when it states none; for a file with a unit,\n"
           "the unit to convert its coordinates to");
  add_number(*sub, "--weld-tolerance", o->weld_tolerance,
             "merge vertices closer than T before writing (0: bitwise-equal\n"
             "coordinates; default: no weld)")
      ->type_name("T");
  sub->add_flag("--float32", o->single_precision, "PLY: store float32 coordinates");
  on_run(*sub, [o] {
    if (o->weld_tolerance && !(*o->weld_tolerance >= 0))
      throw UsageError("--weld-tolerance needs a number >= 0");
    return run_convert(*o);
  });
}

}  // namespace pgamesh::cli
