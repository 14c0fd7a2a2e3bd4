// `pgamesh cga (--pair|--line|--circle|--plane|--sphere) --points "x,y,z;…" [--json]`: a conformal
// object through points, its blades and its parameters (docs/models.md, docs/models-cga.md).
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "json_text.hpp"
#include "models_args.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/models/cga.hpp"

namespace pgamesh::cli {

namespace {

struct CgaOptions {
  bool pair = false, line = false, circle = false, plane = false, sphere = false;
  std::string points;
  bool json = false;
};

struct Report {
  std::string object;
  cga::Full element;
  Json fields = Json::object();    // JSON: center, radius, …
  std::vector<std::string> lines;  // readable: "center   (…)"
};

void add_vec(Report& r, const char* name, const Vec3d& v) {
  r.fields[name] = json_vec3(v);
  r.lines.push_back(std::string(name) + " " + vec_text(v));
}
void add_number(Report& r, const char* name, double v) {
  r.fields[name] = json_number(v);
  r.lines.push_back(std::string(name) + " " + format_number(v));
}
void add_round(Report& r, const cga::RoundParams& p) {
  add_vec(r, "center", p.center);
  add_number(r, "radius", p.radius);
  add_number(r, "radius2", p.radius_squared);
}

Report build(const CgaOptions& o, const std::vector<Vec3d>& p) {
  const int chosen = o.pair + o.line + o.circle + o.plane + o.sphere;
  if (chosen != 1)
    throw UsageError("give exactly one of --pair, --line, --circle, --plane, --sphere");
  const std::size_t need = o.pair || o.line ? 2 : o.sphere ? 4 : 3;
  Report r;
  r.object = o.pair ? "pair" : o.line ? "line" : o.circle ? "circle" : o.plane ? "plane" : "sphere";
  if (p.size() != need)
    throw UsageError("--" + r.object + " needs " + std::to_string(need) +
                     " points in --points, got " + std::to_string(p.size()));
  if (o.pair) {
    const auto x = cga::point_pair(p[0], p[1]);
    r.element = cga::widen<63>(x);
    add_round(r, cga::round_params(x));
    add_vec(r, "direction", cga::pair_params(x).direction);
    const auto pts = cga::pair_points(x);
    r.fields["points"] = Json::array({json_vec3(pts[0]), json_vec3(pts[1])});
    r.lines.push_back("points " + vec_text(pts[0]) + " " + vec_text(pts[1]));
  } else if (o.line) {
    const auto x = cga::line(p[0], p[1]);
    r.element = cga::widen<63>(x);
    const cga::LineParams l = cga::line_params(x);
    add_vec(r, "direction", l.unit_direction);
    add_vec(r, "closest_point", l.closest_point);
  } else if (o.circle) {
    const auto x = cga::circle(p[0], p[1], p[2]);
    r.element = cga::widen<63>(x);
    const cga::CircleParams c = cga::circle_params(x);
    add_round(r, c.round);
    add_vec(r, "normal", c.normal);
  } else if (o.plane) {
    const auto x = cga::plane(p[0], p[1], p[2]);
    r.element = cga::widen<63>(x);
    const cga::PlaneParams pl = cga::plane_params(x);
    add_vec(r, "normal", pl.normal);
    add_number(r, "distance", pl.distance);
    add_vec(r, "closest_point", pl.foot);
  } else {
    const auto x = cga::sphere(p[0], p[1], p[2], p[3]);
    r.element = cga::widen<63>(x);
    add_round(r, cga::sphere_params(x));
  }
  return r;
}

int run_cga(const CgaOptions& o) {
  const std::vector<Vec3d> points = parse_point_list("--points", o.points);
  Report r;
  try {
    r = build(o, points);
  } catch (const ModelError& e) {
    std::fprintf(stderr, "pgamesh cga: %s\n", e.what());
    return 1;
  }
  const auto blades = cga::blades(r.element);
  if (o.json) {
    Json doc = Json::object();
    doc["object"] = r.object;
    Json in = Json::array();
    for (const Vec3d& p : points) in.push_back(json_vec3(p));
    doc["input_points"] = in;
    Json b = Json::object();
    for (const auto& [key, c] : blades) b[key] = json_number(c);
    doc["blades"] = b;
    for (auto it = r.fields.begin(); it != r.fields.end(); ++it) doc[it.key()] = it.value();
    const std::string text = json_text(doc) + "\n";
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
  }
  std::printf("%s through %zu points\n  blades", r.object.c_str(), points.size());
  for (const auto& [key, c] : blades) std::printf("  %s %s", format_number(c).c_str(), key.c_str());
  std::printf("\n");
  for (const std::string& l : r.lines) {
    const auto space = l.find(' ');
    std::printf("  %-14s%s\n", l.substr(0, space).c_str(), l.substr(space + 1).c_str());
  }
  return 0;
}

}  // namespace

void add_cga_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "cga", "a conformal (CGA) point pair, line, circle, plane or sphere through points",
      "Builds the conformal object through the given points as the outer product of their\n"
      "conformal points (Hitzer; docs/models-cga.md) and prints its blades (keys eo, e1, e2, e3,\n"
      "einf joined by ^) and its parameters: centre, radius and signed squared radius of rounds,\n"
      "unit direction of lines and pairs, unit normal of circles and planes, a pair's two points\n"
      "(larger norm first), a plane's signed distance from the origin (normal . x = distance).");
  sub->footer(
      "Example: pgamesh cga --sphere --points \"1,0,0;0,1,0;-1,0,0;0,0,1\" --json\n"
      "Exit status: 0; 1 when the points do not make the object (coincident, collinear,\n"
      "coplanar, not finite); 2 for bad usage.");
  auto o = std::make_shared<CgaOptions>();
  sub->add_flag("--pair", o->pair, "the point pair P1 ^ P2 (2 points)");
  sub->add_flag("--line", o->line, "the line P1 ^ P2 ^ einf (2 points)");
  sub->add_flag("--circle", o->circle, "the circle P1 ^ P2 ^ P3 (3 points)");
  sub->add_flag("--plane", o->plane, "the plane P1 ^ P2 ^ P3 ^ einf (3 points)");
  sub->add_flag("--sphere", o->sphere, "the sphere P1 ^ P2 ^ P3 ^ P4 (4 points)");
  sub->add_option("--points", o->points, "the points as \"x,y,z;x,y,z;...\"")
      ->required()
      ->type_name("LIST");
  sub->add_flag("--json", o->json, "one JSON object on stdout (fields: docs/models.md)");
  on_run(*sub, [o] { return run_cga(*o); });
}

}  // namespace pgamesh::cli
