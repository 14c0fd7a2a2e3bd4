// Volume integrals of a solid from its oriented boundary triangles: the one place where the
// per-face sums of paper Table 1 and §5 (as corrected in docs/conventions.md §8–§10) live.
//
// Each outward (CCW-from-outside) triangle (a, b, c), given relative to a reference point o, adds
// the signed tetrahedron (o, a, b, c) with D = o ∨ a ∨ b ∨ c = o ∨ F = det(a, b, c) = 6 V_tet:
//   volume         V     = (1/6)   Σ D                        paper Table 1, o on the left
//                                                              (docs/conventions.md §8)
//   first moment   ∫r    = (1/24)  Σ D (a + b + c + o)        paper eq. 5.3 with the sign
//                                                              of docs/conventions.md §9
//   second moment  ∫rrᵀ  = (1/120) Σ D (aaᵀ + bbᵀ + ccᵀ + ssᵀ), s = a + b + c
//                                                              pyramid reference eq. 24; the 1/60
//                                                              frame of paper eqs. 5.5/5.6 summed
//                                                              over vertex pairs is this tensor
// The surface sums ride along: area ½ Σ ‖F‖ and the carrier sum Σ F, whose Euclidean norm is twice
// the gap of an open surface (Cor. 4.1).
//
// Coordinates are taken relative to a reference point near the mesh before the carrier is formed,
// which keeps every digit whatever the distance of the mesh from the origin (docs/conventions.md
// §13).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/carrier.hpp"

namespace pgamesh {

// How far the polygon faces summed are from planar (docs/mass-properties.md, "Polygon faces"):
// the faces whose corners leave their mean plane by more than face_planarity_tolerance of the
// face's size, and the largest such deviation. Merged by count and maximum, so the same in any
// order of addition.
struct FacePlanarity {
  std::uint64_t nonplanar_faces = 0;
  double largest_deviation = 0;  // of a corner from its face's mean plane, in length units
  double largest_relative = 0;   // that deviation / the size of its face

  void merge(const FacePlanarity& o) {
    nonplanar_faces += o.nonplanar_faces;
    if (o.largest_relative > largest_relative ||
        (o.largest_relative == largest_relative && o.largest_deviation > largest_deviation)) {
      largest_relative = o.largest_relative;
      largest_deviation = o.largest_deviation;
    }
  }
};

// A face is non-planar when a corner leaves its mean plane by more than this fraction of its size.
// The area of a face bent by δ (relative) differs from its projection's by about δ², so below this
// the choice of surface changes no printed digit; above it the warning says the faces are bent.
inline constexpr double face_planarity_tolerance = 1e-6;

// Raw sums, scaled as accumulated (×2, ×6, ×24, ×120): adding partial sums is reassociation only,
// so sums from several threads combine with +=, in a fixed order for reproducible results.
// T is double, or Double4 for four faces summed side by side (chunked_sums.hpp's lanes).
template <class T>
struct BasicBoundarySums {
  T area2{};                     // Σ ‖F‖ = 2 × area
  pga3::Plane<T> carrier_sum{};  // Σ F
  T volume6{};                   // Σ o ∨ F
  Vec3<T> moment24{};            // Σ (o ∨ F)(a + b + c)
  std::array<T, 6> second120{};  // Σ (o ∨ F)(aaᵀ + bbᵀ + ccᵀ + ssᵀ): xx, yy, zz, xy, yz, zx
  FacePlanarity planarity{};     // of the polygon faces (triangles are planar)

  BasicBoundarySums& operator+=(const BasicBoundarySums& o) {
    area2 += o.area2;
    carrier_sum.e0 += o.carrier_sum.e0;
    carrier_sum.e1 += o.carrier_sum.e1;
    carrier_sum.e2 += o.carrier_sum.e2;
    carrier_sum.e3 += o.carrier_sum.e3;
    volume6 += o.volume6;
    moment24 += o.moment24;
    for (int i = 0; i < 6; ++i) second120[i] += o.second120[i];
    planarity.merge(o.planarity);
    return *this;
  }
};

using BoundarySums = BasicBoundarySums<double>;

// Adds the solid parts of the signed tetrahedron (o, a, b, c) — volume, first and second
// moments, with D = o ∨ F = det(a, b, c) — and returns the carrier F = a ∨ b ∨ c. Coordinates are
// relative to the reference point. The surface parts go through add_face_carrier.
template <class T>
pga3::Plane<T> add_tetrahedron(BasicBoundarySums<T>& s, Vec3<T> a, Vec3<T> b, Vec3<T> c) {
  const pga3::Plane<T> f = triangle_carrier(a, b, c);
  const T d = origin_join(f);
  s.volume6 += d;
  const Vec3<T> sum = a + b + c;
  s.moment24 += d * sum;
  s.second120[0] += d * (a.x * a.x + b.x * b.x + c.x * c.x + sum.x * sum.x);
  s.second120[1] += d * (a.y * a.y + b.y * b.y + c.y * c.y + sum.y * sum.y);
  s.second120[2] += d * (a.z * a.z + b.z * b.z + c.z * c.z + sum.z * sum.z);
  s.second120[3] += d * (a.x * a.y + b.x * b.y + c.x * c.y + sum.x * sum.y);
  s.second120[4] += d * (a.y * a.z + b.y * b.z + c.y * c.z + sum.y * sum.z);
  s.second120[5] += d * (a.z * a.x + b.z * b.x + c.z * c.x + sum.z * sum.x);
  return f;
}

// Adds the surface parts of one face with carrier f: its area ½‖f‖ (paper Table 1; for a
// polygon, f is the sum of its fan carriers and ½‖f‖ the planar polygon area of §4c) and f itself
// to Σ F, whose norm measures the gap (Cor. 4.1). `norm_f` is pga3::norm(f), for a caller that
// needs it elsewhere too (the topology pass sums it twice; one square root serves both).
template <class T>
void add_face_carrier(BasicBoundarySums<T>& s, const pga3::Plane<T>& f, T norm_f) {
  s.area2 += norm_f;
  s.carrier_sum.e0 += f.e0;
  s.carrier_sum.e1 += f.e1;
  s.carrier_sum.e2 += f.e2;
  s.carrier_sum.e3 += f.e3;
}

// The same with the norm of f computed here.
template <class T>
void add_face_carrier(BasicBoundarySums<T>& s, const pga3::Plane<T>& f) {
  add_face_carrier(s, f, pga3::norm(f));
}

// Adds the triangle (a, b, c) as add_triangle below does, and also gives the norm ‖F‖ of its
// carrier in `norm_f`, for a caller that sums it again (the topology pass's face tally): one
// square root serves both.
template <class T>
pga3::Plane<T> add_triangle(BasicBoundarySums<T>& s, Vec3<T> a, Vec3<T> b, Vec3<T> c, T& norm_f) {
  const pga3::Plane<T> f = add_tetrahedron(s, a, b, c);
  norm_f = pga3::norm(f);
  add_face_carrier(s, f, norm_f);
  return f;
}

// Adds the triangle (a, b, c), coordinates relative to the reference point, and returns its
// carrier F = a ∨ b ∨ c (for a caller that sums more of it, as the topology pass does).
template <class T>
pga3::Plane<T> add_triangle(BasicBoundarySums<T>& s, Vec3<T> a, Vec3<T> b, Vec3<T> c) {
  T norm_f{};
  return add_triangle(s, a, b, c, norm_f);
}

// The sign with which a fan triangle of a polygon face counts in the face's area
// (docs/conventions.md §6, "Face area of a polygon"): −1 when its normal `triangle_normal` points
// against the face's summed normal `face_normal` (the fan folds back over a concave corner), else
// +1.
inline double fan_area_sign(Vec3d triangle_normal, Vec3d face_normal) {
  return dot(triangle_normal, face_normal) < 0 ? -1.0 : 1.0;
}

// Adds the fan triangle (a, b, c) of a polygon face as add_triangle does, its area counted with
// `area_sign` (fan_area_sign; +1 for a triangle face, which changes no bit).
template <class T>
pga3::Plane<T> add_fan_triangle(BasicBoundarySums<T>& s, Vec3<T> a, Vec3<T> b, Vec3<T> c,
                                T area_sign) {
  const pga3::Plane<T> f = add_tetrahedron(s, a, b, c);
  add_face_carrier(s, f, area_sign * pga3::norm(f));
  return f;
}

// Adds the surface parts of a polygon face of k ≥ 4 corners corner(0), …, corner(k − 1)
// (relative to the reference point) whose fan carriers (corner(0), corner(i), corner(i + 1)) sum
// to f: f itself to Σ F, and to the area the signed fan area Σ_i s_i ‖F_i‖, s_i = fan_area_sign of
// fan triangle i against f (docs/conventions.md §6, "Face area of a polygon"; paper Table 1 for
// ‖F_i‖ as twice a triangle's area). For a planar polygon, concave or not, that is ½‖f‖ (the folded
// triangles take back what the others overcount, paper §4c); for a non-planar one it is the area
// of the fan whose tetrahedra give its volume, which is also what the tank's slices add up
// (docs/mass-properties.md, "Polygon faces"). A face bent beyond face_planarity_tolerance is
// counted in s.planarity with the half-width of the slab its corners span along f's normal (their
// largest distance from the slab's middle plane), relative to the face's size (the largest
// distance from corner 0 to another corner).
template <class CornerAt>
void add_polygon_surface(BoundarySums& s, std::size_t k, const CornerAt& corner,
                         const pga3::Plane<double>& f) {
  const Vec3d n = f.normal();
  const Vec3d a = corner(0);
  Vec3d b = corner(1);
  double area2 = 0, low = 0, high = 0, size2 = 0;
  auto span_corner = [&](Vec3d c) {
    const double h = dot(n, c - a);
    low = std::min(low, h);
    high = std::max(high, h);
    size2 = std::max(size2, dot(c - a, c - a));
  };
  span_corner(b);
  for (std::size_t i = 2; i < k; ++i) {
    const Vec3d c = corner(i);
    // The fan's carriers again: each one's sign needs their sum f, known only after them all.
    const pga3::Plane<double> t = triangle_carrier(a, b, c);
    area2 += fan_area_sign(t.normal(), n) * pga3::norm(t);
    span_corner(c);
    b = c;
  }
  add_face_carrier(s, f, area2);
  const double norm_n = pga3::norm(f), size = std::sqrt(size2);
  if (!(norm_n > 0) || !(size > 0)) return;
  const double deviation = (high - low) / (2 * norm_n);
  if (!(deviation > face_planarity_tolerance * size)) return;
  FacePlanarity bent;
  bent.nonplanar_faces = 1;
  bent.largest_deviation = deviation;
  bent.largest_relative = deviation / size;
  s.planarity.merge(bent);
}

// Adds the polygon of n ≥ 4 corners corner(0), …, corner(n − 1) (relative to the reference point)
// without triangulating it: its carrier is the sum of its boundary-edge carriers joined with its
// first corner v_0 (paper §4c), F = Σ_i (v_i ∨ v_{i+1}) ∨ v_0 = Σ_i v_0 ∨ v_i ∨ v_{i+1}, so the
// solid parts are those of the fan of signed tetrahedra (o, v_0, v_i, v_{i+1}), exact for a planar
// polygon, concave or not (the fan's negative tetrahedra cancel what the positive ones
// overcount); the surface parts are add_polygon_surface's.
template <class CornerAt>
void add_polygon(BoundarySums& s, std::size_t n, const CornerAt& corner) {
  const Vec3d a = corner(0);
  Vec3d b = corner(1);
  pga3::Plane<double> f{};
  for (std::size_t i = 2; i < n; ++i) {
    const Vec3d c = corner(i);
    f += add_tetrahedron(s, a, b, c);
    b = c;
  }
  add_polygon_surface(s, n, corner, f);
}

// The same for corners v[0], …, v[n − 1] in an array.
inline void add_polygon(BoundarySums& s, const Vec3d* v, std::size_t n) {
  add_polygon(s, n, [v](std::size_t i) { return v[i]; });
}

// The moments of the solid at density 1, about the reference point.
struct BodyMoments {
  double area = 0;
  double volume = 0;    // signed: positive for an outward-oriented closed surface
  Vec3d first{};        // ∫ r dV about the reference point
  Mat3 second{};        // ∫ r rᵀ dV about the reference point
  double gap_area = 0;  // ½ ‖Σ F‖ (Cor. 4.1): 0 for a closed surface
};

BodyMoments body_moments(const BoundarySums& s);

// Centre of mass relative to the reference point: ∫r / V (undefined when V = 0).
inline Vec3d centroid(const BodyMoments& m) {
  return m.first / m.volume;
}

// ∫ (r − c)(r − c)ᵀ dV: second moments about the centroid, by the parallel-axis shift.
Mat3 central_second_moment(const BodyMoments& m);

// Inertia tensor from a second-moment matrix M at density ρ: ρ (tr(M) 1 − M), whose off-diagonal
// entries are minus the products of inertia (docs/conventions.md §10, I_xy = −∫xy dm).
Mat3 inertia_from_second_moment(const Mat3& second, double density);

// parallel(r) = |r|² 1 − r rᵀ (pyramid reference eq. 24): I_O = I_C + m parallel(c).
Mat3 parallel_axis(Vec3d r);

}  // namespace pgamesh
