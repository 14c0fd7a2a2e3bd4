// Double perspective geometric algebra DPGA R(4,4) (Breuils et al. §3.2.2, §6, §8; Goldman–Mann,
// Du–Goldman–Mann): null basis w0…w3, w0*…w3* with w_i·w_j* = ½δ_ij, w_i·w_j = w_i*·w_j* = 0.
// Elements live on the compile-time graded engine for R(4,4) (generators f0…f3 squaring to +1,
// f4…f7 to −1) through the change of basis
//   w_i = ½(f_i + f_(4+i)),   w_i* = ½(f_i − f_(4+i))   (f_i = w_i + w_i*, f_(4+i) = w_i − w_i*),
// and are named in the null basis by nonzero_blades. docs/models-quadrics.md §2.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/algebra/graded.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::dpga {

using quadric::Quadric;
using Algebra = graded::Algebra<4, 4>;
using Vector = graded::Vector<Algebra>;
using Bivector = graded::Bivector<Algebra>;
using Even = graded::Even<Algebra>;

// Null-basis generator names in basis order, as the golden files spell them.
inline constexpr std::array<const char*, 8> generator_names = {"w0",  "w1",  "w2",  "w3",
                                                               "w0*", "w1*", "w2*", "w3*"};

// w_i and w_i* (i = 0…3) as graded vectors.
Vector w(int i);
Vector w_star(int i);

// p = x w0 + y w1 + z w2 + weight w3 and p* = x w0* + y w1* + z w2* + weight w3* (Breuils eq. 31).
Vector point(const Vec3d& p, double weight = 1.0);
Vector dual_point(const Vec3d& p, double weight = 1.0);

// Q = 4a w0*∧w0 + 4b w1*∧w1 + 4c w2*∧w2 + 4j w3*∧w3 + 2d (w0*∧w1 + w1*∧w0) + 2e (w0*∧w2 + w2*∧w0)
//   + 2f (w1*∧w2 + w2*∧w1) + 2g (w0*∧w3 + w3*∧w0) + 2h (…w1, w3…) + 2i (…w2, w3…) (Breuils eq. 34,
// e ↔ xz, f ↔ yz).
Bivector quadric(const Quadric& q);

// Coefficients by the reciprocal operators W^k·Q (Breuils eqs. 57–59; W^1 = w3* ∧ w3).
Quadric coefficients(const Bivector& q);

// F(p) = (p ⌋ Q)·p* computed on the graded engine (Breuils eqs. 35–37).
double value(const Bivector& q, const Vec3d& p);

// The polar plane Π* = Q ⌊ p* (Breuils eq. 38) as its coefficients on w0*…w3*:
// (∂F/∂x, ∂F/∂y, ∂F/∂z, g x + h y + i z + 2j); the tangent plane when F(p) = 0 (then the last
// entry equals −∇F·p).
std::array<double, 4> polar_plane(const Bivector& q, const Vec3d& p);

// The rotor turning x_i towards x_j by theta (i ≠ j in 0…2), acting alike on p and p*:
//   R = exp(−θ (w_i ∧ w_j* − w_j ∧ w_i*))    (Breuils eq. 73 corrected; docs §2.4)
// in closed form: w_i∧w_j* − w_j∧w_i* = ½(f_i f_j − f_(4+i) f_(4+j)), two commuting simple
// bivectors squaring to −1, so R = (cos θ/2 − sin θ/2 f_i f_j)(cos θ/2 + sin θ/2 f_(4+i) f_(4+j)).
Even rotor(int i, int j, double theta);

// 1 + s w_i ∧ w_j* (i ≠ j, 0…3): the element Breuils eq. 73 prints as a "rotor" (s = θ/2). It is a
// SHEAR (x_i += s x_j on points, the transpose inverse on dual points), not a rotation; it is
// offered under this name only. With j = 3 it translates points (but not dual points).
Even shear(int i, int j, double s);

// R Q R̃ (Breuils eq. 72, R R̃ = 1 for rotor()).
Bivector transform(const Even& r, const Bivector& q);

// The quadric rotated by theta in the (x_i, x_j) plane: transform(rotor(i, j, θ), Q).
Bivector rotate(const Bivector& q, int i, int j, double theta);

// Null-basis form of any graded element (the outermorphism f_i ↦ w_i + w_i*, f_(4+i) ↦ w_i − w_i*)
// as a multivector of the engine's "dpga" preset, and the non-zero blades by golden key
// ("w0^w2*", "w0^w2^w0*^w2*", "1").
template <graded::GradeMask G>
clifford::Multivector to_null_basis(const graded::Multivector<Algebra, G>& x);
clifford::Multivector to_null_basis_terms(const clifford::Multivector& orthogonal);
template <graded::GradeMask G>
std::vector<std::pair<std::string, double>> nonzero_blades(
    const graded::Multivector<Algebra, G>& x);
std::vector<std::pair<std::string, double>> nonzero_blades_of(
    const clifford::Multivector& null_basis);

// The engine's DPGA algebra (preset "dpga", null basis).
const clifford::Algebra& algebra();

template <graded::GradeMask G>
clifford::Multivector to_null_basis(const graded::Multivector<Algebra, G>& x) {
  return to_null_basis_terms(graded::to_clifford(x));
}
template <graded::GradeMask G>
std::vector<std::pair<std::string, double>> nonzero_blades(
    const graded::Multivector<Algebra, G>& x) {
  return nonzero_blades_of(to_null_basis(x));
}

}  // namespace pgamesh::dpga
