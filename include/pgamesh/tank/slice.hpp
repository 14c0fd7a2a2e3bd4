// The one place where a triangle is cut by the fuel plane (paper §4d; eqs. 4.11–4.13 as corrected
// in docs/conventions.md §12): the kept part of each triangle is added to the wall sums and its cut
// segment to the free-surface sums. Everything else in the tank layer (naive pass, sorted sweep,
// hierarchy) calls this.
#pragma once

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/tank/free_surface.hpp"

namespace pgamesh::tank {

/// Which side of the plane is kept. The fuel keeps p ∨ v ≤ 0 (vertices on the plane are fuel,
/// docs/conventions.md §12); the ullage keeps p ∨ v > 0, its exact complement, so fuel = tank −
/// ullage also for faces lying in the plane.
enum class Side { fuel, ullage };

/// Where the sums are taken: the wall sums about `reference`; the free-surface sums in `frame`.
/// When the reference is not on the plane, the cone from the reference over the (never built)
/// free surface must be added to get the fuel body: `cone_over_surface` asks fuel_state for it
/// (computed from the free-surface sums, free_surface.hpp).
struct SliceContext {
  Vec3d reference{};
  SurfaceFrame frame;
  bool cone_over_surface = false;
};

struct SliceSums {
  BoundarySums wall;        // the kept triangles and split pieces (the wetted wall)
  FreeSurfaceSums surface;  // the fuel's free surface, from its boundary segments
};

/// s −= t, field by field (the sums are linear in the triangles).
void subtract(BoundarySums& s, const BoundarySums& t);

/// The split vertex on the edge (lo, hi) with heights d_lo ≤ 0 < d_hi:
/// (p∨hi) lo − (p∨lo) hi normalized (eq. 4.11 as in docs/conventions.md §12), evaluated from the
/// lower end so that a vertex on the plane (d_lo = 0) is returned exactly and both triangles of an
/// edge get the same point.
inline Vec3d split_point(Vec3d lo, double d_lo, Vec3d hi, double d_hi) {
  return lo + (d_lo / (d_lo - d_hi)) * (hi - lo);
}

/// A triangle the plane crosses (one or two vertices in the fuel), cut at its odd vertex: `a` is
/// the vertex alone on its side, `ab` and `ac` the split points on its edges to the next and the
/// previous vertex, so (a, ab, ac) keeps the triangle's orientation. The fuel's free surface runs
/// along the cut ac → ab when a is in the fuel and ab → ac otherwise (it closes the fuel wall).
struct CutTriangle {
  Vec3d a, ab, ac;
  bool a_in_fuel = false;
};

/// Cuts the triangle v (heights d = p ∨ v, at least one ≤ 0 and one > 0). Split points are
/// evaluated from their fuel-side end (split_point), so both triangles of an edge agree.
inline CutTriangle cut_triangle(const Vec3d v[3], const double d[3]) {
  const bool in0 = d[0] <= 0, in1 = d[1] <= 0, in2 = d[2] <= 0;
  const bool odd_in = in0 + in1 + in2 == 1;
  const int a = in0 == odd_in ? 0 : (in1 == odd_in ? 1 : 2);
  const int b = a == 2 ? 0 : a + 1, c = a == 0 ? 2 : a - 1;
  auto split = [&](int i, int j) {
    return d[i] <= 0 ? split_point(v[i], d[i], v[j], d[j]) : split_point(v[j], d[j], v[i], d[i]);
  };
  return {v[a], split(a, b), split(a, c), odd_in};
}

/// The fuel's free-surface segment of a cut triangle, in plane coordinates (points relative to
/// the reference, `origin` = o′ − reference).
inline void add_surface_segment(FreeSurfaceSums& s, const SurfaceFrame& frame, Vec3d origin,
                                const CutTriangle& t) {
  const auto p = plane_coordinates(frame, t.ab - origin);
  const auto q = plane_coordinates(frame, t.ac - origin);
  if (t.a_in_fuel)
    add_segment(s, q, p);
  else
    add_segment(s, p, q);
}

/// Adds the kept part of the triangle (v[0], v[1], v[2]) (coordinates relative to the context's
/// reference, CCW seen from outside) with heights d[i] = p ∨ v_i above the plane, its area counted
/// with `area_sign` (tank.hpp, area_sign: −1 for a folded fan triangle).
void add_kept_part(SliceSums& sums, const SliceContext& ctx, Side side, const Vec3d v[3],
                   const double d[3], double area_sign);

}  // namespace pgamesh::tank
