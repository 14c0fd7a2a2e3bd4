// Printing the values of `pgamesh calc` (docs/calc.md, Output): the readable form and the JSON
// object of one value (cmd_calc.cpp assembles the document of a whole run).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "json_text.hpp"
#include "pgamesh/algebra/clifford.hpp"

namespace pgamesh::cli {

// The readable form "1 + 2 e12 - 0.5 e0123" in the algebra's basis order ("0" for zero).
// Coefficients with |c| < hide_below · max|c| (rounding residue of cancellations) are left out and
// the others printed with `digits` significant digits (17 = exact round trip).
struct TextFormat {
  int digits = 15;
  double hide_below = 1e-14;
};
std::string format_text(const clifford::Algebra& algebra, const clifford::Multivector& m,
                        const TextFormat& format = {});

// The JSON object {"blade": coefficient, ...} with every non-zero coefficient in full precision
// (json_text prints %.17g; `{}` is zero; a non-finite coefficient is null).
Json format_json(const clifford::Algebra& algebra, const clifford::Multivector& m);

}  // namespace pgamesh::cli
