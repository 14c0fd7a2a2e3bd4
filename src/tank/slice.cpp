#include "pgamesh/tank/slice.hpp"

namespace pgamesh::tank {

void subtract(BoundarySums& s, const BoundarySums& t) {
  s.area2 -= t.area2;
  s.carrier_sum.e0 -= t.carrier_sum.e0;
  s.carrier_sum.e1 -= t.carrier_sum.e1;
  s.carrier_sum.e2 -= t.carrier_sum.e2;
  s.carrier_sum.e3 -= t.carrier_sum.e3;
  s.volume6 -= t.volume6;
  s.moment24 -= t.moment24;
  for (int i = 0; i < 6; ++i) s.second120[i] -= t.second120[i];
}

void add_kept_part(SliceSums& sums, const SliceContext& ctx, Side side, const Vec3d v[3],
                   const double d[3], double area_sign) {
  bool kept[3];
  for (int i = 0; i < 3; ++i) kept[i] = side == Side::fuel ? d[i] <= 0 : d[i] > 0;
  const int count = kept[0] + kept[1] + kept[2];
  if (count == 0) return;
  if (count == 3) {
    add_fan_triangle(sums.wall, v[0], v[1], v[2], area_sign);
    return;
  }
  const CutTriangle t = cut_triangle(v, d);
  if ((side == Side::fuel) == t.a_in_fuel) {
    add_fan_triangle(sums.wall, t.a, t.ab, t.ac, area_sign);  // the small piece is kept
  } else {
    // One vertex dropped: the whole triangle minus the small one (paper §4d).
    add_fan_triangle(sums.wall, v[0], v[1], v[2], area_sign);
    BoundarySums small;
    add_fan_triangle(small, t.a, t.ab, t.ac, area_sign);
    subtract(sums.wall, small);
  }
  // Whichever side is kept, the surface sums are those of the fuel's free surface.
  add_surface_segment(sums.surface, ctx.frame, ctx.frame.origin - ctx.reference, t);
}

}  // namespace pgamesh::tank
