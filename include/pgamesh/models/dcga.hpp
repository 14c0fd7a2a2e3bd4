// Double conformal geometric algebra DCGA R(8,2) (Easter–Hitzer; Breuils et al. §3.2.1, §5):
// two CGA copies {eo1, e1, e2, e3, einf1} and {eo2, e4, e5, e6, einf2} with eo_k·einf_k = −1.
// Points are bivectors X = x1 ∧ x2 and quadrics (and some quartics) bivectors Q with Q·X = F(x).
// Elements are multivectors of the general engine (preset "dcga", same generator order).
// docs/models-quadrics.md §3.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/models/quadric.hpp"

namespace pgamesh::dcga {

using clifford::Multivector;
using quadric::Quadric;

// Generator names in basis order, as the golden files spell them.
inline constexpr std::array<const char*, 10> generator_names = {"eo1", "e1", "e2", "e3", "einf1",
                                                                "eo2", "e4", "e5", "e6", "einf2"};

const clifford::Algebra& algebra();

// The CGA point of copy 1 or 2: eo_k + x e + ½|x|² einf_k (Breuils eq. 2).
Multivector cga_point(const Vec3d& p, int copy);
// X = x1 ∧ x2 (Breuils eqs. 3–4).
Multivector point(const Vec3d& p);

// The monomials a DCGA point carries (Breuils eq. 4): the ten of a quadric, then the quartic ones
// r², x r², y r², z r², r⁴ with r² = x² + y² + z².
inline constexpr std::array<std::string_view, 15> monomial_names = {
    "x2", "y2", "z2", "xy", "xz", "yz", "x", "y", "z", "1", "r2", "xr2", "yr2", "zr2", "r4"};

// Extraction operator T_m with T_m·X = m(x) (Breuils eqs. 6–8 for the quadric monomials, e ↔ xz;
// the quartic ones from the components of eq. 4: T_{r²} = −(eo1∧einf2 + einf1∧eo2),
// T_{x r²} = e1∧eo2 + eo1∧e4 (alike for y, z), T_{r⁴} = −4 eo1∧eo2).
Multivector extraction_operator(int monomial);
// Reciprocal operator T^m with T^m·T_n = δ_mn on the quadric monomials (Breuils eqs. 50–51).
Multivector reciprocal_operator(int monomial);
// Differential operators D_x, D_y, D_z (Breuils eq. 13).
Multivector differential_operator(int axis);

// Q = a T_x² + b T_y² + c T_z² + d T_xy + e T_xz + f T_yz + g T_x + h T_y + i T_z + j T_1
// (Breuils eqs. 10, 12 with e ↔ xz, f ↔ yz).
Multivector quadric(const Quadric& q);
// Coefficients by T^m·Q (Breuils eq. 54).
Quadric coefficients(const Multivector& q);

// Q·X on the engine (Breuils eq. 11): F(p) for a quadric, the quartic's value for a quartic.
double value(const Multivector& q, const Vec3d& p);

// ∇F at p by eqs. 14–15: n_k = (D_k × Q)·X, × the commutator product ½(AB − BA).
Vec3d gradient(const Multivector& q, const Vec3d& p);

// Tangent plane Π = (n1 + δ einf1) ∧ (n2 + δ einf2), n1 = ∇F on e1..e3, n2 on e4..e6 (eqs. 15–17)
// with δ = n1·x1 (eq. 18) = n·p: a DCGA plane with Π·X = −(n·x − n·p)² (docs §3.3).
Multivector tangent_plane(const Multivector& q, const Vec3d& p);

// Euclidean coordinates of a (scaled) DCGA point: X̂ = X/(X·T_1) (eq. 55 corrected: the printed
// X/(X·(einf1∧einf2)) gives −X̂), x = T_x·X̂, y = T_y·X̂, z = T_z·X̂ (eq. 56 corrected: X̂·e1 is a
// vector). Throws ModelError when X·T_1 = 0.
Vec3d point_coordinates(const Multivector& x);

// Versors acting on both copies: translation by t, T = T1 T2 with T_k = 1 − ½ t_k einf_k (t_k the
// vector t in copy k), and the rotation turning x_i towards x_j by theta, R = R1 R2 with
// R_k = cos θ/2 − sin θ/2 e_i^(k) e_j^(k). V X(p) Ṽ = X(moved p), so V Q Ṽ is the moved surface
// (for quadrics and quartics alike).
Multivector translator(const Vec3d& t);
Multivector rotor(int i, int j, double theta);
Multivector transform(const Multivector& versor, const Multivector& q);

// ------------------------------------------------------------------------ quartics (eq. 4)
// Σ k_m m(x) over the 15 monomials above.
struct Quartic {
  std::array<double, 15> k{};
};
Quartic from_quadric(const Quadric& q);
double value(const Quartic& s, const Vec3d& p);  // closed form
Multivector quartic(const Quartic& s);           // Σ k_m T_m
// Torus about the z axis through the origin: (r² + R² − ρ²)² − 4R²(x² + y²) = 0 (Easter–Hitzer),
// R the distance of the tube's centre circle from the axis, ρ the tube radius.
Quartic torus(double major_radius, double minor_radius);
// Dupin cyclide (x² + y² + z² + b² − μ²)² − 4(a x − c μ)² − 4 b² y² = 0 with a² = b² + c²
// (Easter–Hitzer's standard form; a > 0, b = √(a² − c²) is computed). Throws ModelError for |c| >
// a.
Quartic dupin_cyclide(double a, double c, double mu);

// Non-zero blades by golden key ("e1^e4", "einf1^einf2").
std::vector<std::pair<std::string, double>> nonzero_blades(const Multivector& x);

}  // namespace pgamesh::dcga
