// `pgamesh calc` end to end: results against golden values (pga_basics.json joins, cga.json
// objects and their parameters, quadrics.json elements and values in the three quadric models,
// the 2-D polygon and the 4-D 5-cell), closed forms of the scalar functions on numbers and on
// non-unit rotors and motors, the metric dual against the Hodge complement, the output rules
// (rounding residue hidden in text, full values in the one JSON document), scripts with `let` on
// stdin, and the errors for bad syntax, unknown blades and hostile input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "pgamesh/core/number_text.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::json;
using pgamesh::test::parse_json;
using pgamesh::test::Tolerance;

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  q.push_back('\'');
  return q;
}

// Runs `pgamesh calc ARGS` with `input` on stdin.
CliRun calc(const std::string& args, const std::string& input = "") {
  const pgamesh::test::TempFile in(".in", input);
  return pgamesh::test::run_cli("calc " + args, in.path());
}

std::string point_expr(const json& p) {
  std::string s = "point(";
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i) s.push_back(',');
    s.append(pgamesh::format_number(p[i].get<double>()));
  }
  s.push_back(')');
  return s;
}

// The values of the one JSON document of `calc --json SCRIPT` (stdin), in statement order.
std::vector<json> json_values(const std::string& algebra, const std::string& script) {
  const CliRun r = calc("--algebra " + algebra + " --json", script);
  EXPECT_EQ(r.status, 0) << r.err;
  std::vector<json> out;
  try {
    const json doc = parse_json(r.out);
    EXPECT_EQ(doc["algebra"], algebra);
    for (const auto& res : doc["results"]) out.push_back(res["value"]);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not one JSON document: " << r.out;
  }
  return out;
}

double coeff(const json& value, const std::string& blade) {
  return value.contains(blade) ? value[blade].get<double>() : 0.0;
}

// The vector x e1 + y e2 + z e3 of a value.
std::vector<double> vec3(const json& value) {
  return {coeff(value, "e1"), coeff(value, "e2"), coeff(value, "e3")};
}

// A value against golden blades; `rename` maps generator names between '^' (ei → einf, …).
::testing::AssertionResult blades_match(const json& got, const json& expected, Tolerance t,
                                        const std::map<std::string, std::string>& rename = {}) {
  std::map<std::string, double> g;
  for (auto it = got.begin(); it != got.end(); ++it) {
    std::string k, part;
    const std::string key = it.key() + "^";
    for (char ch : key) {
      if (ch != '^') {
        part.push_back(ch);
        continue;
      }
      const auto r = rename.find(part);
      if (!k.empty()) k.push_back('^');
      k.append(r == rename.end() ? part : r->second);
      part.clear();
    }
    g[k] = it.value().get<double>();
  }
  std::vector<double> gv, ev;
  for (auto it = expected.begin(); it != expected.end(); ++it) {
    ev.push_back(it.value().get<double>());
    gv.push_back(g.count(it.key()) ? g[it.key()] : 0.0);
    g.erase(it.key());
  }
  for (const auto& [k, v] : g) {  // blades the golden file does not list must be ~0
    ev.push_back(0.0);
    gv.push_back(v);
  }
  return pgamesh::test::near_group(gv, ev, t);
}

}  // namespace

// ---- golden values
// ---------------------------------------------------------------------------------

TEST(Calc, Pga3JoinsMatchGolden) {
  const json file = pgamesh::test::load_golden("pga_basics.json");
  int cases = 0;
  for (const auto& c : file["cases"]) {
    if (c["id"].get<std::string>().rfind("joins_random_", 0) != 0) continue;
    const auto t = pgamesh::test::tolerance_of(file, c);
    const json& in = c["input"];
    const std::string script = "let a = " + point_expr(in["a"]) +
                               "\nlet b = " + point_expr(in["b"]) +
                               "\nlet c = " + point_expr(in["c"]) + "\na & b\na & b & c\n";
    const auto v = json_values("pga3", script);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_TRUE(blades_match(v[0], c["expected"]["line_ab"], t));
    EXPECT_TRUE(blades_match(v[1], c["expected"]["plane_abc"], t));
    ++cases;
  }
  EXPECT_EQ(cases, 4);
}

// Every CGA object of cga.json built twice, as the outer product of points and by its model
// function, and its parameters read back by the model functions.
TEST(Calc, CgaObjectsAndParametersMatchGolden) {
  const json file = pgamesh::test::load_golden("cga.json");
  const std::map<std::string, std::string> ei{{"ei", "einf"}};
  int cases = 0;
  for (const auto& c : file["cases"]) {
    const std::string id = c["id"];
    const json& in = c["input"];
    const json& ex = c["expected"];
    const auto t = pgamesh::test::tolerance_of(file, c);
    std::vector<std::string> pts;
    if (in.contains("points"))
      for (const auto& p : in["points"]) pts.push_back(point_expr(p));
    for (const char* k : {"p1", "p2", "p3"})
      if (in.contains(k)) pts.push_back(point_expr(in[k]));
    std::string outer, args;
    for (const auto& p : pts) {
      if (!outer.empty()) outer += " ^ ";
      if (!args.empty()) args += ", ";
      outer += p;
      args += p;
    }
    std::string script;
    std::vector<std::string> fields;
    if (id.rfind("pair_", 0) == 0) {
      script = "let X = pair(" + args + ")\nX\n" + outer +
               "\ncenter(X)\nradius(X)\ndirection(X)\ndown(pair_point(X, 1))\n";
      fields = {"center", "half_distance_r", "direction_p2_to_p1", "point1"};
    } else if (id.rfind("line_", 0) == 0) {
      script = "let X = line(" + args + ")\nX\n" + outer + " ^ ei\ndirection(X)\ncenter(X)\n";
      fields = {"unit_direction", "closest_point"};
    } else if (id.rfind("circle_", 0) == 0) {
      script = "let X = circle(" + args + ")\nX\n" + outer + "\ncenter(X)\nradius(X)\nnormal(X)\n";
      fields = {"center", "radius", "unit_normal"};
    } else if (id.rfind("plane_", 0) == 0) {
      script = "let X = plane(" + args + ")\nX\n" + outer + " ^ ei\nnormal(X)\ndistance(X)\n";
      fields = {"unit_normal", "signed_distance"};
    } else if (id.rfind("sphere_", 0) == 0) {
      script = "let X = sphere(" + args + ")\nX\n" + outer + "\ncenter(X)\nradius(X)\n";
      fields = {"center", "radius"};
    } else {
      continue;
    }
    const auto v = json_values("cga3", script);
    ASSERT_EQ(v.size(), 2 + fields.size()) << id;
    EXPECT_TRUE(blades_match(v[0], ex["blades"], t, ei)) << id << " (model function)";
    EXPECT_TRUE(blades_match(v[1], ex["blades"], t, ei)) << id << " (outer product)";
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const json& got = v[2 + k];
      const std::string& f = fields[k];
      if (f == "point1") {
        EXPECT_TRUE(pgamesh::test::near_group(
            vec3(got), pgamesh::test::flatten(ex["points_larger_norm_first"][0]), t))
            << id;
      } else if (f == "unit_direction") {
        std::vector<double> d = pgamesh::test::flatten(ex["direction"]);
        const double n = std::hypot(d[0], d[1], d[2]);
        for (double& x : d) x /= n;
        EXPECT_TRUE(pgamesh::test::near_group(vec3(got), d, t)) << id;
      } else if (ex[f].is_array()) {
        EXPECT_TRUE(pgamesh::test::near_group(vec3(got), pgamesh::test::flatten(ex[f]), t))
            << id << " " << f;
      } else {
        EXPECT_TRUE(pgamesh::test::near_scalar(coeff(got, "1"), ex[f].get<double>(), t))
            << id << " " << f;
      }
    }
    ++cases;
  }
  EXPECT_EQ(cases, 14);
}

// quadric(a..j) gives the golden element in each model, value(Q, point) the golden values, and the
// nine golden points give the normalized golden coefficients back (value at the eval points).
TEST(Calc, QuadricElementsAndValuesMatchGolden) {
  const json file = pgamesh::test::load_golden("quadrics.json");
  const struct {
    const char* algebra;
    const char* key;
    std::map<std::string, std::string> rename;
  } models[] = {
      {"dpga", "dpga_Q", {{"w0s", "w0*"}, {"w1s", "w1*"}, {"w2s", "w2*"}, {"w3s", "w3*"}}},
      {"dcga", "dcga_Q", {{"ei1", "einf1"}, {"ei2", "einf2"}}},
      {"qcga",
       "qcga_qstar",
       {{"ei1", "einf1"},
        {"ei2", "einf2"},
        {"ei3", "einf3"},
        {"ei4", "einf4"},
        {"ei5", "einf5"},
        {"ei6", "einf6"}}},
  };
  // One calc run per model, every case in it: the quadric of case i is Q<i>, printed, then its
  // value at each of the case's points.
  const json& cases = file["cases"];
  ASSERT_GE(cases.size(), 20u);
  for (const auto& m : models) {
    std::string script;
    std::size_t printed = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const json& in = cases[i]["input"];
      const std::string name = "Q" + std::to_string(i);
      script += "let " + name + " = quadric(";
      for (std::size_t k = 0; k < 10; ++k) {
        if (k) script += ",";
        script += pgamesh::format_number(in["coefficients"][k].get<double>());
      }
      script += ")\n" + name + "\n";
      for (const auto& p : in["eval_points"])
        script += "value(" + name + ", " + point_expr(p) + ")\n";
      printed += 1 + in["eval_points"].size();
    }
    const auto v = json_values(m.algebra, script);
    ASSERT_EQ(v.size(), printed) << m.algebra;
    std::size_t next = 0;
    for (const auto& c : cases) {
      const json& ex = c["expected"];
      const auto t = pgamesh::test::tolerance_of(file, c);
      EXPECT_TRUE(blades_match(v[next++], ex[m.key], t, m.rename)) << c["id"] << " " << m.algebra;
      std::vector<double> values;
      for (std::size_t k = 0; k < c["input"]["eval_points"].size(); ++k)
        values.push_back(coeff(v[next++], "1"));
      EXPECT_TRUE(pgamesh::test::near_group(values, pgamesh::test::flatten(ex["values"]), t))
          << c["id"] << " " << m.algebra;
    }
  }
}

TEST(Calc, QuadricFunctionsInEveryModel) {
  // Unit sphere: F(2,0,0) = 3; ∇F(1,0,0) = (2,0,0); the z axis meets it at z = −1 and z = 1;
  // moved by (1,0,0), F(2,0,0) = 0; nine points of the sphere give it back (unit norm: F(0) = −½).
  for (const char* a : {"dpga", "dcga", "qcga"}) {
    const auto v = json_values(
        a,
        "let Q = quadric(1,1,1,0,0,0,0,0,0,-1)\n"
        "value(Q, point(2,0,0))\n"
        "value(Q, intersect(Q, point(0,0,-5), point(0,0,5)))\n"
        "intersect(Q, point(0,0,-5), point(0,0,5), 2) - point(0,0,1)\n"
        "intersect(Q, point(0,0,-5), point(0,0,5)) - point(0,0,-1)\n"
        "value(translate(Q, 1, 0, 0), point(2,0,0))\n"
        "value(rotate(quadric(1,4,1,0,0,0,0,0,0,-4), 0, 1, pi/2), point(0,2,0))\n"
        "value(quadric(point(1,0,0), point(-1,0,0), point(0,1,0), point(0,-1,0), point(0,0,1), "
        "point(0,0,-1), point(0.6,0.8,0), point(0,0.6,0.8), point(0.8,0,0.6)), point(0,0,0))\n");
    ASSERT_EQ(v.size(), 7u) << a;
    EXPECT_NEAR(coeff(v[0], "1"), 3, 1e-14) << a;
    EXPECT_NEAR(coeff(v[1], "1"), 0, 1e-14) << a;
    for (int k : {2, 3})
      for (auto it = v[k].begin(); it != v[k].end(); ++it)
        EXPECT_NEAR(it.value().get<double>(), 0, 1e-14) << a << " " << it.key();
    EXPECT_NEAR(coeff(v[4], "1"), 0, 1e-14) << a;
    // x² + 4y² + z² = 4 turned by 90° from x towards y: the long axis (x, 2) becomes y: F(0,2,0) =
    // 0
    EXPECT_NEAR(coeff(v[5], "1"), 0, 1e-13) << a;
    EXPECT_NEAR(coeff(v[6], "1"), -0.5, 1e-12) << a;
  }
  // Gradient and tangent plane at (0,0,1): ∇F = (0,0,2), the plane 2z − 2 = 0.
  auto v = json_values("qcga",
                       "let Q = quadric(1,1,1,0,0,0,0,0,0,-1)\ngradient(Q, point(0,0,1))\n"
                       "tangent_plane(Q, point(0,0,1))\n");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(vec3(v[0]), (std::vector<double>{0, 0, 2}));
  EXPECT_EQ(coeff(v[1], "e3"), 2);  // π* = n + (n·p) e∞, e∞ = ⅓(ei1 + ei2 + ei3)
  EXPECT_NEAR(coeff(v[1], "ei1"), 2.0 / 3, 1e-15);
  v = json_values("dpga", "tangent_plane(quadric(1,1,1,0,0,0,0,0,0,-1), point(0,0,1))\n");
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(coeff(v[0], "w2s"), 2);
  EXPECT_EQ(coeff(v[0], "w3s"), -2);
  // Errors name the problem.
  CliRun r = calc(
      "--algebra qcga 'intersect(quadric(1,1,1,0,0,0,0,0,0,-1), point(5,0,0), "
      "point(5,1,0))'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("meets the quadric in 0 points (none)"), std::string::npos) << r.err;
  r = calc("--algebra dpga 'value(point(1,2,3), point(1,2,3))'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("must be a bivector"), std::string::npos) << r.err;
  r = calc(
      "--algebra qcga 'quadric(point(1,0,0), point(2,0,0), point(3,0,0), point(4,0,0), "
      "point(5,0,0), point(6,0,0), point(7,0,0), point(8,0,0), point(9,0,0))'");
  EXPECT_EQ(r.status, 1);
  r = calc("--algebra cga3 'quadric(1,1,1,0,0,0,0,0,0,-1)'");
  EXPECT_NE(r.err.find("quadric() is not defined in algebra cga3 (it is for dpga, dcga, qcga)"),
            std::string::npos)
      << r.err;
}

TEST(Calc, PolygonAreaAndFiveCellFromJoins) {
  // 2-D: area = ½ o ∨ Σ E_i (paper eq. 4.7) for the golden non-convex pentagon: 8.
  const CliRun area =
      calc("--algebra pga2",
           "let o = point(0,0)\n"
           "let a = point(0,0); let b = point(4,0); let c = point(4,3); let d = point(2,1); "
           "let e = point(0,3)\n"
           "0.5 * (o & (a&b + b&c + c&d + d&e + e&a))\n");
  ASSERT_EQ(area.status, 0) << area.err;
  EXPECT_EQ(area.out, "8\n");
  // 4-D: the join of the golden 5-cell's vertices is det = 156.
  const CliRun cell = calc(
      "--algebra pga4 'point(2,3,2,2) & point(-2,2,1,-2) & point(3,-2,-2,2) & "
      "point(-2,3,-3,-1) & point(2,-3,-1,-1)'");
  ASSERT_EQ(cell.status, 0) << cell.err;
  EXPECT_EQ(cell.out, "156\n");
}

// ---- scalar functions, exp / log / sqrt / pow
// ------------------------------------------------------

TEST(Calc, ScalarFunctionsOnNumbers) {
  const auto v = json_values("pga3",
                             "log(2); exp(2); sqrt(2); pow(2, 10); pow(2, 0.5); pow(-2, 3); "
                             "sin(pi/6); cos(pi/3); atan2(1, 1); atan2(-1, -1); tan(0.5); abs(-3); "
                             "asin(1); acos(0); atan(1); sinh(1); cosh(1); tanh(1)");
  const double expected[] = {std::log(2.0),
                             std::exp(2.0),
                             std::sqrt(2.0),
                             1024,
                             std::sqrt(2.0),
                             -8,
                             std::sin(std::numbers::pi / 6),
                             std::cos(std::numbers::pi / 3),
                             std::numbers::pi / 4,
                             -3 * std::numbers::pi / 4,
                             std::tan(0.5),
                             3,
                             std::numbers::pi / 2,
                             std::numbers::pi / 2,
                             std::numbers::pi / 4,
                             std::sinh(1.0),
                             std::cosh(1.0),
                             std::tanh(1.0)};
  ASSERT_EQ(v.size(), std::size(expected));
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_EQ(coeff(v[k], "1"), expected[k]) << k;
  EXPECT_EQ(calc("'log(2)'").out, "0.693147180559945\n");
  EXPECT_EQ(calc("--digits 17 'log(2)'").out, "0.69314718055994529\n");
  for (const char* bad : {"log(0)", "log(-1)", "sqrt(-4)", "asin(2)", "pow(-2, 0.5)", "pow(0, -1)",
                          "exp(1000)", "sin(e1)"}) {
    const CliRun r = calc(quote(bad));
    EXPECT_EQ(r.status, 1) << bad;
    EXPECT_NE(r.err.find("error at column"), std::string::npos) << bad << ": " << r.err;
  }
}

TEST(Calc, ExpLogSqrtPowOfNonUnitRotorsAndMotors) {
  const double ln2 = std::log(2.0);
  // log(2 exp(0.3 e12)) = ln 2 + 0.3 e12; sqrt(4 exp(0.6 e12)) = 2 exp(0.3 e12).
  auto v = json_values("pga3",
                       "log(2*exp(0.3*e12)); sqrt(4*exp(0.6*e12)); pow(4*exp(0.6*e12), 0.5); "
                       "pow(exp(0.2*e12), 3); pow(2*exp(0.2*e12), -1) * 2*exp(0.2*e12); "
                       "log(3*exp(e12 + e01)); log(2 + 2*e01); exp(log(5*exp(0.4*e31 + e02)))");
  ASSERT_EQ(v.size(), 8u);
  EXPECT_NEAR(coeff(v[0], "1"), ln2, 1e-15);
  EXPECT_NEAR(coeff(v[0], "e12"), 0.3, 1e-15);
  for (int k : {1, 2}) {
    EXPECT_NEAR(coeff(v[k], "1"), 2 * std::cos(0.3), 1e-15) << k;
    EXPECT_NEAR(coeff(v[k], "e12"), 2 * std::sin(0.3), 1e-15) << k;
  }
  EXPECT_NEAR(coeff(v[3], "1"), std::cos(0.6), 1e-15);
  EXPECT_NEAR(coeff(v[3], "e12"), std::sin(0.6), 1e-15);
  EXPECT_NEAR(coeff(v[4], "1"), 1, 1e-15);
  EXPECT_NEAR(coeff(v[4], "e12"), 0, 1e-15);
  EXPECT_NEAR(coeff(v[5], "1"), std::log(3.0), 1e-15);
  EXPECT_NEAR(coeff(v[5], "e12"), 1, 1e-15);
  EXPECT_NEAR(coeff(v[5], "e01"), 1, 1e-15);
  EXPECT_NEAR(coeff(v[6], "1"), ln2, 1e-15);
  EXPECT_NEAR(coeff(v[6], "e01"), 1, 1e-15);
  // exp(log M) = M = 5 exp(0.4 e31 + e02)
  const auto m = json_values("pga3", "5*exp(0.4*e31 + e02)");
  ASSERT_EQ(m.size(), 1u);
  EXPECT_TRUE(blades_match(v[7], m[0], {1e-14, 1e-14}));
  // A PGA motor times the dual number 1 + 0.5 e0123: M M~ = (1 + 0.5 I)^2, log M = 0.5 I + 0.3 e12.
  v = json_values("pga3", "log((1 + 0.5*e0123) * exp(0.3*e12))");
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(coeff(v[0], "e0123"), 0.5, 1e-15);
  EXPECT_NEAR(coeff(v[0], "e12"), 0.3, 1e-15);
  EXPECT_NEAR(coeff(v[0], "1"), 0, 1e-15);
  // Readable: the rounding residue of the closed form is not printed.
  EXPECT_EQ(calc("'log(2*exp(0.3*e12))'").out, "0.693147180559945 + 0.3 e12\n");
  // Elements that are no multiple of a rotor or motor are refused.
  CliRun r = calc("'log(e12 + e1)'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("not a multiple of a rotor or motor"), std::string::npos) << r.err;
  r = calc("'log(e01)'");
  EXPECT_NE(r.err.find("not positive"), std::string::npos) << r.err;
}

// ---- duals and the pseudoscalar
// ---------------------------------------------------------------------

TEST(Calc, MetricDualIsNotTheHodgeComplement) {
  // The unit sphere through four points: its metric dual X I^-1 is the dual sphere
  // σ ∝ eo − ½ ei (radius 1); the Hodge complement !S is another vector (eo − 2 ei up to scale).
  const std::string s = "let S = sphere(point(1,0,0), point(0,1,0), point(-1,0,0), point(0,0,1))\n";
  const auto v = json_values(
      "cga3", s + "dual(S)\n!S\nhodge(S) - !S\nundual(dual(S)) - S\nradius(S)\nradius(dual(S))\n"
                  "I\nI*I\ndual(I)\n");
  ASSERT_EQ(v.size(), 9u);
  EXPECT_EQ(coeff(v[0], "ei") / coeff(v[0], "eo"), -0.5);
  EXPECT_EQ(coeff(v[1], "ei") / coeff(v[1], "eo"), -2);
  EXPECT_TRUE(v[2].empty());
  for (auto it = v[3].begin(); it != v[3].end(); ++it)
    EXPECT_NEAR(it.value().get<double>(), 0, 1e-15);
  EXPECT_EQ(coeff(v[4], "1"), 1);
  EXPECT_NEAR(coeff(v[5], "1"), 1, 1e-15);
  EXPECT_EQ(v[6], json({{"eo^e1^e2^e3^ei", 1.0}}));
  EXPECT_EQ(v[7], json({{"1", -1.0}}));
  EXPECT_EQ(v[8], json({{"1", 1.0}}));  // I I^-1
  // In PGA the pseudoscalar squares to 0: dual() refuses and points to the Hodge complement.
  EXPECT_EQ(calc("'I'").out, "e0123\n");
  EXPECT_EQ(calc("'!e1; hodge(e1); unhodge(!e1)'").out, "e032\ne032\ne1\n");
  const CliRun r = calc("'dual(e1)'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("use !X or hodge(X)"), std::string::npos) << r.err;
  EXPECT_NE(calc("'let I = 2'").err.find("'I' is a blade, constant or function name"),
            std::string::npos);
  // In R(3,0,0) the metric dual of e1 is e1 e123^-1 = −e23 (e123^-1 = −e123).
  EXPECT_EQ(calc("--algebra 3,0,0 'dual(e1); undual(dual(e1 + e12))'").out, "-e23\ne1 + e12\n");
}

TEST(Calc, CgaModelFunctions) {
  // Sphere of centre (1,2,3) and radius 2 met by the line x = 1, y = 2: the pair (1,2,5), (1,2,1).
  const auto v =
      json_values("cga3",
                  "let S = sphere(point(1,2,3), 2)\n"
                  "let X = intersect(S, line(point(1,2,0), point(1,2,5)))\n"
                  "down(pair_point(X, 1)); down(pair_point(X, 2)); center(X); radius(X)\n"
                  "radius2(circle(point(1,0,0), point(0,1,0), point(-1,0,0)))\n"
                  "distance(plane(e3, 2)); normal(plane(e3, 2)); distance(point(1,2,3), "
                  "4*e1 + 6*e2 + 3*e3)\n"
                  "center(translate(S, 1, 0, 0)); center(rotate(S, e3, pi/2))\n"
                  "down(sandwich(translator(1, 2, 3), point(0,0,0)))\n"
                  "direction(line(point(0,0,0), point(0,0,7)))\n");
  ASSERT_EQ(v.size(), 12u);
  EXPECT_EQ(vec3(v[0]), (std::vector<double>{1, 2, 5}));
  EXPECT_EQ(vec3(v[1]), (std::vector<double>{1, 2, 1}));
  EXPECT_EQ(vec3(v[2]), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(coeff(v[3], "1"), 2);
  EXPECT_EQ(coeff(v[4], "1"), 1);
  EXPECT_EQ(coeff(v[5], "1"), 2);
  EXPECT_EQ(vec3(v[6]), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(coeff(v[7], "1"), 5);
  EXPECT_EQ(vec3(v[8]), (std::vector<double>{2, 2, 3}));
  const auto c = vec3(v[9]);
  EXPECT_NEAR(c[0], -2, 1e-15);
  EXPECT_NEAR(c[1], 1, 1e-15);
  EXPECT_NEAR(c[2], 3, 1e-15);
  EXPECT_EQ(vec3(v[10]), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(vec3(v[11]), (std::vector<double>{0, 0, 1}));
  // Bad input names the problem.
  const struct {
    const char* expr;
    const char* message;
  } bad[] = {
      {"sphere(point(0,0,0), point(1,0,0), point(0,1,0), point(1,1,0))", "coplanar"},
      {"circle(point(0,0,0), point(1,0,0), point(2,0,0))", "collinear"},
      {"pair(point(1,2,3), point(1,2,3))", "coincide"},
      {"radius(line(point(0,0,0), point(1,0,0)))", "no centre"},
      {"normal(sphere(point(0,0,0), 1))", "normal() reads planes and circles"},
      {"sphere(e1 + ei, 1)", "must be a point"},
      {"sphere(point(0,0,0), -1)", "the radius must be zero or positive"},
      {"pair(point(1,2,3))", "pair() takes 2 arguments, got 1"},
  };
  for (const auto& b : bad) {
    const CliRun r = calc("--algebra cga3 " + quote(b.expr));
    EXPECT_EQ(r.status, 1) << b.expr;
    EXPECT_NE(r.err.find(b.message), std::string::npos) << b.expr << ": " << r.err;
  }
}

// ---- output
// --------------------------------------------------------------------------------------

TEST(Calc, ReadableOutputHidesRoundingResidue) {
  EXPECT_EQ(calc("'point(1,0,0) & point(0,1,0)'").out, "e03 + e31 - e23\n");
  EXPECT_EQ(calc("--algebra cga3 'eo | ei'").out, "-1\n");
  EXPECT_EQ(calc("--algebra 3,0,0 'e1 * e2 - 2*e21 + grade(1 + e123, 3)'").out, "3 e12 + e123\n");
  EXPECT_EQ(calc("'norm(point(1,2,2) & point(1,2,2) + e23)'").out, "1\n");
  EXPECT_EQ(calc("'inorm(point(0,3,4))'").out, "5\n");
  EXPECT_EQ(calc("'log(exp(e12 + e01))'").out, "e01 + e12\n");
  EXPECT_EQ(calc("-- '-e1 + 2'").status, 2);  // '--' is not an option
  EXPECT_EQ(calc("'-e1 + 2'").out, "2 - e1\n");
  EXPECT_EQ(calc("--algebra 9,6,0 'e19AF * e1'").out, "-e9AF\n");
  EXPECT_EQ(calc("--algebra 2,0,0 '(e1 + e2) / (e1 + e2)'").out, "1\n");
  EXPECT_EQ(calc("'0.1 + 0.2'").out, "0.3\n");
  // exp(pi e12) = cos pi + sin pi e12 leaves sin(pi) = 1.2e-16 on e12: hidden in text (below
  // 1e-14 of the largest coefficient), kept in JSON.
  EXPECT_EQ(calc("'exp(pi*e12)'").out, "-1\n");
  EXPECT_EQ(calc("--algebra pga4 'log(exp(0.5*e12 + 0.25*e34 + 2*e01))'").out,
            "2 e01 + 0.5 e12 + 0.25 e34\n");
  const CliRun r = calc("--json 'exp(pi*e12)'");
  const json doc = parse_json(r.out);
  EXPECT_EQ(doc["results"][0]["value"], json({{"1", -1.0}, {"e12", std::sin(std::numbers::pi)}}));
  // A value whose only coefficients are tiny is still printed.
  EXPECT_EQ(calc("'1E-300 * e1'").out, "1e-300 e1\n");
}

TEST(Calc, JsonIsOneDocumentForTheWholeRun) {
  CliRun r = calc("--json 'let a = point(1,0,0); a & point(0,1,0); 0 * e1;  1+2'");
  ASSERT_EQ(r.status, 0) << r.err;
  json doc = parse_json(r.out);  // throws unless the whole output is one document
  EXPECT_EQ(doc["algebra"], "pga3");
  ASSERT_EQ(doc["results"].size(), 3u);
  EXPECT_EQ(doc["results"][0]["value"], json({{"e03", 1.0}, {"e31", 1.0}, {"e23", -1.0}}));
  EXPECT_EQ(doc["results"][0]["expression"], "a & point(0,1,0)");
  EXPECT_EQ(doc["results"][0]["column"], 23);
  EXPECT_TRUE(doc["results"][1]["value"].empty());  // zero is {}
  EXPECT_EQ(doc["results"][2]["value"], json({{"1", 3.0}}));
  EXPECT_EQ(doc["results"][2]["column"], 50);
  EXPECT_FALSE(doc.contains("error"));
  // An error ends the run: the document still parses, with the results so far and the error.
  r = calc("--json", "1 + 1\n2 +\n3\n");
  EXPECT_EQ(r.status, 1);
  doc = parse_json(r.out);
  ASSERT_EQ(doc["results"].size(), 1u);
  EXPECT_EQ(doc["results"][0]["line"], 1);
  EXPECT_EQ(doc["error"]["line"], 2);
  EXPECT_EQ(doc["error"]["column"], 4);
  EXPECT_EQ(doc["error"]["message"], "unexpected end of expression");
  EXPECT_EQ(r.err, "<stdin>:2:4: error at column 4: unexpected end of expression\n");
  // No statements: an empty list.
  r = calc("--json", "# nothing\n");
  EXPECT_EQ(parse_json(r.out)["results"].size(), 0u);
}

// ---- errors
// ------------------------------------------------------------------------------------------

TEST(Calc, ErrorsNameTheColumn) {
  CliRun r = calc("--algebra pga3 'e1 + e7'");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "pgamesh calc: error at column 6: unknown blade 'e7' in algebra pga3\n");
  r = calc("'(e1 + e2'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("column 9: expected ')'"), std::string::npos) << r.err;
  r = calc("'e1 $ e2'");
  EXPECT_NE(r.err.find("column 4: unexpected character '$'"), std::string::npos) << r.err;
  r = calc("'inverse(e0)'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("column 1: inverse"), std::string::npos) << r.err;
  r = calc("'1 + 2e12'");  // 2·e12 or 2·10¹²? refused; 2E12 and 2e+12 are numbers
  EXPECT_NE(r.err.find("column 5: ambiguous '2e1"), std::string::npos) << r.err;
  EXPECT_EQ(calc("'2E3 + 2e+3 + 1.5e-3'").out, "4000.0015\n");
  r = calc("'grade(e1, 1.5)'");
  EXPECT_NE(r.err.find("column 11: the grade must be an integer"), std::string::npos) << r.err;
  r = calc("--algebra 4,1,0 'point(1,2,3)'");
  EXPECT_NE(r.err.find("point() is not defined in algebra 4,1,0"), std::string::npos) << r.err;
  r = calc("'1E999'");
  EXPECT_NE(r.err.find("out of range"), std::string::npos) << r.err;
  r = calc("'exp'");
  EXPECT_NE(r.err.find("function 'exp' needs its arguments in parentheses"), std::string::npos);
  r = calc("'nope(1)'");
  EXPECT_NE(r.err.find("column 1: unknown function 'nope'"), std::string::npos) << r.err;
  r = calc("'1 + log(1, 2)'");
  EXPECT_NE(r.err.find("column 5: log() takes 1 argument, got 2"), std::string::npos) << r.err;
  r = calc("'point(1, e1, 2)'");
  EXPECT_NE(r.err.find("column 10: point: a coordinate must be a number"), std::string::npos)
      << r.err;
  r = calc("'1 / (e1 - e1)'");
  EXPECT_NE(r.err.find("column 5: division by zero"), std::string::npos) << r.err;
  r = calc("--algebra nope '1'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown algebra 'nope'"), std::string::npos);
  r = calc("--algebra 20,10,0 '1'");  // more than 24 generators
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(calc("--digits 18 '1'").status, 2);
}

TEST(Calc, ScriptsOnStdinWithLineNumbers) {
  CliRun r = calc("--algebra pga3", "# a comment\nlet a = point(1,0,0)\nlet b = 2 * a; b\nb +\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "2 e032 + 2 e123\n");
  EXPECT_EQ(r.err, "<stdin>:4:4: error at column 4: unexpected end of expression\n");
  r = calc("", "let e1 = 3\n");
  EXPECT_NE(r.err.find("'e1' is a blade"), std::string::npos) << r.err;
  r = calc("", "let sphere = 3\n");
  EXPECT_NE(r.err.find("'sphere' is a blade, constant or function name"), std::string::npos)
      << r.err;
}

TEST(Calc, HelpListsTheFunctionTable) {
  const CliRun r = calc("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* f :
       {"atan2(y, x)", "dual(X)", "hodge(X)", "pow(X, y)", "sphere", "quadric", "tangent_plane"})
    EXPECT_NE(r.out.find(f), std::string::npos) << f;
}

TEST(Calc, HostileInputFailsCleanly) {
  // deep nesting is refused, not a stack overflow
  CliRun r = calc("-", std::string(100000, '(') + "1" + std::string(100000, ')'));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("nested too deeply"), std::string::npos) << r.err.substr(0, 200);
  r = calc("-", std::string(100000, '-') + "1");
  EXPECT_EQ(r.status, 1);
  r = calc("-", "f(" + std::string(100000, '(') + "1");
  EXPECT_EQ(r.status, 1);
  // a long flat sum is fine (evaluated in a loop)
  std::string sum = "0";
  for (int i = 0; i < 20000; ++i) sum += " + e1";
  r = calc("-", sum);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "20000 e1\n");
  // exp of a non-simple bivector with infinite size: an error, not an endless scaling loop
  r = calc("--algebra 4,0,0 'exp(1E308*e12 + 1E308*e34 + 1E308*e13)'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("not finite"), std::string::npos) << r.err;
  r = calc("'pow(e1 + e2, 1E9)'");  // 2^(5e8): not finite
  EXPECT_EQ(r.status, 1);
  // binary junk
  r = calc("-", std::string("\x01\xff\x00garbage", 10));
  EXPECT_EQ(r.status, 1);
  r = calc("--json -", std::string("1;\xff", 3));  // the document stays valid JSON
  EXPECT_EQ(r.status, 1);
  EXPECT_NO_THROW(parse_json(r.out));
}
