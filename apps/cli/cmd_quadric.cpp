// `pgamesh quadric (--coefficients a,…,j | --through "x,y,z;…") [--model qcga|dcga|dpga]
// [--point x,y,z]… [--line ox,oy,oz,dx,dy,dz]… [--rotate I,J,ANGLE] [--translate x,y,z] [--json]`:
// a quadric in one of the three GA models, its type, values, tangent planes, line intersections
// and moved copies (docs/models.md, docs/models-quadrics.md).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "json_text.hpp"
#include "models_args.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/models/dcga.hpp"
#include "pgamesh/models/dpga.hpp"
#include "pgamesh/models/qcga.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::cli {

namespace {

using quadric::Quadric;

struct QuadricOptions {
  std::string coefficients, through, model = "qcga";
  std::vector<std::string> points, lines;
  std::string rotate, translate;
  bool json = false;
};

Json numbers(std::span<const double> v) {
  Json a = Json::array();
  for (double x : v) a.push_back(json_number(x));
  return a;
}
std::string numbers_text(std::span<const double> v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + format_number(x);
  return "[" + s + "]";
}

// The model the command works in: its element's blades, and value / gradient / motions computed
// by the model itself (the closed forms of quadric.hpp only where the model has no operation).
struct Model {
  std::string name;
  Quadric q;

  std::vector<std::pair<std::string, double>> blades() const {
    if (name == "dpga") return dpga::nonzero_blades(dpga::quadric(q));
    if (name == "dcga") return dcga::nonzero_blades(dcga::quadric(q));
    return qcga::nonzero_blades(qcga::dual_quadric(q));
  }
  double value(const Vec3d& p) const {
    if (name == "dpga") return dpga::value(dpga::quadric(q), p);
    if (name == "dcga") return dcga::value(dcga::quadric(q), p);
    return qcga::value(qcga::dual_quadric(q), p);
  }
  Vec3d gradient(const Vec3d& p) const {
    if (name == "dpga") {
      const auto pi = dpga::polar_plane(dpga::quadric(q), p);
      return {pi[0], pi[1], pi[2]};
    }
    if (name == "dcga") return dcga::gradient(dcga::quadric(q), p);
    return qcga::normal(qcga::dual_quadric(q), p);
  }
  // Rotation by theta in the (x_i, x_j) plane, x_i towards x_j: the DPGA rotor (Breuils eq. 73
  // corrected), the DCGA rotor; QCGA through the coefficients.
  Quadric rotated(int i, int j, double theta) const {
    if (name == "dpga") return dpga::coefficients(dpga::rotate(dpga::quadric(q), i, j, theta));
    if (name == "dcga")
      return dcga::coefficients(dcga::transform(dcga::rotor(i, j, theta), dcga::quadric(q)));
    return quadric::rotate(q, quadric::plane_rotation(i, j, theta));
  }
  // Translation: the DCGA translator; DPGA has no translating versor and QCGA's is not
  // implemented, so both move the coefficients (docs/models-quadrics.md §2).
  Quadric translated(const Vec3d& t) const {
    if (name == "dcga")
      return dcga::coefficients(dcga::transform(dcga::translator(t), dcga::quadric(q)));
    return quadric::translate(q, t);
  }
};

int run_quadric(const QuadricOptions& o) {
  if (o.coefficients.empty() == o.through.empty())
    throw UsageError("give exactly one of --coefficients and --through");
  if (o.model != "qcga" && o.model != "dcga" && o.model != "dpga")
    throw UsageError("--model must be qcga, dcga or dpga, not '" + o.model + "'");
  // Parse every option first: bad usage exits 2 before anything is computed.
  std::vector<Vec3d> through;
  std::vector<double> given;
  if (!o.through.empty())
    through = parse_point_list("--through", o.through);
  else
    given = parse_number_list("--coefficients", o.coefficients, 10);
  std::vector<Vec3d> points;
  for (const std::string& p : o.points) {
    const auto x = parse_number_list("--point", p, 3);
    points.push_back({x[0], x[1], x[2]});
  }
  std::vector<std::vector<double>> lines;
  for (const std::string& l : o.lines) lines.push_back(parse_number_list("--line", l, 6));
  std::vector<double> rotate, translate;
  if (!o.rotate.empty()) {
    rotate = parse_number_list("--rotate", o.rotate, 3);
    for (int k : {0, 1})
      if (rotate[k] != 0 && rotate[k] != 1 && rotate[k] != 2)
        throw UsageError("--rotate I,J,ANGLE: I and J are axes 0 (x), 1 (y) or 2 (z)");
    if (rotate[0] == rotate[1]) throw UsageError("--rotate I,J,ANGLE: I and J must differ");
  }
  if (!o.translate.empty()) translate = parse_number_list("--translate", o.translate, 3);

  Model m{o.model, {}};
  Json doc = Json::object();
  doc["model"] = o.model;
  std::string text;
  auto line = [&text](const std::string& name, const std::string& value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "  %-24s ", name.c_str());
    text += buf + value + "\n";
  };
  if (!through.empty()) {
    const quadric::FitResult f = quadric::fit(through);
    m.q = f.quadric;
    doc["coefficients"] = numbers(m.q.k);
    doc["fit"] = {{"points", through.size()},
                  {"algebraic_rms", json_number(f.algebraic_rms)},
                  {"algebraic_max", json_number(f.algebraic_max)},
                  {"geometric_rms", json_number(f.geometric_rms)},
                  {"geometric_max", json_number(f.geometric_max)}};
    line("coefficients (fitted)", numbers_text(m.q.k));
    line("fit", std::to_string(through.size()) + " points, distance rms " +
                    format_number(f.geometric_rms) + ", max " + format_number(f.geometric_max));
  } else {
    for (std::size_t k = 0; k < 10; ++k) m.q[k] = given[k];
    quadric::check_finite(m.q);
    doc["coefficients"] = numbers(m.q.k);
    line("coefficients", numbers_text(m.q.k));
  }
  const auto type = std::string(quadric::to_string(quadric::classify(m.q).type));
  doc["type"] = type;
  line("type", type);
  Json element = Json::object();
  std::string element_text;
  for (const auto& [key, c] : m.blades()) {
    element[key] = json_number(c);
    element_text += (element_text.empty() ? "" : "  ") + format_number(c) + " " + key;
  }
  doc["element"] = element;
  line(o.model + " element", element_text.empty() ? "0" : element_text);

  if (!points.empty()) {
    Json list = Json::array();
    for (const Vec3d& p : points) {
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw ModelError("--point " + vec_text(p) + ": the coordinates are not finite");
      const double f = m.value(p);
      const Vec3d g = m.gradient(p);
      const auto plane = quadric::tangent_plane(m.q, p);
      list.push_back({{"point", json_vec3(p)},
                      {"value", json_number(f)},
                      {"gradient", json_vec3(g)},
                      {"tangent_plane", numbers(plane)}});
      line("point " + vec_text(p), "value " + format_number(f) + ", gradient " + vec_text(g) +
                                       ", tangent plane " + numbers_text(plane));
    }
    doc["points"] = list;
  }
  if (!lines.empty()) {
    Json list = Json::array();
    for (const auto& l : lines) {
      const Vec3d origin{l[0], l[1], l[2]}, direction{l[3], l[4], l[5]};
      const quadric::LineIntersection hit =
          o.model == "qcga" ? qcga::intersect_line(qcga::dual_quadric(m.q), origin, direction)
                            : quadric::intersect_line(m.q, origin, direction);
      Json t = Json::array(), pts = Json::array();
      std::string where;
      for (int k = 0; k < hit.count; ++k) {
        t.push_back(json_number(hit.t[static_cast<std::size_t>(k)]));
        pts.push_back(json_vec3(hit.points[static_cast<std::size_t>(k)]));
        where += " " + vec_text(hit.points[static_cast<std::size_t>(k)]);
      }
      const std::string kind(quadric::to_string(hit.kind));
      list.push_back({{"origin", json_vec3(origin)},
                      {"direction", json_vec3(direction)},
                      {"kind", kind},
                      {"t", t},
                      {"points", pts}});
      line("line " + vec_text(origin) + " + t " + vec_text(direction), kind + where);
    }
    doc["lines"] = list;
  }
  if (!rotate.empty()) {
    const Quadric r =
        m.rotated(static_cast<int>(rotate[0]), static_cast<int>(rotate[1]), rotate[2]);
    quadric::check_finite(r);
    doc["rotated_coefficients"] = numbers(r.k);
    line("rotated coefficients", numbers_text(r.k));
  }
  if (!translate.empty()) {
    const Quadric t = m.translated({translate[0], translate[1], translate[2]});
    quadric::check_finite(t);
    doc["translated_coefficients"] = numbers(t.k);
    line("translated coefficients", numbers_text(t.k));
  }
  const std::string out = o.json ? json_text(doc) + "\n" : "quadric (" + o.model + ")\n" + text;
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace

void add_quadric_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "quadric", "a quadric in DPGA, DCGA or QCGA: type, values, tangent planes, lines",
      "A quadric F = a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j = 0 from\n"
      "its coefficients or fitted to points (least squares, at least 9 points), as the element of\n"
      "a geometric-algebra model (Breuils et al.; docs/models-quadrics.md): its type, its blades,\n"
      "F, the gradient and the tangent plane [n, -n.p] at points, where lines meet it, and its\n"
      "coefficients after a rotation or translation.");
  sub->footer(
      "Example: pgamesh quadric --coefficients 1,1,1,0,0,0,0,0,0,-1 --point 1,0,0 --line "
      "0,0,-5,0,0,1\n"
      "Exit status: 0; 1 for input the model refuses (fewer than 9 points, points on a\n"
      "lower-order surface, a zero line direction, NaN); 2 for bad usage.");
  auto o = std::make_shared<QuadricOptions>();
  sub->add_option("--coefficients", o->coefficients, "a,b,c,d,e,f,g,h,i,j")->type_name("LIST");
  sub->add_option("--through", o->through, "fit to the points \"x,y,z;x,y,z;...\" (>= 9)")
      ->type_name("LIST");
  sub->add_option("--model", o->model, "qcga (default), dcga or dpga")->type_name("NAME");
  sub->add_option("--point", o->points, "x,y,z: value, gradient, tangent plane (repeatable)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("P");
  sub->add_option("--line", o->lines,
                  "ox,oy,oz,dx,dy,dz: where o + t d meets the quadric (repeatable)")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name("L");
  sub->add_option("--rotate", o->rotate, "I,J,ANGLE: turn axis I towards J (0 x, 1 y, 2 z)")
      ->type_name("R");
  sub->add_option("--translate", o->translate, "x,y,z")->type_name("T");
  sub->add_flag("--json", o->json, "one JSON object on stdout (fields: docs/models.md)");
  on_run(*sub, [o] { return run_quadric(*o); });
}

}  // namespace pgamesh::cli
