// Products and functions of the general Clifford engine (conventions: docs/conventions.md §4
// operators). Metric products run in the algebra's orthogonal basis (see algebra.hpp); outer,
// regressive and the duals are metric-free and run on the user's basis.
#pragma once

#include "pgamesh/algebra/clifford/algebra.hpp"

namespace pgamesh::clifford {

// Geometric product A B.
Multivector geometric(const Algebra& alg, const Multivector& a, const Multivector& b);

// Outer (wedge) product A ∧ B — the meet in PGA.
Multivector outer(const Algebra& alg, const Multivector& a, const Multivector& b);

// Left contraction A ⌋ B = Σ ⟨A_r B_s⟩_(s−r) (zero for r > s).
Multivector left_contraction(const Algebra& alg, const Multivector& a, const Multivector& b);

// Right contraction A ⌊ B = Σ ⟨A_r B_s⟩_(r−s) (zero for s > r).
Multivector right_contraction(const Algebra& alg, const Multivector& a, const Multivector& b);

// Scalar product ⟨A B⟩_0.
double scalar_product(const Algebra& alg, const Multivector& a, const Multivector& b);

// Symmetric ("fat dot") inner product Σ ⟨A_r B_s⟩_|r−s| (= ganja.js `|`, docs/conventions.md §4).
Multivector inner(const Algebra& alg, const Multivector& a, const Multivector& b);

// Commutator product A × B = ½ (A B − B A).
Multivector commutator(const Algebra& alg, const Multivector& a, const Multivector& b);

// Hodge (complement) dual: e_J e_J* = I (docs/conventions.md §3; metric-free, works in degenerate
// algebras).
Multivector dual(const Algebra& alg, const Multivector& a);

// Undual A^(−*), with A^(−*) ∧ A = I, so undual(dual(A)) = A.
Multivector undual(const Algebra& alg, const Multivector& a);

// Regressive product (join) A ∨ B = (A* ∧ B*)^(−*) (paper eq. 2.2).
Multivector regressive(const Algebra& alg, const Multivector& a, const Multivector& b);

// The pseudoscalar I = u_0 ∧ … ∧ u_(n−1).
Multivector pseudoscalar(const Algebra& alg);

// Metric dual A I⁻¹ (nondegenerate algebras; throws std::domain_error otherwise).
Multivector metric_dual(const Algebra& alg, const Multivector& a);

// ⟨A Ã⟩_0 — the squared norm of a blade or versor (can be negative in mixed signatures).
double norm_squared(const Algebra& alg, const Multivector& a);

// sqrt |⟨A Ã⟩_0|.
double norm(const Algebra& alg, const Multivector& a);

// Inverse of a versor (or of any A with A Ã a non-zero scalar): Ã / (A Ã). Throws
// std::domain_error when A Ã is not a scalar or is zero.
Multivector inverse(const Algebra& alg, const Multivector& a);

// Sandwich V X Ṽ (motors and rotors act this way, docs/conventions.md §7).
Multivector sandwich(const Algebra& alg, const Multivector& v, const Multivector& x);

// exp(A): closed forms when A² is a scalar (cos/sin, cosh/sinh, 1 + A) or, in R(3,0,1), a scalar
// plus pseudoscalar (screw motion, dual-number angle); in R(d,0,1), 4 ≤ d ≤ 7, pgad::exp's closed
// form in the angle sums of the invariant decomposition (isoclinic planes included); otherwise a
// scaled-and-squared Taylor series.
Multivector exp(const Algebra& alg, const Multivector& a);

// log of a normalised rotor or motor s + B (+ p I): closed forms when B² is a scalar, the screw
// (Study number) form in R(3,0,1), and pgad::log in R(d,0,1), 4 ≤ d ≤ 7 (principal range: rotation
// angles summing to less than π). Throws std::domain_error when no closed form applies or the
// argument is not a normalised motor.
Multivector log(const Algebra& alg, const Multivector& a);

// Square root of a normalised rotor or motor: exp(½ log R).
Multivector sqrt(const Algebra& alg, const Multivector& a);

}  // namespace pgamesh::clifford
