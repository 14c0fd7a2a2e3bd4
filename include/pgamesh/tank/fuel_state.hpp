// What a fuel query answers: the fuel body (volume, centre of mass, inertia), the wetted wall and
// the free surface, at one level. Density 1: mass = volume, inertia in volume × length² units.
#pragma once

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/tank/free_surface.hpp"
#include "pgamesh/tank/fuel_plane.hpp"
#include "pgamesh/tank/slice.hpp"
#include "pgamesh/tank/tank.hpp"

namespace pgamesh::tank {

struct FuelState {
  FuelPlane plane;
  double volume = 0;
  double fraction = 0;      // volume / tank volume
  bool has_center = false;  // false for an empty tank (no centre of mass)
  Vec3d center_of_mass{};   // absolute coordinates
  Mat3 inertia_com{};       // about the centre of mass (docs/conventions.md §10),
                            // I_xy = −∫xy dV
  double wetted_area = 0;   // tank wall under the fuel
  double surface_area = 0;  // the free surface = gap ½‖F‖ of the kept wall (Cor. 4.1)
  FreeSurface surface;      // centroid and second moments of area of the free surface
  pga3::Plane<double> carrier_sum{};  // F = Σ kept carriers, absolute coordinates
  double ullage_volume = 0;           // tank volume − fuel volume
};

/// Builds the state from the slice sums of the fuel side (or the ullage side: then fuel = tank −
/// ullage for the wall sums). The fuel body is the wall sums plus the cone over the free surface
/// when the reference is off the plane (with o′ on the plane that cone is flat: eq. 4.13).
FuelState fuel_state(const Tank& tank, const FuelPlane& plane, const SliceContext& ctx,
                     const SliceSums& sums, Side side);

/// The reference pass: every triangle cut about o′ = the projection onto the plane of the centre
/// of the fuel-side vertices' box (docs/conventions.md §13: near the kept part; the tank's
/// reference point when no vertex is fuel), eq. 4.13 corrected as in docs/conventions.md §12:
/// V = (1/6) o′ ∨ F, COM from eq. 5.4 corrected. Costs one pass over the vertices (heights) and one
/// over the triangles.
FuelState fuel_naive(const Tank& tank, const FuelPlane& plane);

}  // namespace pgamesh::tank
