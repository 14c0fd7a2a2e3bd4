// The one place where a triangle is cut by the fuel plane (paper §4d, ERRATA §0.2 and §1 on
// eqs. 4.11–4.13): the kept part of each triangle is added to the wall sums and its cut segment to
// the free-surface sums. Everything else in the tank layer (naive pass, sorted sweep, hierarchy)
// calls this.
#pragma once

#include "pgamesh/algebra/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/tank/free_surface.hpp"

namespace pgamesh::tank {

/// Which side of the plane is kept. The fuel keeps p ∨ v ≤ 0 (vertices on the plane are fuel,
/// ERRATA §0.2); the ullage keeps p ∨ v > 0, its exact complement, so fuel = tank − ullage also
/// for faces lying in the plane.
enum class Side { fuel, ullage };

/// Where the sums are taken: the wall sums about `reference`; the free-surface sums in `frame`.
/// When the reference is not on the plane, the cone from the reference over the (never built)
/// free surface must be added to get the fuel body: `cone_over_surface` asks for it, as a fan of
/// the cut segments from o′.
struct SliceContext {
  Vec3d reference{};
  SurfaceFrame frame;
  bool cone_over_surface = false;
};

struct SliceSums {
  BoundarySums wall;          // the kept triangles and split pieces (the wetted wall)
  FreeSurfaceSums surface;    // the fuel's free surface, from its boundary segments
  BoundarySums surface_cone;  // cone from the reference over the fuel's free surface
};

/// s −= t, field by field (the sums are linear in the triangles).
void subtract(BoundarySums& s, const BoundarySums& t);

/// The split vertex on the edge (lo, hi) with heights d_lo ≤ 0 < d_hi:
/// (p∨hi) lo − (p∨lo) hi normalized (ERRATA on eq. 4.11), evaluated from the lower end so that a
/// vertex on the plane (d_lo = 0) is returned exactly and both triangles of an edge get the same
/// point.
inline Vec3d split_point(Vec3d lo, double d_lo, Vec3d hi, double d_hi) {
  return lo + (d_lo / (d_lo - d_hi)) * (hi - lo);
}

/// Adds the kept part of the triangle (v[0], v[1], v[2]) (coordinates relative to the context's
/// reference, CCW seen from outside) with heights d[i] = p ∨ v_i above the plane.
void add_kept_part(SliceSums& sums, const SliceContext& ctx, Side side, const Vec3d v[3],
                   const double d[3]);

}  // namespace pgamesh::tank
