// `pgamesh calc` end to end: results against golden values (pga_basics.json joins, cga.json outer
// products, the 2-D polygon and the 4-D 5-cell), scripts with `let` on stdin, and the errors for
// bad syntax, unknown blades and hostile input (column numbers, exit codes, no crash).
#include <gtest/gtest.h>

#include <cstdio>

#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::json;
using pgamesh::test::parse_json;

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

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

std::string point_expr(const json& p) {
  std::string s = "point(";
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i) s.push_back(',');
    s.append(num(p[i].get<double>()));
  }
  s.push_back(')');
  return s;
}

::testing::AssertionResult json_matches(const std::string& out, const json& expected,
                                        pgamesh::test::Tolerance t,
                                        const std::map<std::string, std::string>& rename = {}) {
  json got;
  try {
    got = parse_json(out);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "not JSON: " << out;
  }
  std::map<std::string, double> g;
  for (auto it = got.begin(); it != got.end(); ++it) {
    std::string k, part;  // rename whole generator names between '^'
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
    const CliRun r = calc("--algebra pga3 --json", script);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto nl = r.out.find('\n');
    EXPECT_TRUE(json_matches(r.out.substr(0, nl), c["expected"]["line_ab"], t));
    EXPECT_TRUE(json_matches(r.out.substr(nl + 1), c["expected"]["plane_abc"], t));
    ++cases;
  }
  EXPECT_EQ(cases, 4);
}

TEST(Calc, CgaOuterProductsMatchGolden) {
  const json file = pgamesh::test::load_golden("cga.json");
  int cases = 0;
  for (const auto& c : file["cases"]) {
    const std::string id = c["id"];
    std::string expr;
    if (id.rfind("pair_", 0) == 0)
      expr = point_expr(c["input"]["p1"]) + " ^ " + point_expr(c["input"]["p2"]);
    else if (id.rfind("sphere_", 0) == 0 || id.rfind("circle_", 0) == 0) {
      for (const auto& p : c["input"]["points"]) {
        if (!expr.empty()) expr.append(" ^ ");
        expr.append(point_expr(p));
      }
    } else {
      continue;
    }
    const CliRun r = calc("--algebra cga3 --json " + quote(expr));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(json_matches(r.out, c["expected"]["blades"], pgamesh::test::tolerance_of(file, c),
                             {{"ei", "einf"}}))
        << id;
    ++cases;
  }
  EXPECT_GE(cases, 9);
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

TEST(Calc, ReadableOutputAndFunctions) {
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
  EXPECT_EQ(calc("--json '0 * e1'").out, "{}\n");
}

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
  r = calc("--algebra nope '1'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown algebra 'nope'"), std::string::npos);
  r = calc("--algebra 20,10,0 '1'");  // more than 24 generators
  EXPECT_EQ(r.status, 2);
}

TEST(Calc, ScriptsOnStdinWithLineNumbers) {
  CliRun r = calc("--algebra pga3", "# a comment\nlet a = point(1,0,0)\nlet b = 2 * a; b\nb +\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "2 e032 + 2 e123\n");
  EXPECT_EQ(r.err, "<stdin>:4:4: error at column 4: unexpected end of expression\n");
  r = calc("", "let e1 = 3\n");
  EXPECT_NE(r.err.find("'e1' is a blade"), std::string::npos) << r.err;
}

TEST(Calc, HostileInputFailsCleanly) {
  // deep nesting is refused, not a stack overflow
  CliRun r = calc("-", std::string(100000, '(') + "1" + std::string(100000, ')'));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("nested too deeply"), std::string::npos) << r.err.substr(0, 200);
  r = calc("-", std::string(100000, '-') + "1");
  EXPECT_EQ(r.status, 1);
  // a long flat sum is fine
  std::string sum = "0";
  for (int i = 0; i < 20000; ++i) sum += " + e1";
  r = calc("-", sum);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, "20000 e1\n");
  // exp of a non-simple bivector with infinite size: an error, not an endless scaling loop
  r = calc("--algebra 4,0,0 'exp(1E308*e12 + 1E308*e34 + 1E308*e13)'");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("not finite"), std::string::npos) << r.err;
  // binary junk
  r = calc("-", std::string("\x01\xff\x00garbage", 10));
  EXPECT_EQ(r.status, 1);
}
