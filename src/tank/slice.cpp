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

namespace {

// The fuel's free-surface segment p → q (relative to the reference): boundary sums in the plane
// frame and, when asked, the fan triangle (o′, p, q) of the cone from the reference.
void add_surface_segment(SliceSums& sums, const SliceContext& ctx, Vec3d p, Vec3d q) {
  const Vec3d o = ctx.frame.origin - ctx.reference;
  add_segment(sums.surface, plane_coordinates(ctx.frame, p - o),
              plane_coordinates(ctx.frame, q - o));
  if (ctx.cone_over_surface) add_triangle(sums.surface_cone, o, p, q);
}

}  // namespace

void add_kept_part(SliceSums& sums, const SliceContext& ctx, Side side, const Vec3d v[3],
                   const double d[3]) {
  bool kept[3];
  for (int i = 0; i < 3; ++i) kept[i] = side == Side::fuel ? d[i] <= 0 : d[i] > 0;
  const int count = kept[0] + kept[1] + kept[2];
  if (count == 0) return;
  if (count == 3) {
    add_triangle(sums.wall, v[0], v[1], v[2]);
    return;
  }
  // The split point of the edge i–j, always evaluated from its fuel-side end.
  auto split = [&](int i, int j) {
    return d[i] <= 0 ? split_point(v[i], d[i], v[j], d[j]) : split_point(v[j], d[j], v[i], d[i]);
  };
  // Rotate (keeping the orientation) so that a is the odd vertex: the one kept vertex, or the one
  // dropped vertex.
  const bool odd_kept = count == 1;
  int a = 0;
  while (kept[a] != odd_kept) ++a;
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const Vec3d ab = split(a, b), ac = split(a, c);
  Vec3d cut_from, cut_to;  // the cut edge as the kept wall piece runs along it
  if (odd_kept) {
    add_triangle(sums.wall, v[a], ab, ac);  // the small piece (a, ab, ac)
    cut_from = ab;
    cut_to = ac;
  } else {
    // One vertex dropped: the whole triangle minus the small one (paper §4d).
    add_triangle(sums.wall, v[0], v[1], v[2]);
    BoundarySums small;
    add_triangle(small, v[a], ab, ac);
    subtract(sums.wall, small);
    cut_from = ac;
    cut_to = ab;
  }
  // The free surface closes the fuel: it runs along the fuel wall's cut edges backwards. The
  // ullage wall runs along them forwards.
  if (side == Side::fuel)
    add_surface_segment(sums, ctx, cut_to, cut_from);
  else
    add_surface_segment(sums, ctx, cut_from, cut_to);
}

}  // namespace pgamesh::tank
