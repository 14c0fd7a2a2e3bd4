// Simplices in any dimension k ≤ d in PGA R(d,0,1) (paper §4): the carrier S(σk) = v0 ∨ … ∨ vk
// (Def. 4.1), its magnitude ‖S‖ / k! (Def. 4.2) and the same magnitude from the oriented boundary,
// ‖Σ_i (−1)^i v0 ∨ … ∨ v̂i ∨ … ∨ vk‖∞ / k! (Thm 4.1).
#pragma once

#include <span>
#include <stdexcept>

#include "pgamesh/algebra/pgad.hpp"

namespace pgamesh::geometry {

// k! for the small k of simplices.
constexpr double factorial(int k) {
  double f = 1;
  for (int i = 2; i <= k; ++i) f *= i;
  return f;
}

// The carrier v0 ∨ … ∨ vk of the simplex with these vertices (k + 1 = vertices.size() ≥ 1), built
// from the points' embeddings (paper Def. 4.1). Grade d − k.
template <int D>
pgad::Multivector<D> carrier(std::span<const pgad::Vec<D>> vertices) {
  if (vertices.empty() || vertices.size() > static_cast<std::size_t>(D + 1))
    throw std::invalid_argument("carrier: a k-simplex in R(d,0,1) has 1 to d + 1 vertices");
  pgad::Multivector<D> s = pgad::point<D>(vertices[0]);
  for (std::size_t i = 1; i < vertices.size(); ++i) s = pgad::join(s, pgad::point<D>(vertices[i]));
  return s;
}

// Signed sum of the boundary carriers Σ_i (−1)^i S(σk without vi) (the chain ∂σk, paper eq. 4.1).
template <int D>
pgad::Multivector<D> boundary_carrier(std::span<const pgad::Vec<D>> vertices) {
  pgad::Multivector<D> sum{};
  std::vector<pgad::Vec<D>> facet(vertices.size() - 1);
  for (std::size_t skip = 0; skip < vertices.size(); ++skip) {
    for (std::size_t i = 0, j = 0; i < vertices.size(); ++i)
      if (i != skip) facet[j++] = vertices[i];
    const double sign = (skip % 2) ? -1.0 : 1.0;
    sum += sign * carrier<D>(facet);
  }
  return sum;
}

// Magnitude (length, area, volume, …) of a k-simplex: ‖S(σk)‖ / k! (paper Def. 4.2).
template <int D>
double magnitude(std::span<const pgad::Vec<D>> vertices) {
  const int k = static_cast<int>(vertices.size()) - 1;
  return pgad::norm(carrier<D>(vertices)) / factorial(k);
}

// The same magnitude from the boundary: ‖Σ_∂σk S(σk−1)‖∞ / k! (paper Thm 4.1), k ≥ 1.
template <int D>
double magnitude_from_boundary(std::span<const pgad::Vec<D>> vertices) {
  if (vertices.size() < 2) throw std::invalid_argument("magnitude_from_boundary: needs k ≥ 1");
  const int k = static_cast<int>(vertices.size()) - 1;
  return pgad::ideal_norm(boundary_carrier<D>(vertices)) / factorial(k);
}

}  // namespace pgamesh::geometry
