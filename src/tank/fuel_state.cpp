#include "pgamesh/tank/fuel_state.hpp"

#include <vector>

#include "pgamesh/core/bounding_box.hpp"

namespace pgamesh::tank {

FuelState fuel_state(const Tank& tank, const FuelPlane& plane, const SliceContext& ctx,
                     const SliceSums& sums, Side side) {
  FuelState st;
  st.plane = plane;
  BoundarySums wall = sums.wall;
  if (side == Side::ullage) {
    wall = tank.total;
    subtract(wall, sums.wall);
  }
  // The wall sums are about ctx.reference; so must the tank total be for the ullage side.
  BoundarySums body = wall;
  if (ctx.cone_over_surface) body += cone_over_surface(sums.surface, ctx.frame, ctx.reference);
  const BodyMoments wm = body_moments(wall);
  const BodyMoments bm = body_moments(body);
  st.volume = bm.volume;
  st.fraction = st.volume / tank.volume;
  st.ullage_volume = tank.volume - st.volume;
  st.wetted_area = wm.area;
  st.surface_area = wm.gap_area;
  st.surface = free_surface(sums.surface, ctx.frame);
  if (st.volume > 0) {
    st.has_center = true;
    st.center_of_mass = ctx.reference + centroid(bm);
    st.inertia_com = inertia_from_second_moment(central_second_moment(bm), 1.0);
  }
  // F about the reference → absolute coordinates: the e0 coefficient is −n·(a − r) per triangle.
  st.carrier_sum = wall.carrier_sum;
  st.carrier_sum.e0 -= dot(wall.carrier_sum.normal(), ctx.reference);
  return st;
}

FuelState fuel_naive(const Tank& tank, const FuelPlane& plane) {
  // The vertices' heights p ∨ v and the box of those in the fuel: o′ is the projection of its
  // centre, so that the pieces are summed about a point near them (docs/conventions.md §13) — about
  // the tank's centre the fan from o′ over a small fill would cancel terms of the tank's size.
  const pga3::Plane<double> p = plane.plane();
  std::vector<double> d(tank.vertices.size());
  Box3 kept;
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = pga3::join(p, pga3::point(tank.vertices[i]));
    if (d[i] <= 0) kept.add(tank.vertices[i]);
  }
  SliceContext ctx;
  ctx.frame = surface_frame(plane, kept.empty() ? tank.reference : kept.centre());
  ctx.reference = ctx.frame.origin;  // o′ on the plane: the free surface adds nothing (eq. 4.13)
  ctx.cone_over_surface = false;
  SliceSums sums;
  for (std::size_t t = 0; t < tank.triangles.size(); ++t) {
    const auto& tri = tank.triangles[t];
    Vec3d v[3];
    double dt[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = tank.vertices[tri[i]] - ctx.reference;
      dt[i] = d[tri[i]];
    }
    add_kept_part(sums, ctx, Side::fuel, v, dt, area_sign(tank, t));
  }
  return fuel_state(tank, plane, ctx, sums, Side::fuel);
}

}  // namespace pgamesh::tank
