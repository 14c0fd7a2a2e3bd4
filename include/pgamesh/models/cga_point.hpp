// Conformal points (docs/models-cga.md §2): up, down, weight, normalisation and the distance read
// from the inner product.
#pragma once

#include <cmath>
#include <string>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::cga {

// X = x + ½ x² e_∞ + e_o (Hitzer eq. 4): X² = 0 and X·Y = −½ |x − y|².
constexpr Vector up(Vec3d x) {
  Vector v;
  v.c = {1.0, x.x, x.y, x.z, 0.5 * dot(x, x)};
  return v;
}

// The weight −X·e_∞ of a vector: its e_o coefficient (1 for an up() point).
constexpr double weight(const Vector& x) {
  return x[eo_mask];
}

// The Euclidean part of a vector (its e1, e2, e3 coefficients), without normalisation.
constexpr Vec3d euclidean(const Vector& x) {
  return {x[e1_mask], x[e2_mask], x[e3_mask]};
}

// X / (−X·e_∞): the point with weight 1. Throws ModelError for a vector without e_o component (a
// point at infinity, a dual plane) or a non-finite weight.
inline Vector normalize_point(const Vector& x) {
  const double w = weight(x);
  if (w == 0 || !std::isfinite(w))
    throw ModelError("cga::normalize_point: the vector has weight " + std::to_string(w) +
                     " (no e_o component: a point at infinity or a dual plane)");
  return x / w;
}

// The Euclidean position of a (possibly scaled) point, Hitzer eq. 5 read through the weight:
// x = (e1, e2, e3 coefficients) / (−X·e_∞). Throws like normalize_point.
inline Vec3d down(const Vector& x) {
  const double w = weight(x);
  if (w == 0 || !std::isfinite(w))
    throw ModelError("cga::down: the vector has weight " + std::to_string(w) +
                     " (no e_o component: a point at infinity or a dual plane)");
  return euclidean(x) / w;
}

// The Euclidean distance of two points from the inner product, |x − y| = sqrt(−2 X·Y / (w_X w_Y))
// (Hitzer eq. 4 with e_o·e_∞ = −1).
inline double point_distance(const Vector& x, const Vector& y) {
  const double d2 = -2.0 * scalar_product(x, y) / (weight(x) * weight(y));
  return std::sqrt(d2 > 0 ? d2 : 0.0);
}

}  // namespace pgamesh::cga
