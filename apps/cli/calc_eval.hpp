// The expression language of `pgamesh calc` (docs/calc.md): numbers, basis blades by name,
// `+ - * /`, `^ & | ~ !`, parentheses, functions and `let` names, evaluated on the general
// Clifford engine. Errors carry the 1-based column of the offending token; nothing throws out.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pgamesh/algebra/clifford.hpp"

namespace pgamesh::cli {

// How `point(...)` embeds Euclidean coordinates in an algebra.
enum class PointModel { none, pga, cga, dpga, dcga, qcga };

struct CalcAlgebra {
  std::string name;
  clifford::Algebra algebra;
  PointModel model = PointModel::none;
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

  // The readable form "1 + 2 e12 - 0.5 e0123" ("0" for zero).
  std::string format(const clifford::Multivector& m) const;
  // The JSON object {"blade": coefficient, ...} (full precision).
  std::string format_json(const clifford::Multivector& m) const;

  const CalcAlgebra& algebra() const { return alg_; }

 private:
  CalcAlgebra alg_;
  std::map<std::string, clifford::Multivector> names_;
};

// Splits a script into statements at ';' and newlines; each with its 1-based line and the column
// where it starts. Comments run from '#' to the end of the line.
struct Statement {
  std::string text;
  std::size_t line = 1, column = 1;
};
std::vector<Statement> split_statements(std::string_view script);

}  // namespace pgamesh::cli
