#include "pgamesh/tank/free_surface.hpp"

#include <cmath>
#include <limits>

namespace pgamesh::tank {

FreeSurfaceSums& FreeSurfaceSums::operator+=(const FreeSurfaceSums& o) {
  area2 += o.area2;
  for (int i = 0; i < 2; ++i) first6[i] += o.first6[i];
  for (int i = 0; i < 3; ++i) second24[i] += o.second24[i];
  return *this;
}

SurfaceFrame surface_frame(const FuelPlane& plane, Vec3d near) {
  SurfaceFrame f;
  f.origin = near - height_above(plane, near) * plane.up;
  const Vec3d x{1, 0, 0}, y{0, 1, 0};
  Vec3d a = x - dot(x, plane.up) * plane.up;
  if (length(a) < 1e-6) a = y - dot(y, plane.up) * plane.up;
  f.axis1 = a / length(a);
  f.axis2 = cross(plane.up, f.axis1);
  return f;
}

FreeSurface free_surface(const FreeSurfaceSums& s, const SurfaceFrame& frame) {
  FreeSurface out;
  out.area = s.area2 / 2;
  out.axis1 = frame.axis1;
  out.axis2 = frame.axis2;
  if (out.area == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.centroid = {nan, nan, nan};
    return out;
  }
  const double c1 = s.first6[0] / 6 / out.area, c2 = s.first6[1] / 6 / out.area;
  out.centroid = frame.origin + c1 * frame.axis1 + c2 * frame.axis2;
  // Parallel-axis shift to the centroid.
  out.second = {s.second24[0] / 24 - out.area * c1 * c1, s.second24[1] / 24 - out.area * c2 * c2,
                s.second24[2] / 24 - out.area * c1 * c2};
  return out;
}

BoundarySums cone_over_surface(const FreeSurfaceSums& s, const SurfaceFrame& frame,
                               Vec3d reference) {
  const Vec3d o = frame.origin - reference;
  const Vec3d up = cross(frame.axis1, frame.axis2);
  const double h = dot(o, up);
  const double area = s.area2 / 2;
  // ∫s dA and ∫s sᵀ dA in plane coordinates about o′, then ∫x dA and ∫x xᵀ dA in space.
  const Vec3d g = (s.first6[0] / 6) * frame.axis1 + (s.first6[1] / 6) * frame.axis2;
  const double s11 = s.second24[0] / 24, s22 = s.second24[1] / 24, s12 = s.second24[2] / 24;
  const Vec3d first = area * o + g;
  const Vec3d& a = frame.axis1;
  const Vec3d& b = frame.axis2;
  auto second = [&](int i, int j) {
    return area * o[i] * o[j] + o[i] * g[j] + g[i] * o[j] + s11 * a[i] * a[j] + s22 * b[i] * b[j] +
           s12 * (a[i] * b[j] + b[i] * a[j]);
  };
  BoundarySums c;
  c.volume6 = 2 * h * area;      // 6 V
  c.moment24 = (6 * h) * first;  // 24 ∫r dV
  const double k = 24 * h;       // 120 ∫rrᵀ dV
  c.second120 = {k * second(0, 0), k * second(1, 1), k * second(2, 2),
                 k * second(0, 1), k * second(1, 2), k * second(2, 0)};
  return c;
}

}  // namespace pgamesh::tank
