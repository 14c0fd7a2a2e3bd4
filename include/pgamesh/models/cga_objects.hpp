// Conformal objects built from points (direct, OPNS form: the outer product of points, X ∧ Y = 0
// for the points Y on it) and from parameters (dual, IPNS form: X · Y = 0), docs/models-cga.md §3.
//
// The point-built constructors return exactly up(a) ∧ up(b) ∧ … (∧ e_∞ for flats) as Hitzer
// writes them, but compute it about the first point (outer product of the points moved by −a,
// then translated back by the sandwich with translator(a)), so objects far from the origin keep
// the digits that the ½ x² terms would otherwise cancel. They throw ModelError for non-finite
// coordinates and for degenerate point sets (coincident, collinear, coplanar).
#pragma once

#include <span>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/cga_point.hpp"

namespace pgamesh::cga {

// ---- direct (OPNS) forms from points -----------------------------------------------------------

// P1 ∧ P2 (Hitzer eq. 6). Throws when the points coincide.
Bivector point_pair(Vec3d p1, Vec3d p2);

// up(p) ∧ e_∞: the flat point at p (weight 1 on e_o∧e_∞).
Bivector flat_point(Vec3d p);

// P1 ∧ P2 ∧ e_∞ (Hitzer eq. 16): direction p2 − p1, moment p1 ∧ p2. Throws when they coincide.
Trivector line(Vec3d p1, Vec3d p2);

// The same element as line(p, p + d): e_o∧d∧e_∞ + (p ∧ d)∧e_∞ (Hitzer eqs. 16, 19). Throws for a
// zero or non-finite direction.
Trivector line_from_point(Vec3d p, Vec3d d);

// P1 ∧ P2 ∧ P3 (Hitzer eq. 20). Throws when the points are coincident or collinear.
Trivector circle(Vec3d p1, Vec3d p2, Vec3d p3);

// P1 ∧ P2 ∧ P3 ∧ e_∞ (Hitzer eq. 36); its unit normal is (p2 − p1) × (p3 − p1) normalised.
// Throws when the points are coincident or collinear.
Quadvector plane(Vec3d p1, Vec3d p2, Vec3d p3);

// P1 ∧ P2 ∧ P3 ∧ P4 (Hitzer eq. 43). Throws when the points are coplanar (or coincident).
Quadvector sphere(Vec3d p1, Vec3d p2, Vec3d p3, Vec3d p4);

// ---- dual (IPNS) forms from parameters ---------------------------------------------------------

// σ = up(c) − ½ r² e_∞, so X·σ = −½(|x − c|² − r²) (the factor of Hitzer eq. 50). A negative
// `radius_squared` gives the imaginary sphere of that signed squared radius.
Vector dual_sphere_r2(Vec3d center, double radius_squared);
// Real sphere of radius r ≥ 0.
Vector dual_sphere(Vec3d center, double radius);

// π = n̂ + δ e_∞ with n̂ = n/|n|: X·π = n̂·x − δ, the plane n̂·x = δ (δ: signed distance from the
// origin along n̂). Throws for a zero or non-finite normal.
Vector dual_plane(Vec3d normal, double distance);

// The circle with centre c, unit normal n̂ and radius r as the meet of its plane and its sphere:
// π ∧ σ with π = dual_plane(n, n̂·c), σ = dual_sphere(c, r) (this order makes circle_params read
// n̂, as for the direct circle_from_center). Throws for a zero normal or negative radius.
Bivector dual_circle(Vec3d center, Vec3d normal, double radius);

// The dual of line_from_point(p, d).
Bivector dual_line(Vec3d p, Vec3d d);

// ---- direct forms from parameters (the undual of the dual forms, oriented as the point-built
// objects read: docs/models-cga.md §4) ---------------------------------------------------------

// undual(dual_sphere(c, r)) = σ I: dual() of it gives σ back.
Quadvector sphere_from_center(Vec3d center, double radius);

// The plane with unit normal n̂ and distance δ, oriented so that plane_params reads n̂ and δ back:
// −undual(dual_plane(n, δ)) (docs/models-cga.md §4 on the sign).
Quadvector plane_from_normal(Vec3d normal, double distance);

// The circle with centre, normal and radius, oriented so that circle_params reads that normal.
Trivector circle_from_center(Vec3d center, Vec3d normal, double radius);

// ---- intersections -----------------------------------------------------------------------------

// The meet of two objects given in dual form: x ∧ y is the dual form of their intersection
// (sphere ∧ sphere → circle, sphere ∧ plane → circle, plane ∧ plane → line, sphere ∧ line → point
// pair, …). Real, tangent or imaginary: classify() says which.
template <GradeMask GA, GradeMask GB>
constexpr auto meet_dual(const Multivector<GA>& x, const Multivector<GB>& y) {
  return x ^ y;
}

// Throws ModelError naming `what` when a coordinate of p is NaN or infinite.
void require_finite(Vec3d p, const char* what);

}  // namespace pgamesh::cga
