// Blade keys of the quadric models: outer products of generators in basis order joined with '^'
// ("w0^w2*", "e1^einf2"), "1" for the scalar — the spelling of the golden files.
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/multivector.hpp"

namespace pgamesh::quadric::detail {

inline std::string blade_key(clifford::BladeMask mask, std::span<const char* const> names) {
  if (mask == 0) return "1";
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (mask >> i & 1u) {
      if (!out.empty()) out += '^';
      out += names[i];
    }
  return out;
}

inline std::vector<std::pair<std::string, double>> named_terms(const clifford::Multivector& x,
                                                               std::span<const char* const> names) {
  std::vector<std::pair<std::string, double>> out;
  for (const clifford::Term& t : x.terms)
    if (t.coeff != 0) out.emplace_back(blade_key(t.mask, names), t.coeff);
  return out;
}

}  // namespace pgamesh::quadric::detail
