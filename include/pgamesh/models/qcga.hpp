// Quadric conformal geometric algebra QCGA R(9,6) (Breuils et al. §3.2.3, §7, §8; the point and
// metric of Breuils et al. 2018): basis e1, e2, e3, eo1…eo6, einf1…einf6 with e_i·e_j = δ_ij,
// eo_k·einf_l = −δ_kl and every other product 0. A quadric is the grade-1 dual element q* with
// x·q* = F(x). Elements here are plain arrays of the 15 vector coefficients (the closed forms);
// to_clifford/from_clifford move them to the general engine, where the tests check every closed
// form against the full computation. docs/models-quadrics.md §4.
#pragma once

#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::qcga {

using quadric::Quadric;

// A vector of R(9,6): v[0..2] on e1..e3, v[3..8] on eo1..eo6, v[9..14] on einf1..einf6.
struct Vector {
  std::array<double, 15> v{};
  friend bool operator==(const Vector&, const Vector&) = default;
};

// Generator names in basis order, as the golden files spell them.
inline constexpr std::array<const char*, 15> generator_names = {
    "e1",  "e2",    "e3",    "eo1",   "eo2",   "eo3",   "eo4",  "eo5",
    "eo6", "einf1", "einf2", "einf3", "einf4", "einf5", "einf6"};

// The engine's QCGA algebra (preset "qcga": same generator order; eo_k·einf_l = −δ_kl).
const clifford::Algebra& algebra();

// x·y with the QCGA metric (closed form of the engine's scalar product on vectors).
double inner(const Vector& x, const Vector& y);

// x = x e1 + y e2 + z e3 + ½x² einf1 + ½y² einf2 + ½z² einf3 + xy einf4 + xz einf5 + yz einf6
//     + eo1 + eo2 + eo3 (Breuils 2018; eq. 63 without its stray "w").
Vector point(const Vec3d& p);

// The dual quadric q* with x·q* = F(x): −(2a eo1 + 2b eo2 + 2c eo3 + d eo4 + e eo5 + f eo6)
// + g e1 + h e2 + i e3 − (j/3)(einf1 + einf2 + einf3) (the form of Breuils eq. 74).
Vector dual_quadric(const Quadric& q);

// Coefficients by the reciprocal operators Q^k·q* (Breuils eqs. 60–61). Parts of q* that no
// operator reads (einf4..6, unequal einf1..3) are ignored as the paper's eq. 61 ignores them.
Quadric coefficients(const Vector& qstar);

// x·q* for the embedded point: F(p) (the QCGA point test, Breuils §3.2.3).
double value(const Vector& qstar, const Vec3d& p);

// Normal n_ε = ∇F at p (Breuils eq. 45).
Vec3d normal(const Vector& qstar, const Vec3d& p);

// Tangent plane at p as a QCGA dual plane π* = n + (n·p) e∞, e∞ = ⅓(einf1 + einf2 + einf3), with
// n = ∇F(p) on e1..e3: x·π* = n·x − n·p (Breuils eq. 46 corrected: its offset term is not n·p).
Vector tangent_plane(const Vector& qstar, const Vec3d& p);

// Euclidean point of a (scaled) QCGA point: x̂ = −x/(x·e∞) with e∞ = ⅓(einf1+einf2+einf3)
// (Breuils eq. 62 with the ⅓ it needs), then x = x̂·e1, y = x̂·e2, z = x̂·e3 (eq. 69).
// Throws ModelError when x·e∞ = 0.
Vec3d point_coordinates(const Vector& x);

// The line x(t) = origin + t·direction against q*: the classical quadratic on the coefficients
// (docs/models-quadrics.md §3; Breuils eqs. 47–48 leave the line's orientation unspecified).
quadric::LineIntersection intersect_line(const Vector& qstar, const Vec3d& origin,
                                         const Vec3d& direction);

// The quadric through nine points, Breuils eq. 70 q* = (x1 ∧ … ∧ x9 ∧ I_o^⊳)^*, in closed form
// (the null vector of the 9×10 monomial matrix), scaled to unit coefficient norm with the sign
// rule of quadric::normalized. Throws ModelError for points on a lower-order surface or NaN.
Vector quadric_from_points(std::span<const Vec3d, 9> points);

// The same on the general engine, the full computation of eq. 70: I_o^⊳ = (eo1 − eo2) ∧
// (eo2 − eo3) ∧ eo4 ∧ eo5 ∧ eo6 and X^* = X I⁻¹ (unnormalized; a few ms).
clifford::Multivector quadric_from_points_ga(std::span<const Vec3d, 9> points);

// Engine interop: the vector as a clifford::Multivector of algebra(), and back (throws
// ModelError when the multivector has a part outside grade 1).
clifford::Multivector to_clifford(const Vector& x);
Vector from_clifford(const clifford::Multivector& x);

// Non-zero coefficients by blade name ("e1", "eo4", "einf2"), in basis order.
std::vector<std::pair<std::string, double>> nonzero_blades(const Vector& x);

}  // namespace pgamesh::qcga
