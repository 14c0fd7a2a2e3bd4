// Versors of CGA (docs/models-cga.md §6): rotor, translator, dilator, their products, and their
// action on any object by the sandwich V X Ṽ.
#pragma once

#include <cmath>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/cga_point.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::cga {

// Blade masks of the bivectors the elementary versors use.
inline constexpr BladeMask e12_mask = 6, e13_mask = 10, e23_mask = 12, eoinf_mask = 17;

// Rotation by +angle (right-handed) about the axis through the origin with direction `axis`:
// R = cos(θ/2) − sin(θ/2) (a_x e23 + a_y e31 + a_z e12), a = axis / |axis| (the Euclidean rotor;
// e31 = −e1∧e3). Throws ModelError for a zero or non-finite axis.
inline Rotor rotor(Vec3d axis, double angle) {
  const double len = length(axis);
  if (!(len > 0) || !std::isfinite(len) || !std::isfinite(angle))
    throw ModelError("cga::rotor: the axis must be a non-zero finite vector and the angle finite");
  const Vec3d a = axis / len;
  const double c = std::cos(0.5 * angle), s = std::sin(0.5 * angle);
  Rotor r;
  r.c[0] = c;
  r.c[static_cast<std::size_t>(Rotor::index_of(e23_mask))] = -s * a.x;
  r.c[static_cast<std::size_t>(Rotor::index_of(e13_mask))] = s * a.y;  // −s a_y e31 = +s a_y e13
  r.c[static_cast<std::size_t>(Rotor::index_of(e12_mask))] = -s * a.z;
  return r;
}

// Translation by t: T = 1 − ½ t e_∞ = 1 − ½ t ∧ e_∞, so T up(x) T̃ = up(x + t).
constexpr Rotor translator(Vec3d t) {
  Rotor r;
  r.c[0] = 1.0;
  r.c[static_cast<std::size_t>(Rotor::index_of(e1_mask | einf_mask))] = -0.5 * t.x;
  r.c[static_cast<std::size_t>(Rotor::index_of(e2_mask | einf_mask))] = -0.5 * t.y;
  r.c[static_cast<std::size_t>(Rotor::index_of(e3_mask | einf_mask))] = -0.5 * t.z;
  return r;
}

// Uniform scaling by s > 0 about the origin: D = cosh(γ/2) + sinh(γ/2) e_o∧e_∞ with γ = ln s,
// i.e. ((s + 1) + (s − 1) e_o∧e_∞) / (2√s); D up(x) D̃ = (1/s) up(s x) (a point of weight 1/s).
// Throws ModelError unless s is positive and finite.
inline Rotor dilator(double s) {
  if (!(s > 0) || !std::isfinite(s))
    throw ModelError("cga::dilator: the scale factor must be positive and finite");
  const double k = 0.5 / std::sqrt(s);
  Rotor r;
  r.c[0] = (s + 1) * k;
  r.c[static_cast<std::size_t>(Rotor::index_of(eoinf_mask))] = (s - 1) * k;
  return r;
}

// Rotation by angle about the axis through `point` with direction `axis`: T R T̃.
inline Versor rotor_about(Vec3d point, Vec3d axis, double angle) {
  return widen<NullBasis::even_grades>(translator(point) * rotor(axis, angle) * translator(-point));
}

// The rigid motion "rotate about the origin, then translate by t": M = T R.
inline Versor motor(Rotor rotation, Vec3d t) {
  return widen<NullBasis::even_grades>(translator(t) * rotation);
}

// Composition: apply b first, then a (a b).
template <GradeMask GA, GradeMask GB>
constexpr Versor compose(const Multivector<GA>& a, const Multivector<GB>& b) {
  return widen<NullBasis::even_grades>(a * b);
}

// Ṽ / ⟨V Ṽ⟩₀: the inverse of a versor. Throws ModelError when V Ṽ is zero.
template <GradeMask G>
Multivector<G> inverse(const Multivector<G>& v) {
  const double n = norm_squared(v);
  if (n == 0 || !std::isfinite(n)) throw ModelError("cga::inverse: V Ṽ is zero or not finite");
  return graded::reverse(v) / n;
}

// V X Ṽ: the versor's action on any object, direct or dual form alike.
template <GradeMask GV, GradeMask GX>
constexpr Multivector<GX> apply(const Multivector<GV>& v, const Multivector<GX>& x) {
  return sandwich(v, x);
}

// The versor's action on a Euclidean point: down(V up(x) Ṽ).
template <GradeMask GV>
Vec3d apply_to_point(const Multivector<GV>& v, Vec3d x) {
  return down(sandwich(v, up(x)));
}

}  // namespace pgamesh::cga
