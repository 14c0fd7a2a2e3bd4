// `pgamesh fit FILE (--sphere|--plane|--cylinder|--quadric) [--json]`: least-squares fit of a
// shape to the vertices of a mesh or to a CSV/XYZ point file (docs/models.md; the fits of
// docs/models-cga.md §8 and docs/models-quadrics.md §7).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "json_text.hpp"
#include "models_args.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/models/cga_fit.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::cli {

namespace {

struct FitOptions {
  std::string file;
  bool sphere = false, plane = false, cylinder = false, quadric = false;
  bool json = false;
};

int run_fit(const FitOptions& o) {
  if (o.sphere + o.plane + o.cylinder + o.quadric != 1)
    throw UsageError("give exactly one of --sphere, --plane, --cylinder, --quadric");
  const std::vector<Vec3d> points = read_points(o.file);
  Json doc = Json::object();
  doc["file"] = o.file;
  doc["points"] = points.size();
  std::vector<std::pair<std::string, std::string>> lines;
  auto vec = [&](const char* name, const Vec3d& v) {
    doc[name] = json_vec3(v);
    lines.emplace_back(name, vec_text(v));
  };
  auto num = [&](const char* name, double v) {
    doc[name] = json_number(v);
    lines.emplace_back(name, format_number(v));
  };
  double rms = 0, max_error = 0;
  if (o.sphere) {
    doc["shape"] = "sphere";
    const cga::SphereFit f = cga::fit_sphere(points);
    vec("center", f.center);
    num("radius", f.radius);
    rms = f.rms;
    max_error = f.max_error;
  } else if (o.plane) {
    doc["shape"] = "plane";
    const cga::PlaneFit f = cga::fit_plane(points);
    vec("normal", f.normal);
    num("distance", f.distance);
    vec("point", f.point);
    rms = f.rms;
    max_error = f.max_error;
  } else if (o.cylinder) {
    doc["shape"] = "cylinder";
    const cga::CylinderFit f = cga::fit_cylinder(points);
    vec("axis_point", f.axis_point);
    vec("axis_direction", f.axis_direction);
    num("radius", f.radius);
    rms = f.rms;
    max_error = f.max_error;
  } else {
    doc["shape"] = "quadric";
    const quadric::FitResult f = quadric::fit(points);
    Json k = Json::array();
    std::string text;
    for (double c : f.quadric.k) {
      k.push_back(json_number(c));
      text += (text.empty() ? "" : ", ") + format_number(c);
    }
    doc["coefficients"] = k;
    lines.emplace_back("coefficients", "[" + text + "]");
    // Far from the origin the global coefficients lose digits; the fit's own frame keeps them
    // (docs/models-quadrics.md §7), so the type is read there.
    const std::string type(quadric::to_string(quadric::classify(f.local).type));
    doc["type"] = type;
    lines.emplace_back("type", type);
    num("algebraic_rms", f.algebraic_rms);
    rms = f.geometric_rms;  // first-order distance |F| / |grad F|
    max_error = f.geometric_max;
  }
  num("rms", rms);
  num("max_distance", max_error);
  if (o.json) {
    const std::string text = json_text(doc) + "\n";
    std::fwrite(text.data(), 1, text.size(), stdout);
  } else {
    std::printf("%s: %s fitted to %zu points\n", o.file.c_str(),
                doc["shape"].get<std::string>().c_str(), points.size());
    for (const auto& [name, value] : lines) std::printf("  %-16s%s\n", name.c_str(), value.c_str());
  }
  return 0;
}

}  // namespace

void add_fit_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "fit", "least-squares sphere, plane, cylinder or quadric through a mesh's vertices",
      "Fits a shape to the vertices of a mesh (STL, OBJ, PLY, OFF) or to a point file (.csv,\n"
      ".xyz, .txt, .pts: three numbers a line, separated by commas or blanks, '#' comments and\n"
      "one header line allowed) and reports its parameters, the RMS and the largest distance of\n"
      "the points from it. Sphere: the conformal (Pratt) fit; plane: total least squares;\n"
      "cylinder: distance to the axis by Levenberg-Marquardt; quadric: the ten coefficients\n"
      "(unit norm), with the first-order distance |F|/|grad F| (docs/models.md).");
  sub->footer(
      "Example: pgamesh fit scan.xyz --sphere --json\n"
      "Exit status: 0; 1 for an unreadable file or points that do not determine the shape (too\n"
      "few, coplanar for a sphere, collinear, NaN); 2 for bad usage.");
  auto o = std::make_shared<FitOptions>();
  add_file(*sub, o->file, "the mesh or point file");
  sub->add_flag("--sphere", o->sphere, "fit a sphere (at least 4 points, not coplanar)");
  sub->add_flag("--plane", o->plane, "fit a plane (at least 3 points, not collinear)");
  sub->add_flag("--cylinder", o->cylinder, "fit a circular cylinder (at least 6 points)");
  sub->add_flag("--quadric", o->quadric, "fit a general quadric (at least 9 points)");
  sub->add_flag("--json", o->json, "one JSON object on stdout (fields: docs/models.md)");
  on_run(*sub, [o] { return run_fit(*o); });
}

}  // namespace pgamesh::cli
