// Reading Euclidean parameters back from conformal objects, in either form, and classifying a
// blade (docs/models-cga.md §5). Every function takes the object and its form: Form::direct for
// outer products of points (OPNS), Form::dual for the IPNS forms (dual_sphere, dual_plane, …, or
// dual(X)). A dual form is read as the direct form undual(x), except the plane, whose dual form
// n̂ + δ e_∞ is read directly (docs/models-cga.md §4 on the orientation this implies).
//
// Rounds (pairs, circles, spheres) are read about their own centre: the element is translated to
// it before the radius is taken, so an object far from the origin loses no more than its
// coefficients already lost (docs/models-cga.md §7).
#pragma once

#include <array>
#include <string>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/cga_algebra.hpp"
#include "pgamesh/models/cga_point.hpp"

namespace pgamesh::cga {

enum class Form { direct, dual };

// Centre and signed squared radius of a round: radius_squared < 0 for an imaginary round
// (imaginary = true, radius = sqrt(−radius_squared)); 0 for a tangent (zero-radius) round.
struct RoundParams {
  Vec3d center;
  double radius_squared = 0;
  double radius = 0;
  bool imaginary = false;
};

// A point pair P1 ∧ P2 (Hitzer eqs. 6, 11, 12): its round parameters (radius = half the
// distance of the points), the unit direction p̂ from p2 to p1 (= −u/|u|) and the components of
// eq. 6, V2 = b + ½ v e_∞ − u e_o − ½ γ N.
struct PairParams {
  RoundParams round;
  Vec3d direction;
  Vec3d u, v;
  double gamma = 0;
  Vec3d b;  // the Euclidean bivector b as (b23, b31, b12)
};

// A line P1 ∧ P2 ∧ e_∞ = m e_∞ + d N (Hitzer eq. 16): direction d (= p2 − p1, unnormalised),
// moment m = p1 ∧ p2 as the cross product p1 × p2, the point nearest the origin (d × m)/|d|².
struct LineParams {
  Vec3d direction;
  Vec3d unit_direction;
  Vec3d moment;
  Vec3d closest_point;
};

// A circle (Hitzer eqs. 24, 27, 31): round parameters, the plane bivector Ic (the e_o∧Ic part,
// Hitzer eq. 24) as (e12, e13, e23) coefficients, its unit normal (Ic23, −Ic13, Ic12)/|Ic|
// (= (p2 − p1) × (p3 − p1) normalised for P1 ∧ P2 ∧ P3) and the carrier plane X ∧ e_∞.
struct CircleParams {
  RoundParams round;
  std::array<double, 3> plane_bivector{};  // e1^e2, e1^e3, e2^e3
  Vec3d normal;
  Quadvector carrier;
};

// A plane: unit normal n̂, signed distance δ from the origin (n̂·x = δ on the plane) and the foot
// of the perpendicular from the origin δ n̂ (Hitzer eqs. 37–39).
struct PlaneParams {
  Vec3d normal;
  double distance = 0;
  Vec3d foot;
};

// What a blade represents (in the form it was given).
enum class Kind {
  zero,
  scalar,
  point,              // null vector with weight (direct form), or its dual
  point_at_infinity,  // a multiple of e_∞
  flat_point,         // up(p) ∧ e_∞
  point_pair,
  imaginary_point_pair,
  tangent,  // a round of zero radius (pair, circle or sphere)
  line,
  circle,
  imaginary_circle,
  plane,
  sphere,
  imaginary_sphere,
  direction,  // a free blade E ∧ e_∞ (no location)
  space,      // the pseudoscalar: all of space
  vector,     // a non-null vector in direct form: no object (its dual is a sphere or plane)
  mixed_grades,
  not_a_blade,
};

const char* kind_name(Kind k);

// ---- on any element (the templates below forward to these) --------------------------------------

RoundParams round_params(const Full& x, Form form = Form::direct);
PairParams pair_params(const Full& x, Form form = Form::direct);
std::array<Vec3d, 2> pair_points(const Full& x, Form form = Form::direct);
LineParams line_params(const Full& x, Form form = Form::direct);
CircleParams circle_params(const Full& x, Form form = Form::direct);
PlaneParams plane_params(const Full& x, Form form = Form::direct);
RoundParams sphere_params(const Full& x, Form form = Form::direct);
Vec3d location(const Full& x, Form form = Form::direct);
Full carrier(const Full& x, Form form = Form::direct);
Kind classify(const Full& x, Form form = Form::direct, double rel = 1e-12);

// Centre, signed squared radius, radius of a round of any grade: the centre is the normalised
// X e_∞ X (the reflection of infinity in the round), ρ² = ⟨X X̂⟩₀ / ⟨(e_∞⌋X)²⟩₀ (Hitzer eqs. 27,
// 52 in one formula for pairs, circles and spheres). Throws ModelError for a flat (no centre).
template <GradeMask G>
RoundParams round_params(const Multivector<G>& x, Form form = Form::direct) {
  return round_params(widen<63>(x), form);
}

// Point pair parameters. Throws ModelError when x is not a pair (grade 2 direct / 3 dual).
template <GradeMask G>
PairParams pair_params(const Multivector<G>& x, Form form = Form::direct) {
  return pair_params(widen<63>(x), form);
}

// The two points of a real pair, larger norm first: P± = (V2 ∓ sqrt(V2²)) (e_∞⌋V2)⁻¹, normalised
// (Hitzer eqs. 7–10 solved without his eq. 9, whose printed sign is wrong and which divides by
// p2² − p1² = 0 for equal norms; docs/models-cga.md §5.2). Throws ModelError for an imaginary
// pair (V2² < 0: no real points). A tangent pair returns its point twice.
template <GradeMask G>
std::array<Vec3d, 2> pair_points(const Multivector<G>& x, Form form = Form::direct) {
  return pair_points(widen<63>(x), form);
}

// Line parameters (Hitzer eqs. 16, 17). Throws ModelError when x is not a line.
template <GradeMask G>
LineParams line_params(const Multivector<G>& x, Form form = Form::direct) {
  return line_params(widen<63>(x), form);
}

// Circle parameters (Hitzer eqs. 24, 27, 31). Throws ModelError when x is not a circle.
template <GradeMask G>
CircleParams circle_params(const Multivector<G>& x, Form form = Form::direct) {
  return circle_params(widen<63>(x), form);
}

// Plane parameters: direct form read as Hitzer eqs. 36–39 (normal ∝ the Hodge dual of the
// e_o∧Ip∧e_∞ part, δ from the p1∧p2∧p3∧e_∞ part); dual form n + δ e_∞ read as it is. Throws
// ModelError when x is not a plane.
template <GradeMask G>
PlaneParams plane_params(const Multivector<G>& x, Form form = Form::direct) {
  return plane_params(widen<63>(x), form);
}

// Sphere parameters (Hitzer eq. 52; dual form: σ² / (σ·e_∞)²). Throws when x is not a sphere.
template <GradeMask G>
RoundParams sphere_params(const Multivector<G>& x, Form form = Form::direct) {
  return sphere_params(widen<63>(x), form);
}

// Where an object is: a point's position, a round's centre, a flat point's point, a line's or
// plane's point nearest the origin. Throws ModelError for other elements.
template <GradeMask G>
Vec3d location(const Multivector<G>& x, Form form = Form::direct) {
  return location(widen<63>(x), form);
}

// The carrier flat X ∧ e_∞ of a round, in direct form: a pair's line, a circle's plane, a
// sphere's whole space (a multiple of the pseudoscalar).
template <GradeMask G>
Full carrier(const Multivector<G>& x, Form form = Form::direct) {
  return carrier(widen<63>(x), form);
}

// The kind of blade x represents. Zero tests are relative: coefficients of x (and of the
// products the test forms) within rel of the largest count as zero.
template <GradeMask G>
Kind classify(const Multivector<G>& x, Form form = Form::direct, double rel = 1e-12) {
  return classify(widen<63>(x), form, rel);
}

// ---- distances ---------------------------------------------------------------------------------

// |x − y| through the conformal inner product (Hitzer eq. 4): sqrt(−2 X·Y). Near the origin; far
// from it subtract the positions instead (docs/models-cga.md §7).
double distance(Vec3d x, Vec3d y);

// Signed distance of x from a plane given in dual form π (n̂·x − δ, positive on the normal's side).
double distance_to_plane(Vec3d x, const Vector& dual_plane);

// Signed distance of x from a sphere given in dual form σ: |x − c| − r (negative inside), from
// X·σ/w = −½(|x − c|² − r²) as −2 (X·σ)/w / (|x − c| + r), which keeps its digits near the surface.
double distance_to_sphere(Vec3d x, const Vector& dual_sphere);

}  // namespace pgamesh::cga
