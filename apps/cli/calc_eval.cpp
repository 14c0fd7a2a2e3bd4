// The evaluator of `pgamesh calc`: algebras, names, operators; functions by table lookup.
#include "calc_eval.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <vector>

#include "calc_functions.hpp"

namespace pgamesh::cli {

using clifford::Multivector;

std::optional<CalcAlgebra> calc_algebra(std::string_view name) {
  auto alg = clifford::make_algebra(name);
  if (!alg) return std::nullopt;
  CalcAlgebra c{std::string(name), std::move(*alg)};
  const auto& sq = c.algebra.orthogonal_squares();
  c.degenerate = c.algebra.is_diagonal() && std::count(sq.begin(), sq.end(), 0.0) > 0;
  const int n = c.algebra.dimension();
  if (c.algebra.is_diagonal() && sq[0] == 0 && std::count(sq.begin(), sq.end(), 0.0) == 1 &&
      std::count(sq.begin(), sq.end(), 1.0) == n - 1) {
    c.model = CalcModel::pga;  // R(d,0,1) with e0 first
    c.point_dimension = n - 1;
  } else if (name == "cga3" || name == "cga") {
    c.model = CalcModel::cga;
    c.point_dimension = 3;
  } else if (name == "dpga") {
    c.model = CalcModel::dpga;
    c.point_dimension = 3;
  } else if (name == "dcga") {
    c.model = CalcModel::dcga;
    c.point_dimension = 3;
  } else if (name == "qcga") {
    c.model = CalcModel::qcga;
    c.point_dimension = 3;
  }
  return c;
}

namespace {

// Runs f, reporting any exception of the engine or the models layer at `column`.
template <class F>
Multivector at_column(std::size_t column, F f) {
  try {
    return f();
  } catch (const CalcFailure&) {
    throw;
  } catch (const std::exception& e) {
    fail_at(column, e.what());
  }
}

}  // namespace

bool is_reserved_name(std::string_view name) {
  return name == "pi" || name == "I" || name == "let" || !find_functions(name).empty();
}

Multivector Calculator::eval(const Expr& e, std::size_t depth) const {
  switch (e.kind) {
    case Expr::Kind::number:
      return clifford::scalar(e.number);
    case Expr::Kind::name:
      return eval_name(e);
    case Expr::Kind::chain:
      return eval_chain(e, depth);
    case Expr::Kind::call:
      return eval_call(e, depth);
    case Expr::Kind::unary: {
      const Multivector x = eval(e.args[0], depth + 1);
      switch (e.text[0]) {
        case '-':
          return -x;
        case '~':
          return clifford::reverse(x);
        case '!':  // the Hodge complement (metric-free); dual() is the metric dual
          return clifford::dual(alg_.algebra, x);
        default:
          return x;
      }
    }
  }
  fail_at(e.column, "internal error: unknown expression");
}

Multivector Calculator::eval_chain(const Expr& e, std::size_t depth) const {
  const clifford::Algebra& a = alg_.algebra;
  Multivector v = eval(e.args[0], depth + 1);
  for (std::size_t k = 0; k < e.ops.size(); ++k) {
    const Multivector r = eval(e.args[k + 1], depth + 1);
    const std::size_t col = e.op_columns[k];
    switch (e.ops[k]) {
      case '+':
        v = v + r;
        break;
      case '-':
        v = v - r;
        break;
      case '*':
        v = clifford::geometric(a, v, r);
        break;
      case '/':
        if (is_scalar(r)) {
          if (r[0] == 0) fail_at(e.args[k + 1].column, "division by zero");
          v = v / r[0];
        } else {
          v = clifford::geometric(a, v, at_column(col, [&] { return clifford::inverse(a, r); }));
        }
        break;
      case '^':
        v = clifford::outer(a, v, r);
        break;
      case '&':
        v = clifford::regressive(a, v, r);
        break;
      case '|':
        v = clifford::inner(a, v, r);
        break;
      default:
        fail_at(col, "internal error: unknown operator");
    }
  }
  return v;
}

Multivector Calculator::eval_name(const Expr& e) const {
  const std::string& n = e.text;
  if (n == "pi") return clifford::scalar(std::numbers::pi);
  if (n == "I") return clifford::pseudoscalar(alg_.algebra);
  if (auto it = names_.find(n); it != names_.end()) return it->second;
  if (auto b = alg_.algebra.parse_blade(n)) return clifford::basis_blade(b->first, b->second);
  if (!find_functions(n).empty())
    fail_at(e.column, "function '" + n + "' needs its arguments in parentheses");
  fail_at(e.column, "unknown blade '" + n + "' in algebra " + alg_.name);
}

Multivector Calculator::eval_call(const Expr& e, std::size_t depth) const {
  const std::vector<const FunctionInfo*> candidates = find_functions(e.text);
  if (candidates.empty()) fail_at(e.column, "unknown function '" + e.text + "'");
  const FunctionInfo* f = nullptr;
  for (const FunctionInfo* c : candidates)
    if (c->models & model_bit(alg_.model)) f = c;
  if (f == nullptr) {
    std::string where;
    for (const FunctionInfo* c : candidates) {
      for (CalcModel m :
           {CalcModel::pga, CalcModel::cga, CalcModel::dpga, CalcModel::dcga, CalcModel::qcga})
        if (c->models & model_bit(m)) {
          static constexpr const char* names[] = {"", "pgaN", "cga3", "dpga", "dcga", "qcga"};
          if (!where.empty()) where += ", ";
          where += names[static_cast<int>(m)];
        }
    }
    fail_at(e.column,
            e.text + "() is not defined in algebra " + alg_.name + " (it is for " + where + ")");
  }
  const int n = static_cast<int>(e.args.size());
  if (n < f->min_args || n > f->max_args) {
    std::string count = std::to_string(f->min_args);
    if (f->max_args != f->min_args)
      count += f->max_args > 1000 ? " or more" : " to " + std::to_string(f->max_args);
    fail_at(e.column, e.text + "() takes " + count + " argument" +
                          (f->min_args == 1 && f->max_args == 1 ? "" : "s") + ", got " +
                          std::to_string(n) + ": " + std::string(f->signature));
  }
  std::vector<Multivector> values;
  std::vector<std::size_t> columns;
  values.reserve(e.args.size());
  for (const Expr& arg : e.args) {
    values.push_back(eval(arg, depth + 1));
    columns.push_back(arg.column);
  }
  const CallArgs args{alg_, e.text, e.column, values, columns};
  return at_column(e.column, [&] { return f->fn(args); });
}

CalcResult Calculator::run(std::string_view statement) {
  try {
    const ParsedStatement s = parse_statement(statement);
    if (!s.let_name.empty()) {
      if (alg_.algebra.parse_blade(s.let_name) || is_reserved_name(s.let_name))
        fail_at(s.let_column, "'" + s.let_name + "' is a blade, constant or function name");
      names_[s.let_name] = eval(s.expr);
      return {};
    }
    return {eval(s.expr), std::nullopt};
  } catch (const CalcFailure& f) {
    return {std::nullopt, CalcError{f.column, f.message}};
  } catch (const std::exception& e) {  // e.g. std::bad_alloc: reported, never escapes
    return {std::nullopt, CalcError{1, e.what()}};
  }
}

}  // namespace pgamesh::cli
