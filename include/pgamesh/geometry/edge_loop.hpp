// Sums of edge carriers along a chain of edges — a boundary loop of an open mesh, or the rim of a
// polygon. The edge carrier is the join a ∨ b (paper eq. 3.10): direction b − a, moment a × b.
// Around a closed loop the directions cancel and the moments sum to twice the loop's vector area,
// ½ Σ a × b (paper §4c, Table 1 "planar polygon area", in 3-D as corrected in docs/conventions.md
// §6: area = ½ ‖Σ E_i‖∞). For a loop that bounds a missing planar patch this is the patch's area;
// for a non-planar loop it is the area of its projection onto the plane it is most spread over.
#pragma once

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

struct EdgeChainSums {
  pga3::Line<double> carrier_sum{};  // Σ a ∨ b
  double length = 0;                 // Σ ‖a ∨ b‖ = Σ |b − a|
};

// Adds the edge a → b, coordinates relative to a reference point near the chain
// (docs/conventions.md §13: the moments a × b keep their digits only when a and b are small
// compared with the chain's size).
inline void add_edge(EdgeChainSums& s, Vec3d a, Vec3d b) {
  const pga3::Line<double> e = pga3::join(pga3::point(a), pga3::point(b));
  s.carrier_sum.e01 += e.e01;
  s.carrier_sum.e02 += e.e02;
  s.carrier_sum.e03 += e.e03;
  s.carrier_sum.e12 += e.e12;
  s.carrier_sum.e31 += e.e31;
  s.carrier_sum.e23 += e.e23;
  s.length += pga3::norm(e);
}

// The vector area ½ Σ a × b: half the ideal part (moment) of the carrier sum. Independent of the
// reference point for a closed chain (its directions sum to zero).
inline Vec3d vector_area(const EdgeChainSums& s) {
  return 0.5 * s.carrier_sum.moment();
}

// ½ ‖Σ E_i‖∞ (docs/conventions.md §6, Table 1 "planar polygon area" in 3-D).
inline double enclosed_area(const EdgeChainSums& s) {
  return 0.5 * pga3::ideal_norm(s.carrier_sum);
}

}  // namespace pgamesh
