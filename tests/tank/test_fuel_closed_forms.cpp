// The one-level query against closed forms and exact polyhedral references: boxes at arbitrary
// tilts (inclusion–exclusion over the corners), prisms standing and lying (exact polygon
// clipping), spherical caps on refined icospheres, planes through vertices, edges and faces.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pgamesh/mesh/primitives.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_state.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "tank/tank_test_support.hpp"

using namespace pgamesh;
using namespace pgamesh::tank;
using pgamesh::test::random_unit;

namespace {

FuelState query(const Tank& t, Vec3d up, double level) {
  return fuel_naive(t, fuel_plane(up, level));
}

// Box [−L/2, L/2]³ ∩ {n·x ≤ h} for n with no zero component, by inclusion–exclusion over the
// corners: 1_box = Σ_ε (−1)^|ε| 1_{x ≥ corner_ε} (coordinates flipped so that n > 0); each term is
// the corner simplex of edge lengths s/n_i, s = h − n·corner. Returns volume and first moment.
struct VolMoment {
  double volume = 0;
  Vec3d first{};
  double scale = 0;  // Σ |terms|: the cancellation the reference suffers
};
VolMoment box_cut(Vec3d L, Vec3d n, double h) {
  // Shift to [0, L] and flip axes with n_i < 0 (x_i → L_i − x_i).
  Vec3d lo = -0.5 * L;
  h -= dot(n, lo);
  bool flip[3];
  for (int i = 0; i < 3; ++i) {
    flip[i] = n[i] < 0;
    if (flip[i]) {
      h -= n[i] * L[i];
      n[i] = -n[i];
    }
  }
  VolMoment r;
  for (int e = 0; e < 8; ++e) {
    Vec3d corner{e & 1 ? L.x : 0, e & 2 ? L.y : 0, e & 4 ? L.z : 0};
    const int sign = ((e & 1) + ((e >> 1) & 1) + ((e >> 2) & 1)) % 2 ? -1 : 1;
    const double s = h - dot(n, corner);
    if (s <= 0) continue;
    const double v = s * s * s / (6 * n.x * n.y * n.z);
    r.volume += sign * v;
    r.scale += v;
    r.first += sign * v * (corner + Vec3d{s / (4 * n.x), s / (4 * n.y), s / (4 * n.z)});
  }
  // Back to the original coordinates.
  Vec3d c = r.first / r.volume;
  for (int i = 0; i < 3; ++i)
    if (flip[i]) c[i] = L[i] - c[i];
  r.first = r.volume * (c + lo);
  return r;
}

// Area of the convex polygon P ∩ {a·x ≤ h} in 2-D (Sutherland–Hodgman, then the shoelace).
double clipped_polygon_area(const std::vector<std::array<double, 2>>& poly, std::array<double, 2> a,
                            double h) {
  std::vector<std::array<double, 2>> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& p = poly[i];
    const auto& q = poly[(i + 1) % poly.size()];
    const double dp = a[0] * p[0] + a[1] * p[1] - h, dq = a[0] * q[0] + a[1] * q[1] - h;
    if (dp <= 0) out.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      const double t = dp / (dp - dq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  double area2 = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& p = out[i];
    const auto& q = out[(i + 1) % out.size()];
    area2 += p[0] * q[1] - p[1] * q[0];
  }
  return area2 / 2;
}

}  // namespace

TEST(Primitives, ClosedOutwardWithExactVolumes) {
  const Tank b = make_tank(box(2, 3, 5));
  EXPECT_DOUBLE_EQ(b.volume, 30);
  EXPECT_EQ(b.gap_area, 0);
  for (int n : {3, 7, 32}) {
    const Tank c = make_tank(cylinder(1.5, 2, n, 3));
    EXPECT_NEAR(c.volume, n / 2.0 * 1.5 * 1.5 * std::sin(2 * std::numbers::pi / n) * 2, 1e-13);
    EXPECT_NEAR(c.gap_area, 0, 1e-13);
  }
  double previous_error = 100;
  for (int level = 0; level <= 4; ++level) {
    const Tank s = make_tank(icosphere(level, 2));
    EXPECT_NEAR(s.gap_area, 0, 1e-12);
    const double error = 4.0 / 3 * std::numbers::pi * 8 - s.volume;
    EXPECT_GT(error, 0);  // inscribed
    EXPECT_LT(error, previous_error * 0.35);
    previous_error = error;
  }
  const Tank cap = make_tank(capsule(1, 2, 48, 12));
  EXPECT_NEAR(cap.gap_area, 0, 1e-12);
  const double ideal = std::numbers::pi * 2 + 4.0 / 3 * std::numbers::pi;
  EXPECT_LT(std::abs(cap.volume - ideal) / ideal, 5e-3);
}

TEST(FuelClosedForms, TiltedBoxesAgainstInclusionExclusion) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  const Vec3d L{1.5, 0.7, 2.3};
  const Tank t = make_tank(box(L.x, L.y, L.z));
  for (int k = 0; k < 200; ++k) {
    const Vec3d up = random_unit(rng);
    const LevelRange r = level_range(t, up);
    const double level = r.lowest + uni(rng) * (r.highest - r.lowest);
    const FuelState st = query(t, up, level);
    const VolMoment ref = box_cut(L, up, level);
    ASSERT_NEAR(st.volume, ref.volume, 1e-13 * t.volume + 1e-14 * ref.scale) << k;
    ASSERT_TRUE(st.has_center);
    const Vec3d c = ref.first / ref.volume;
    const double tc = 1e-12 + 1e-14 * ref.scale / ref.volume;
    EXPECT_NEAR(st.center_of_mass.x, c.x, tc) << k;
    EXPECT_NEAR(st.center_of_mass.y, c.y, tc) << k;
    EXPECT_NEAR(st.center_of_mass.z, c.z, tc) << k;
    // dV/dlevel = free-surface area: a central difference of the exact reference volume.
    const double dh = 1e-5 * (r.highest - r.lowest);
    if (level - dh > r.lowest && level + dh < r.highest) {
      const double dv = (box_cut(L, up, level + dh).volume - box_cut(L, up, level - dh).volume);
      EXPECT_NEAR(st.surface_area, dv / (2 * dh), 1e-5 * st.surface_area + 1e-8) << k;
    }
  }
}

TEST(FuelClosedForms, UprightBoxInertiaAndFreeSurfaceMoments) {
  const double a = 2, b = 3, c = 5, fill = 1.25;
  const Tank t = make_tank(box(a, b, c));
  const FuelState st = query(t, {0, 0, 1}, -c / 2 + fill);
  EXPECT_NEAR(st.volume, a * b * fill, 1e-13);
  EXPECT_NEAR(st.center_of_mass.z, -c / 2 + fill / 2, 1e-14);
  const double m = st.volume;
  EXPECT_NEAR(st.inertia_com[0][0], m / 12 * (b * b + fill * fill), 1e-12);
  EXPECT_NEAR(st.inertia_com[1][1], m / 12 * (a * a + fill * fill), 1e-12);
  EXPECT_NEAR(st.inertia_com[2][2], m / 12 * (a * a + b * b), 1e-12);
  EXPECT_NEAR(st.inertia_com[0][1], 0, 1e-13);
  EXPECT_NEAR(st.wetted_area, a * b + 2 * (a + b) * fill, 1e-13);
  EXPECT_NEAR(st.surface_area, a * b, 1e-13);
  // Free surface: the a × b rectangle; axis1 = x, axis2 = y.
  EXPECT_NEAR(st.surface.second[0], b * a * a * a / 12, 1e-13);  // ∫s1²
  EXPECT_NEAR(st.surface.second[1], a * b * b * b / 12, 1e-13);  // ∫s2² (transverse)
  EXPECT_NEAR(st.surface.second[2], 0, 1e-13);
  EXPECT_NEAR(st.surface.centroid.z, -c / 2 + fill, 1e-14);
  EXPECT_EQ(st.surface.axis1.x, 1);
  EXPECT_EQ(st.surface.axis2.y, 1);
}

TEST(FuelClosedForms, TiltedFreeSurfaceRectangle) {
  // Up tilted about x by θ: while the plane cuts only the four side walls, the free surface is an
  // a × b/cosθ rectangle centred on the plane's trace of the box axis.
  const double a = 2, b = 1, c = 6, theta = 0.4;
  const Tank t = make_tank(box(a, b, c));
  const Vec3d up{0, -std::sin(theta), std::cos(theta)};
  const FuelState st = query(t, up, 0.3);
  const double w = b / std::cos(theta);
  EXPECT_NEAR(st.surface_area, a * w, 1e-13);
  EXPECT_NEAR(st.surface.area, a * w, 1e-13);
  EXPECT_NEAR(st.surface.second[0], w * a * a * a / 12, 1e-13);
  EXPECT_NEAR(st.surface.second[1], a * w * w * w / 12, 1e-13);
  EXPECT_NEAR(st.surface.second[2], 0, 1e-13);
  const double zc = 0.3 / std::cos(theta);  // plane meets the z axis at up·(0,0,z) = 0.3
  EXPECT_NEAR(st.surface.centroid.x, 0, 1e-14);
  EXPECT_NEAR(st.surface.centroid.y, 0, 1e-14);
  EXPECT_NEAR(st.surface.centroid.z, zc, 1e-14);
  EXPECT_NEAR(st.volume, a * b * (c / 2 + zc), 1e-12);
}

TEST(FuelClosedForms, StandingAndLyingPrisms) {
  const double r = 0.8, len = 3;
  for (int n : {6, 13, 64}) {
    const Tank t = make_tank(cylinder(r, len, n, 2));
    std::vector<std::array<double, 2>> poly;
    for (int j = 0; j < n; ++j) {
      const double phi = 2 * std::numbers::pi * j / n;
      poly.push_back({r * std::cos(phi), r * std::sin(phi)});
    }
    const double section = clipped_polygon_area(poly, {1, 0}, 10);
    // Standing (axis along up): V = section × height of fuel, COM on the axis.
    for (double fill : {0.1, 1.5, 2.9}) {
      const FuelState st = query(t, {0, 0, 1}, -len / 2 + fill);
      EXPECT_NEAR(st.volume, section * fill, 1e-13);
      EXPECT_NEAR(st.center_of_mass.z, -len / 2 + fill / 2, 1e-13);
      EXPECT_NEAR(st.center_of_mass.x, 0, 1e-13);
      EXPECT_NEAR(st.surface_area, section, 1e-13);
    }
    // Lying (up ⟂ axis, at an angle β in the section plane): V = len × clipped polygon area.
    for (double beta : {0.0, 0.3, 1.0}) {
      const Vec3d up{std::cos(beta), std::sin(beta), 0};
      for (double level : {-0.7, -0.2, 0.0, 0.55}) {
        const FuelState st = query(t, up, level);
        const double exact = len * clipped_polygon_area(poly, {up.x, up.y}, level);
        EXPECT_NEAR(st.volume, exact, 1e-13) << n << " " << beta << " " << level;
      }
    }
  }
  // Against the circle's closed form: segment area r² acos((r−h)/r) − (r−h) √(2rh − h²); error
  // shrinks like 1/n².
  double previous = 1;
  for (int n : {16, 64, 256}) {
    const Tank t = make_tank(cylinder(r, len, n, 1));
    const double h = 0.5;  // fuel depth
    const FuelState st = query(t, {1, 0, 0}, -r + h);
    const double ideal =
        len * (r * r * std::acos((r - h) / r) - (r - h) * std::sqrt(2 * r * h - h * h));
    const double error = std::abs(st.volume - ideal) / ideal;
    EXPECT_LT(error, previous / 10);
    previous = error;
    // Free surface: chord × length.
    EXPECT_NEAR(st.surface_area, len * 2 * std::sqrt(2 * r * h - h * h), 0.05);
  }
  EXPECT_LT(previous, 2e-4);
}

TEST(FuelClosedForms, SphericalCapsConvergeOnRefinedIcospheres) {
  // V(h) = π h² (3r − h)/3, centroid 3(2r − h)²/(4(3r − h)) below the centre.
  const double r = 1.3;
  for (double h : {0.4, 1.3, 2.0}) {
    double prev_v = 1, prev_c = 1;
    for (int level = 2; level <= 5; ++level) {
      const Tank t = make_tank(icosphere(level, r));
      for (Vec3d up : {Vec3d{0, 0, 1}, Vec3d{0.3, -0.5, 0.8}}) {
        up = up / length(up);
        const FuelState st = query(t, up, -r + h);
        const double v = std::numbers::pi * h * h * (3 * r - h) / 3;
        const double depth = 3 * (2 * r - h) * (2 * r - h) / (4 * (3 * r - h));
        const double err_v = std::abs(st.volume - v) / v;
        const double err_c = length(st.center_of_mass + depth * up) / r;
        if (up.z == 1) {
          EXPECT_LT(err_v, prev_v * 0.35) << h << " L" << level;
          EXPECT_LT(err_c, prev_c * 0.35) << h << " L" << level;
          prev_v = err_v;
          prev_c = err_c;
        }
        EXPECT_LT(err_v, 0.1 / (1 << (2 * (level - 2))));
      }
    }
    EXPECT_LT(prev_v, 2e-3);
  }
}

TEST(FuelClosedForms, PlanesThroughVerticesEdgesAndFaces) {
  const Tank t = make_tank(box(1, 1, 1));
  // The bottom face lies in the plane: no volume, the face is wetted and is the free surface
  // (the limit from above: dV/dlevel = 1).
  FuelState st = query(t, {0, 0, 1}, -0.5);
  EXPECT_EQ(st.volume, 0);
  EXPECT_FALSE(st.has_center);
  EXPECT_EQ(st.wetted_area, 1);
  EXPECT_EQ(st.surface_area, 1);
  EXPECT_EQ(st.surface.area, 1);
  // The top face in the plane: full, no free surface.
  st = query(t, {0, 0, 1}, 0.5);
  EXPECT_EQ(st.volume, 1);
  EXPECT_EQ(st.wetted_area, 6);
  EXPECT_EQ(st.surface_area, 0);
  EXPECT_EQ(st.surface.area, 0);
  EXPECT_EQ(st.center_of_mass.z, 0);
  // Below the bottom and above the top.
  EXPECT_EQ(query(t, {0, 0, 1}, -0.6).volume, 0);
  EXPECT_EQ(query(t, {0, 0, 1}, 0.6).volume, 1);
  // A plane through two opposite edges (x + z = 0): exactly half, COM by symmetry.
  const double s = std::sqrt(0.5);
  st = query(t, {s, 0, s}, 0);
  EXPECT_NEAR(st.volume, 0.5, 1e-15);
  EXPECT_NEAR(st.center_of_mass.x, -1.0 / 6, 1e-15);
  EXPECT_NEAR(st.center_of_mass.y, 0, 1e-15);
  EXPECT_NEAR(st.center_of_mass.z, -1.0 / 6, 1e-15);
  EXPECT_NEAR(st.surface_area, std::sqrt(2.0), 1e-15);
  // Through a corner and the diagonal of the opposite... : x + y + z = −1/2 cuts the corner
  // tetrahedron of legs 1 at (−½, −½, −½) exactly through three vertices: V = 1/6.
  const double k = 1 / std::sqrt(3.0);
  st = query(t, {k, k, k}, -0.5 * k);
  EXPECT_NEAR(st.volume, 1.0 / 6, 1e-15);
  EXPECT_NEAR(st.surface_area, std::sqrt(3.0) / 2, 1e-15);
  // Continuity at those planes: levels a hair away give nearly the same answers.
  for (double eps : {1e-12, -1e-12}) {
    const FuelState near = query(t, {k, k, k}, -0.5 * k + eps);
    EXPECT_NEAR(near.volume, st.volume, 1e-11);
    EXPECT_NEAR(near.center_of_mass.x, st.center_of_mass.x, 1e-11);
    EXPECT_NEAR(near.surface_area, st.surface_area, 1e-10);
  }
}

TEST(FuelClosedForms, ConcaveFacesGiveExactVolumesAndCentres) {
  // An L-shaped prism (L area 3, height 1) whose caps are hexagons starting at a corner that does
  // not see the whole L: their fan from the first corner has an inverted triangle, whose signed
  // volume and moments cancel what the others overcount.
  const double l[6][2] = {{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}};
  Mesh m;
  for (int z = 0; z < 2; ++z)
    for (const auto& p : l) m.vertices.push_back({p[0], p[1], double(z)});
  auto face = [&](std::vector<std::uint32_t> c) {
    m.corners.insert(m.corners.end(), c.begin(), c.end());
    m.face_offsets.push_back(static_cast<std::uint32_t>(m.corners.size()));
  };
  face({6, 7, 8, 9, 10, 11});  // top, counter-clockwise from above
  face({0, 5, 4, 3, 2, 1});    // bottom, clockwise from above
  for (std::uint32_t i = 0; i < 6; ++i) face({i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6});
  const Tank t = make_tank(m);
  EXPECT_NEAR(t.volume, 3, 1e-14);
  EXPECT_NEAR(t.gap_area, 0, 1e-14);
  // The folded fan triangle counts negatively in the area as in the volume: two caps of 3 and a
  // rim of 8 × 1, as `pgamesh props` gives (not 2 × 4 + 8, the caps' unsigned fan areas).
  EXPECT_NEAR(t.area, 14, 1e-14);
  const FuelIndex index(t);
  for (const Vec3d up : {Vec3d{0, 0, 1}, Vec3d{0, 1, 0}}) {
    // Half the height along z: half the prism; along y: the rectangle [0,2]×[0,1] of the L.
    const double level = up.z ? 0.5 : 1.0;
    const FuelState half = query(t, up, level);
    EXPECT_NEAR(half.volume, up.z ? 1.5 : 2, 1e-14);
    EXPECT_NEAR(half.surface_area, up.z ? 3 : 1, 1e-14);
    const Vec3d com = up.z ? Vec3d{5.0 / 6, 5.0 / 6, 0.25} : Vec3d{1, 0.5, 0.5};
    EXPECT_NEAR(length(half.center_of_mass - com), 0, 1e-14);
    // Wetted wall along z: the bottom L (3) and half the rim (8 × ½). Along y, below y = 1: the
    // [0,2]×[0,1] parts of both caps (2 + 2), the walls y = 0 (2), x = 2 (1), x = 0 below y = 1
    // (1), and the step y = 1, x ∈ [1,2], which lies in the plane and so is fuel's (1).
    const double wetted = up.z ? 7 : 9;
    EXPECT_NEAR(half.wetted_area, wetted, 1e-14);
    // The hierarchy and the sorted sweep count the folded triangles alike.
    EXPECT_NEAR(index.query(fuel_plane(up, level)).wetted_area, wetted, 1e-14);
    const std::vector<double> levels{level, 2.0};
    const std::vector<FuelState> swept = fuel_sweep(t, up, levels);
    EXPECT_NEAR(swept[0].wetted_area, wetted, 1e-14);
    EXPECT_NEAR(swept[1].wetted_area, 14, 1e-14);
  }
}

TEST(FuelClosedForms, TinyFillsOfAFarBoxAgainstTheExactCorner) {
  // A unit box 1e6 from the origin tilted so that the fuel is a corner tetrahedron of legs
  // s/up_i: V = s³ / (6 up_x up_y up_z), with s = level − up·corner. The reference point near the
  // fuel keeps the fan from cancelling terms of the tank's size (docs/conventions.md §13); what
  // remains is the rounding of the heights up·x − level of absolute coordinates
  // (ulp(1.7e6) = 2.3e-10 against s).
  for (const double offset : {0.0, 1e6}) {
    Mesh m = box(1, 1, 1);
    for (auto& v : m.vertices) v = v + Vec3d{offset, -offset, offset};
    const Tank t = make_tank(m);
    const Vec3d up = unit_up({0.3, 0.5, 0.8});
    const Vec3d corner{offset - 0.5, -offset - 0.5, offset - 0.5};
    for (const double s : {1e-2, 1e-4, 1e-6}) {
      const double level = dot(up, corner) + s;
      // s from the level as stored: its rounding is part of the question asked.
      const long double se =
          static_cast<long double>(level) -
          (static_cast<long double>(up.x) * corner.x + static_cast<long double>(up.y) * corner.y +
           static_cast<long double>(up.z) * corner.z);
      const double exact = static_cast<double>(se * se * se / (6.0L * up.x * up.y * up.z));
      const double heights = 4 * 2.3e-10 * (offset > 0) / s;  // relative error of s
      const Vec3d com = corner + Vec3d{s / (4 * up.x), s / (4 * up.y), s / (4 * up.z)};
      SCOPED_TRACE(offset);
      SCOPED_TRACE(s);
      // The reference pass, the hierarchy and the sweep (before its first whole triangle) all sum
      // a fill made of pieces only about o′ near the fuel.
      const std::vector<double> levels{level, level + 0.5};
      for (const FuelState& f :
           {query(t, up, level), FuelIndex(t).query({up, level}), fuel_sweep(t, up, levels)[0]}) {
        EXPECT_NEAR(f.volume / exact, 1, 1e-9 + 3 * heights);
        EXPECT_NEAR(length(f.center_of_mass - com), 0, 1e-9 * s + 4.7e-10 * (offset > 0));
      }
    }
  }
}
