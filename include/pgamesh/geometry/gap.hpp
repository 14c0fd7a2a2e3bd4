// The gap of an open boundary and the volume ambiguity it implies (paper Cor. 4.1,
// docs/conventions.md §6).
//
// For a closed surface the carriers sum to a pure e0 part; for an open one the normal part of Σ F
// is what the holes would contribute if they were capped (with opposite orientation), so
// G = ½ (normal part of Σ F) is the gap's vector area and ½ ‖Σ F‖ = ‖G‖ the gap area. G is also the
// sum of the vector areas of the boundary loops (Stokes), and ‖G‖ is the missing area only when the
// missing faces are coplanar.
//
// The signed volume of an open surface depends on the reference point q it is measured about:
// V(q) = (1/6) Σ q ∨ F_i = (1/6) Σ n_i·(a_i − q). Moving q by d changes it by −(1/3) G·d. V(q) is
// exactly the volume of the closed surface obtained by capping every hole with a fan of triangles
// to the apex q (the fan's tetrahedra about q are flat), which is how the ambiguity is reported.
#pragma once

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// G = ½ (e1, e2, e3 coefficients of Σ F): the gap's vector area; ‖G‖ = BodyMoments::gap_area.
inline Vec3d gap_vector(const BoundarySums& s) {
  return 0.5 * s.carrier_sum.normal();
}

// V(q) for q = reference point + offset: the signed volume about another point, equal to the
// volume enclosed when every hole is capped by a fan to q. Equals body_moments(s).volume for a
// closed surface whatever the offset.
inline double volume_about(const BoundarySums& s, Vec3d offset) {
  return (s.volume6 - dot(s.carrier_sum.normal(), offset)) / 6;
}

}  // namespace pgamesh
