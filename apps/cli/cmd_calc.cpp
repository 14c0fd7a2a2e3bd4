// `pgamesh calc`: a calculator on the general Clifford engine (docs/calc.md).
//   pgamesh calc [--algebra NAME] [--json] 'EXPR; let a = EXPR; ...'
//   pgamesh calc [--algebra NAME] [--json] < script        (or EXPR = '-')
#include <cstdio>
#include <cstring>
#include <string>

#include "calc_eval.hpp"
#include "commands.hpp"

namespace pgamesh::cli {

namespace {

constexpr std::size_t max_script_bytes = std::size_t{1} << 24;  // 16 MiB of expressions

void calc_usage(std::FILE* out) {
  std::fprintf(out,
               "usage: pgamesh calc [--algebra NAME] [--json] ['EXPR; let x = EXPR; ...' | -]\n"
               "\n"
               "Evaluates geometric-algebra expressions; without EXPR (or with '-') reads\n"
               "statements from stdin, one per line or separated by ';'.\n"
               "\n"
               "  --algebra NAME  pga2, pga3 (default), pga1..pga6, cga3 (eo, ei), dpga, dcga,\n"
               "                  qcga, or p,q,r (e.g. 4,1,0)\n"
               "  --json          print each result as {\"blade\": coefficient, ...}\n"
               "\n"
               "operators: + - * / (geometric), ^ (outer/meet), & (join), | (inner), ~ (reverse),\n"
               "           ! (dual); ^ & | bind tighter than * and /, which bind tighter than + -\n"
               "functions: exp log sqrt dual undual reverse involute conjugate inverse norm inorm\n"
               "           grade(X,k) lc(A,B) rc(A,B) sp(A,B) cross(A,B) point(x,y[,z...]); pi\n"
               "example:   pgamesh calc --algebra pga3 'point(1,0,0) & point(0,1,0)'\n");
}

}  // namespace

static int run_calc(int argc, char** argv) {
  std::string algebra_name = "pga3";
  bool json = false;
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
      return 1;
    }
    if (r.value) {
      const std::string out = json ? calc.format_json(*r.value) : calc.format(*r.value);
      std::fwrite(out.data(), 1, out.size(), stdout);
      std::fputc('\n', stdout);
    }
  }
  return 0;
}

namespace {
const RegisterCommand registered{
    {"calc", "geometric-algebra calculator: PGA, CGA, quadric models, any R(p,q,r)", run_calc, 80}};
}  // namespace

}  // namespace pgamesh::cli
