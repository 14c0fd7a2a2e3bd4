// The evaluator of `pgamesh calc` (docs/calc.md): an algebra, the names a script defines with
// `let`, and the evaluation of the expression trees of calc_syntax.hpp on the general Clifford
// engine. Functions come from the table of calc_functions.hpp; numbers are printed by
// calc_print.hpp. Errors carry the 1-based column of the offending token; nothing throws out.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "calc_syntax.hpp"
#include "pgamesh/algebra/clifford.hpp"

namespace pgamesh::cli {

// The geometric model an algebra carries: how `point(...)` embeds Euclidean coordinates and
// which model functions (sphere, quadric, …) apply.
enum class CalcModel { none, pga, cga, dpga, dcga, qcga };

struct CalcAlgebra {
  std::string name;
  clifford::Algebra algebra;
  CalcModel model = CalcModel::none;
  int point_dimension = 0;  // coordinates point() takes
  bool degenerate = false;  // has null generators in a diagonal form (PGA): coefficient norms
};

// The algebra for `--algebra NAME` (presets or "p,q,r"); nullopt when unknown.
std::optional<CalcAlgebra> calc_algebra(std::string_view name);

struct CalcError {
  std::size_t column = 0;  // 1-based column in the statement
  std::string message;
};

// Result of one statement: a value to print, nothing (a `let`), or an error.
struct CalcResult {
  std::optional<clifford::Multivector> value;
  std::optional<CalcError> error;
};

class Calculator {
 public:
  explicit Calculator(CalcAlgebra algebra) : alg_(std::move(algebra)) {}

  // Evaluates one statement: `let NAME = EXPR` or `EXPR`.
  CalcResult run(std::string_view statement);

  const CalcAlgebra& algebra() const { return alg_; }

 private:
  clifford::Multivector eval(const Expr& e, std::size_t depth = 0) const;
  clifford::Multivector eval_chain(const Expr& e, std::size_t depth) const;
  clifford::Multivector eval_name(const Expr& e) const;
  clifford::Multivector eval_call(const Expr& e, std::size_t depth) const;

  CalcAlgebra alg_;
  std::map<std::string, clifford::Multivector> names_;
};

// True when NAME is a constant (pi, I) or a function: such names cannot be redefined by `let`.
bool is_reserved_name(std::string_view name);

}  // namespace pgamesh::cli
