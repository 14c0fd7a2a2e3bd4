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

#include <array>
#include <cstddef>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/carrier.hpp"

namespace pgamesh {

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

  BasicBoundarySums& operator+=(const BasicBoundarySums& o) {
    area2 += o.area2;
    carrier_sum.e0 += o.carrier_sum.e0;
    carrier_sum.e1 += o.carrier_sum.e1;
    carrier_sum.e2 += o.carrier_sum.e2;
    carrier_sum.e3 += o.carrier_sum.e3;
    volume6 += o.volume6;
    moment24 += o.moment24;
    for (int i = 0; i < 6; ++i) second120[i] += o.second120[i];
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

// Adds the polygon v[0], …, v[n−1] (n ≥ 3, coordinates relative to the reference point) without
// triangulating it: its carrier is the sum of its boundary-edge carriers joined with v[0]
// (paper §4c), F = Σ_i (v_i ∨ v_{i+1}) ∨ v_0 = Σ_i v_0 ∨ v_i ∨ v_{i+1}, so the solid parts are
// those of the fan of signed tetrahedra (o, v_0, v_i, v_{i+1}) and the area is ½‖F‖. For a planar
// polygon, concave or not, every part is exact (the fan's negative triangles cancel what the
// positive ones overcount). For a non-planar polygon the solid parts are those of the fan about
// v_0 and the area is the norm of its vector area, i.e. the area of its projection onto its mean
// plane (docs/mass-properties.md).
inline void add_polygon(BoundarySums& s, const Vec3d* v, std::size_t n) {
  pga3::Plane<double> f{};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const pga3::Plane<double> t = add_tetrahedron(s, v[0], v[i], v[i + 1]);
    f.e0 += t.e0;
    f.e1 += t.e1;
    f.e2 += t.e2;
    f.e3 += t.e3;
  }
  add_face_carrier(s, f);
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
