#include "mesh/topology/triangle_intersection.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/topology/exact_predicates.hpp"

namespace pgamesh::detail {

namespace {

// An axis along which triangle a, b, c projects to a non-degenerate triangle (its normal's
// largest component first, then the others: the exact test decides). Coplanar points project
// one-to-one along it, so incidences in the plane are those of the projection.
int projection_axis(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d n = cross(b - a, c - a);
  int axes[3] = {0, 1, 2};
  std::sort(axes, axes + 3, [&](int i, int j) { return std::abs(n[i]) > std::abs(n[j]); });
  for (int k : axes)
    if (orient2d_without(k, a, b, c) != 0) return k;
  return axes[0];  // only for collinear corners, which the callers exclude
}

// Whether p lies in the closed triangle a, b, c of the plane without axis `drop`.
bool inside_triangle(int drop, const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const int s = orient2d_without(drop, a, b, c);
  return orient2d_without(drop, a, b, p) * s >= 0 && orient2d_without(drop, b, c, p) * s >= 0 &&
         orient2d_without(drop, c, a, p) * s >= 0;
}

// Whether p lies in the axis-aligned box of segment a b (a point on the segment's line does
// exactly when it lies on the segment).
bool within_segment_box(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
  return true;
}

// Whether the closed segments p q and r s of one plane (projected without axis `drop`) meet.
bool segments_meet(int drop, const Vec3d& p, const Vec3d& q, const Vec3d& r, const Vec3d& s,
                   Vec3d* witness) {
  const int o1 = orient2d_without(drop, p, q, r), o2 = orient2d_without(drop, p, q, s);
  if (o1 * o2 > 0) return false;
  const int o3 = orient2d_without(drop, r, s, p), o4 = orient2d_without(drop, r, s, q);
  if (o3 * o4 > 0) return false;
  if (o1 == 0 && o2 == 0) {  // on one line: they meet when one holds an end of the other
    for (const Vec3d* e : {&r, &s})
      if (within_segment_box(*e, p, q)) {
        if (witness) *witness = *e;
        return true;
      }
    for (const Vec3d* e : {&p, &q})
      if (within_segment_box(*e, r, s)) {
        if (witness) *witness = *e;
        return true;
      }
    return false;
  }
  if (witness) {  // the crossing of the two lines, in doubles
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const double dx = q[i] - p[i], dy = q[j] - p[j], ex = s[i] - r[i], ey = s[j] - r[j];
    const double den = dx * ey - dy * ex;
    const double t = den == 0 ? 0 : ((r[i] - p[i]) * ey - (r[j] - p[j]) * ex) / den;
    *witness = p + (q - p) * std::clamp(t, 0.0, 1.0);
  }
  return true;
}

// Whether the closed segment p q meets the closed triangle a, b, c, both in one plane.
bool coplanar_segment_meets_triangle(const Vec3d& p, const Vec3d& q, const Vec3d& a, const Vec3d& b,
                                     const Vec3d& c, Vec3d* witness) {
  const int drop = projection_axis(a, b, c);
  for (const Vec3d* e : {&p, &q})
    if (inside_triangle(drop, *e, a, b, c)) {
      if (witness) *witness = *e;
      return true;
    }
  return segments_meet(drop, p, q, a, b, witness) || segments_meet(drop, p, q, b, c, witness) ||
         segments_meet(drop, p, q, c, a, witness);
}

// Whether the closed segment p q meets the closed triangle a, b, c; op and oq are
// orient3d(a, b, c, p) and orient3d(a, b, c, q).
bool segment_meets_triangle(const Vec3d& p, const Vec3d& q, int op, int oq, const Vec3d& a,
                            const Vec3d& b, const Vec3d& c, Vec3d* witness) {
  if (op * oq > 0) return false;
  if (op == 0 && oq == 0) return coplanar_segment_meets_triangle(p, q, a, b, c, witness);
  // The line p q crosses the plane once; it meets the closed triangle when it passes no edge on
  // the outside: the three orientations agree (zeros allowed).
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  if (!((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0))) return false;
  if (witness) {  // where the segment crosses the plane, in doubles
    const Vec3d n = cross(b - a, c - a);
    const double dp = dot(n, p - a), dq = dot(n, q - a);
    const double t = dp == dq ? 0 : dp / (dp - dq);
    *witness = p + (q - p) * std::clamp(t, 0.0, 1.0);
  }
  return true;
}

int orient_to_plane_of(const IndexedTriangle& t, const Vec3d& p) {
  return orient3d(t.p[0], t.p[1], t.p[2], p);
}

bool unshared_triangles_intersect(const IndexedTriangle& t, const IndexedTriangle& u,
                                  Vec3d* witness) {
  int du[3], dt[3];
  for (int k = 0; k < 3; ++k) du[k] = orient_to_plane_of(t, u.p[k]);
  if ((du[0] > 0 && du[1] > 0 && du[2] > 0) || (du[0] < 0 && du[1] < 0 && du[2] < 0)) return false;
  if (du[0] == 0 && du[1] == 0 && du[2] == 0) {
    // Coplanar: the boundaries cross, or u lies inside t (then its first corner does).
    for (int k = 0; k < 3; ++k)
      if (coplanar_segment_meets_triangle(t.p[k], t.p[(k + 1) % 3], u.p[0], u.p[1], u.p[2],
                                          witness))
        return true;
    if (inside_triangle(projection_axis(t.p[0], t.p[1], t.p[2]), u.p[0], t.p[0], t.p[1], t.p[2])) {
      if (witness) *witness = u.p[0];
      return true;
    }
    return false;
  }
  for (int k = 0; k < 3; ++k) dt[k] = orient_to_plane_of(u, t.p[k]);
  if ((dt[0] > 0 && dt[1] > 0 && dt[2] > 0) || (dt[0] < 0 && dt[1] < 0 && dt[2] < 0)) return false;
  // Not coplanar: the common part is a segment of the planes' line whose ends lie on edges, so
  // an edge of one meets the other.
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    if (segment_meets_triangle(t.p[k], t.p[l], dt[k], dt[l], u.p[0], u.p[1], u.p[2], witness))
      return true;
  }
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    if (segment_meets_triangle(u.p[k], u.p[l], du[k], du[l], t.p[0], t.p[1], t.p[2], witness))
      return true;
  }
  return false;
}

}  // namespace

bool triangles_intersect(const IndexedTriangle& t, const IndexedTriangle& u, Vec3d* witness) {
  int shared = 0;
  int ti[3] = {}, ui[3] = {};  // the shared corners' positions in t and u
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t.v[i] == u.v[j] && shared < 3) {
        ti[shared] = i;
        ui[shared] = j;
        ++shared;
      }
  if (shared >= 3) {  // the same three vertices: the triangles coincide
    if (witness) *witness = (t.p[0] + t.p[1] + t.p[2]) / 3.0;
    return true;
  }
  if (shared == 2) {
    // The planes meet in the shared edge's line unless they coincide; in one plane the triangles
    // overlap when their third corners lie on the same side of the edge (CGAL's test).
    const Vec3d& a = t.p[ti[0]];
    const Vec3d& b = t.p[ti[1]];
    const Vec3d& r = t.p[3 - ti[0] - ti[1]];
    const Vec3d& s = u.p[3 - ui[0] - ui[1]];
    if (orient3d(a, b, r, s) != 0) return false;
    const int drop = projection_axis(a, b, r);
    if (orient2d_without(drop, a, b, r) * orient2d_without(drop, a, b, s) <= 0) return false;
    if (witness) *witness = (a + b) / 2.0;  // on the edge, where the overlap begins
    return true;
  }
  if (shared == 1) {
    // The common part, if more than the vertex, is a segment from it whose far end lies on the
    // edge opposite the vertex in one of the triangles, inside the other.
    const int i = ti[0], j = ui[0];
    const Vec3d& t1 = t.p[(i + 1) % 3];
    const Vec3d& t2 = t.p[(i + 2) % 3];
    const Vec3d& u1 = u.p[(j + 1) % 3];
    const Vec3d& u2 = u.p[(j + 2) % 3];
    return segment_meets_triangle(u1, u2, orient_to_plane_of(t, u1), orient_to_plane_of(t, u2),
                                  t.p[0], t.p[1], t.p[2], witness) ||
           segment_meets_triangle(t1, t2, orient_to_plane_of(u, t1), orient_to_plane_of(u, t2),
                                  u.p[0], u.p[1], u.p[2], witness);
  }
  return unshared_triangles_intersect(t, u, witness);
}

}  // namespace pgamesh::detail
