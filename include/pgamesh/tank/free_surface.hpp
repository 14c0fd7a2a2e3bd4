// The free surface (the cut face of the fuel) measured from its boundary only: the split segments
// of the crossing triangles, oriented counter-clockwise seen from above, fanned from a point o′ of
// the plane. This is the 2-D form of the boundary sums (paper Table 1 in R(2,0,1): area
// ½ Σ o′ ∨ E, Green's theorem in the plane); the face itself is never built.
//
// Coordinates on the plane: s = ((x − o′)·axis1, (x − o′)·axis2) with axis1 × axis2 = up, so the
// counter-clockwise sense seen from above is positive.
#pragma once

#include <array>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/tank/fuel_plane.hpp"

namespace pgamesh::tank {

/// A right-handed frame on the fuel plane: origin o′ on the plane, axis1 × axis2 = up.
struct SurfaceFrame {
  Vec3d origin{};
  Vec3d axis1{1, 0, 0}, axis2{0, 1, 0};
};

/// The frame with origin the projection of `near` onto the plane (docs/conventions.md §12: o′ = the
/// foot of the perpendicular from a point near the mesh) and axis1 the tank's x axis projected onto
/// the plane (its y axis when x is within 1e-6 rad of up), axis2 = up × axis1.
SurfaceFrame surface_frame(const FuelPlane& plane, Vec3d near);

/// Plane coordinates of x in the frame (x given as x − o′).
inline std::array<double, 2> plane_coordinates(const SurfaceFrame& f, Vec3d x_minus_origin) {
  return {dot(x_minus_origin, f.axis1), dot(x_minus_origin, f.axis2)};
}

/// Raw sums over the boundary segments (p, q) in plane coordinates, D = det(p, q) = twice the
/// signed area of the fan triangle (o′, p, q):
///   area2 = Σ D,  first6 = Σ D (p + q),  second24 = Σ D (ppᵀ + qqᵀ + (p+q)(p+q)ᵀ)  (11, 22, 12)
/// so that ∫dA = area2/2, ∫s dA = first6/6, ∫ssᵀ dA = second24/24 (triangle (0, p, q)).
struct FreeSurfaceSums {
  double area2 = 0;
  std::array<double, 2> first6{};
  std::array<double, 3> second24{};

  FreeSurfaceSums& operator+=(const FreeSurfaceSums& o);
};

/// Adds the boundary segment p → q (plane coordinates).
inline void add_segment(FreeSurfaceSums& s, std::array<double, 2> p, std::array<double, 2> q) {
  const double d = p[0] * q[1] - p[1] * q[0];
  const double s0 = p[0] + q[0], s1 = p[1] + q[1];
  s.area2 += d;
  s.first6[0] += d * s0;
  s.first6[1] += d * s1;
  s.second24[0] += d * (p[0] * p[0] + q[0] * q[0] + s0 * s0);
  s.second24[1] += d * (p[1] * p[1] + q[1] * q[1] + s1 * s1);
  s.second24[2] += d * (p[0] * p[1] + q[0] * q[1] + s0 * s1);
}

/// Area, centroid and second moments of area of the free surface.
struct FreeSurface {
  double area = 0;   // from the segments (equals ½‖F‖ for a closed tank)
  Vec3d centroid{};  // undefined (NaN) when the area is 0
  Vec3d axis1{}, axis2{};
  /// ∫ s sᵀ dA about the centroid in (axis1, axis2): {∫s1², ∫s2², ∫s1 s2}. ∫s2² is the moment
  /// about the axis through the centroid along axis1 (for axis1 = forward, the transverse
  /// free-surface moment i_T of naval architecture), ∫s1² the moment about axis2 (i_L).
  std::array<double, 3> second{};
};

/// The free surface from its boundary sums.
FreeSurface free_surface(const FreeSurfaceSums& s, const SurfaceFrame& frame);

/// The solid sums (volume6, moment24, second120 of BoundarySums; the surface fields stay 0) of
/// the cone from `reference` over the free surface, from the surface's own moments: the cone
/// {t x : x on the surface, 0 ≤ t ≤ 1} has dV = h t² dt dA with h = (o′ − reference)·up, so
///   V = h A / 3,  ∫r dV = (h/4) ∫x dA,  ∫rrᵀ dV = (h/5) ∫xxᵀ dA   (x relative to the reference),
/// and ∫x dA, ∫xxᵀ dA follow from area2, first6 and second24 with x = (o′ − reference) + s1 axis1 +
/// s2 axis2. This equals the fan of tetrahedra (reference, o′, p, q) over the boundary segments
/// (paper eq. 4.13 with o off the plane) at a constant cost instead of one tetrahedron a segment.
BoundarySums cone_over_surface(const FreeSurfaceSums& s, const SurfaceFrame& frame,
                               Vec3d reference);

}  // namespace pgamesh::tank
