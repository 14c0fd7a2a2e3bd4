// The function table of `pgamesh calc` (docs/calc.md, Functions): each entry names a function,
// its arity, the models it applies to and its implementation. calc_functions.cpp holds the
// algebra's own functions (products, duals, exp/log/sqrt/pow, scalar functions, norms, points),
// calc_models.cpp those that call the models layer (spheres, circles, quadrics, …).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "calc_eval.hpp"

namespace pgamesh::cli {

// The arguments of one call, already evaluated, with the columns to report errors at.
struct CallArgs {
  const CalcAlgebra& alg;
  std::string_view name;  // the function
  std::size_t column;     // of the function name
  std::span<const clifford::Multivector> values;
  std::span<const std::size_t> columns;  // of each argument

  std::size_t size() const { return values.size(); }
  const clifford::Multivector& operator[](std::size_t i) const { return values[i]; }
  const clifford::Algebra& algebra() const { return alg.algebra; }

  // Fails at the function's column / at argument i's column.
  [[noreturn]] void fail(const std::string& message) const;
  [[noreturn]] void fail_at(std::size_t i, const std::string& message) const;
  // Argument i as a number; fails naming `what` when it is not a scalar.
  double number(std::size_t i, std::string_view what = "the argument") const;
  // Argument i as a non-negative integer ≤ max.
  int integer(std::size_t i, int max, std::string_view what) const;
};

using CalcFunction = clifford::Multivector (*)(const CallArgs&);

// Bits of CalcModel (1u << model); any_model: every algebra.
inline constexpr unsigned model_bit(CalcModel m) {
  return 1u << static_cast<unsigned>(m);
}
inline constexpr unsigned any_model = ~0u;
inline constexpr unsigned quadric_models =
    model_bit(CalcModel::dpga) | model_bit(CalcModel::dcga) | model_bit(CalcModel::qcga);

struct FunctionInfo {
  std::string_view name;
  std::string_view signature;  // "log(X)"
  std::string_view summary;
  int min_args = 1, max_args = 1;
  unsigned models = any_model;  // where it is defined
  CalcFunction fn = nullptr;
};

// The algebra's own functions (calc_functions.cpp) and the models' (calc_models.cpp).
std::span<const FunctionInfo> general_functions();
std::span<const FunctionInfo> model_functions();

// Every function named `name` (a name may have entries for different models); empty when none.
std::vector<const FunctionInfo*> find_functions(std::string_view name);

// "sphere, circle, …" of the functions defined in the model `m` (for --help and errors).
std::string function_names_for(CalcModel m);

// True when the multivector is a scalar (zero included).
bool is_scalar(const clifford::Multivector& m);

}  // namespace pgamesh::cli
