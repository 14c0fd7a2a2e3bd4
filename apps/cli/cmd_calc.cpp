// `pgamesh calc`: a calculator on the general Clifford engine (docs/calc.md).
//   pgamesh calc [--algebra NAME] [--json] [--digits N] 'EXPR; let a = EXPR; ...'
//   pgamesh calc [--algebra NAME] [--json] [--digits N] < script        (or EXPR = '-')
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>

#include "calc_eval.hpp"
#include "calc_functions.hpp"
#include "calc_print.hpp"
#include "commands.hpp"

namespace pgamesh::cli {

namespace {

constexpr std::size_t max_script_bytes = std::size_t{1} << 24;  // 16 MiB of expressions

void calc_usage(std::FILE* out) {
  std::fprintf(
      out,
      "usage: pgamesh calc [--algebra NAME] [--json] [--digits N] ['EXPR; let x = EXPR; ...' | -]\n"
      "\n"
      "Evaluates geometric-algebra expressions; without EXPR (or with '-') reads\n"
      "statements from stdin, one per line or separated by ';'.\n"
      "\n"
      "  --algebra NAME  pga2, pga3 (default), pga1..pga6, cga3 (eo, ei), dpga, dcga,\n"
      "                  qcga, or p,q,r (e.g. 4,1,0)\n"
      "  --json          one JSON document: {\"algebra\", \"results\": [{\"line\", \"column\",\n"
      "                  \"expression\", \"value\": {\"blade\": coefficient, ...}}, ...]}\n"
      "  --digits N      significant digits of the readable output (1..17, default 15)\n"
      "\n"
      "operators: + - * / (geometric), ^ (outer/meet), & (join), | (inner), ~ (reverse),\n"
      "           ! (Hodge complement); ^ & | bind tighter than * and /, then + -\n"
      "constants: pi, I (the pseudoscalar)\n"
      "functions:\n");
  for (const FunctionInfo& f : general_functions())
    std::fprintf(out, "  %-16s %.*s\n", std::string(f.signature).c_str(),
                 static_cast<int>(f.summary.size()), f.summary.data());
  std::fprintf(out, "models (docs/calc.md, Models):\n");
  static constexpr struct {
    CalcModel model;
    const char* name;
  } models[] = {{CalcModel::pga, "pgaN"},
                {CalcModel::cga, "cga3"},
                {CalcModel::dpga, "dpga"},
                {CalcModel::dcga, "dcga"},
                {CalcModel::qcga, "qcga"}};
  for (const auto& m : models)
    std::fprintf(out, "  %-5s %s\n", m.name, function_names_for(m.model).c_str());
  std::fprintf(out,
               "example:   pgamesh calc --algebra pga3 'point(1,0,0) & point(0,1,0)'\n"
               "           pgamesh calc --algebra cga3 'radius(sphere(point(1,0,0), "
               "point(0,1,0), point(-1,0,0), point(0,0,1)))'\n");
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

int run_calc(int argc, char** argv) {
  std::string algebra_name = "pga3";
  bool json = false;
  TextFormat text;
  std::string expr;
  bool have_expr = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      calc_usage(stdout);
      return 0;
    } else if (a == "--json") {
      json = true;
    } else if (a == "--algebra" || a == "-a") {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "pgamesh calc: --algebra needs a name\n");
        return 2;
      }
      algebra_name = argv[++i];
    } else if (a.rfind("--algebra=", 0) == 0) {
      algebra_name = a.substr(10);
    } else if (a == "--digits") {
      const char* v = i + 1 < argc ? argv[++i] : "";
      const auto r = std::from_chars(v, v + std::strlen(v), text.digits);
      if (r.ec != std::errc() || *r.ptr != '\0' || text.digits < 1 || text.digits > 17) {
        std::fprintf(stderr, "pgamesh calc: --digits needs a whole number from 1 to 17\n");
        return 2;
      }
    } else if (!have_expr && a.rfind("--", 0) != 0) {
      expr = a;  // anything but an option, so an expression may start with '-': -e1 + 2
      have_expr = true;
    } else {
      std::fprintf(stderr, "pgamesh calc: unexpected argument '%s'\n", a.c_str());
      calc_usage(stderr);
      return 2;
    }
  }
  auto alg = calc_algebra(algebra_name);
  if (!alg) {
    std::fprintf(stderr,
                 "pgamesh calc: unknown algebra '%s' (pga1..pga6, pga2, pga3, cga3, dpga, dcga, "
                 "qcga, or p,q,r with p+q+r <= %d)\n",
                 algebra_name.c_str(), clifford::Algebra::max_generators);
    return 2;
  }
  const bool from_stdin = !have_expr || expr == "-";
  if (from_stdin) {
    expr.clear();
    char buf[65536];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, stdin)) > 0) {
      expr.append(buf, n);
      if (expr.size() > max_script_bytes) {
        std::fprintf(stderr, "<stdin>: input larger than %zu bytes\n", max_script_bytes);
        return 1;
      }
    }
  }
  Calculator calc(std::move(*alg));
  Json document = Json::object();
  document["algebra"] = calc.algebra().name;
  document["results"] = Json::array();
  int status = 0;
  for (const Statement& s : split_statements(expr)) {
    const CalcResult r = calc.run(s.text);
    if (r.error) {
      const std::size_t column = s.column + r.error->column - 1;
      if (from_stdin)
        std::fprintf(stderr, "<stdin>:%zu:%zu: error at column %zu: %s\n", s.line, column, column,
                     r.error->message.c_str());
      else
        std::fprintf(stderr, "pgamesh calc: error at column %zu: %s\n", column,
                     r.error->message.c_str());
      document["error"] = {{"line", s.line}, {"column", column}, {"message", r.error->message}};
      status = 1;
      break;
    }
    if (!r.value) continue;
    if (json) {
      const std::size_t lead = s.text.find_first_not_of(" \t\r");
      document["results"].push_back({{"line", s.line},
                                     {"column", s.column + (lead == std::string::npos ? 0 : lead)},
                                     {"expression", trimmed(s.text)},
                                     {"value", format_json(calc.algebra().algebra, *r.value)}});
    } else {
      const std::string out = format_text(calc.algebra().algebra, *r.value, text);
      std::fwrite(out.data(), 1, out.size(), stdout);
      std::fputc('\n', stdout);
    }
  }
  if (json) {
    const std::string doc = json_text(document) + "\n";
    std::fwrite(doc.data(), 1, doc.size(), stdout);
  }
  return status;
}

const RegisterCommand registered{
    {"calc", "geometric-algebra calculator: PGA, CGA, quadric models, any R(p,q,r)", run_calc, 80}};

}  // namespace

}  // namespace pgamesh::cli
