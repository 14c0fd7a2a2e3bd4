// Mass properties against closed forms and invariances: boxes, tetrahedra, spheres converging to
// 4/3 π r³, concave polygon faces, open meshes whose gap is the missing area, translation and
// rotation invariance, face flips, thread-count independence, density and mass options.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "geometry/chunked_sums.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "support/solids.hpp"

using namespace pgamesh;
using namespace pgamesh::test;

namespace {

void expect_matrix_near(const Mat3& got, const Mat3& expected, double rel) {
  const double tol = rel * max_abs(expected);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[i][j], expected[i][j], tol) << i << "," << j;
}

// R v for the rotation by `angle` about the unit axis a (Rodrigues).
Vec3d rotate(Vec3d v, Vec3d a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(a, v) + (1 - c) * dot(a, v) * a;
}

}  // namespace

TEST(MassClosedForms, BoxOfQuads) {
  const double a = 2, b = 3, c = 5, rho = 7.5;
  MassOptions opt;
  opt.density = rho;
  const MassProperties p = mass_properties(box_mesh(a, b, c), opt);
  EXPECT_EQ(p.faces, 6u);
  EXPECT_EQ(p.triangles, 12u);
  EXPECT_DOUBLE_EQ(p.volume, a * b * c);
  EXPECT_DOUBLE_EQ(p.area, 2 * (a * b + b * c + c * a));
  EXPECT_DOUBLE_EQ(p.mass, rho * a * b * c);
  EXPECT_EQ(p.gap_area, 0);
  EXPECT_NEAR(p.center_of_mass.x, a / 2, 1e-15);
  EXPECT_NEAR(p.center_of_mass.y, b / 2, 1e-15);
  EXPECT_NEAR(p.center_of_mass.z, c / 2, 1e-15);
  const double m = p.mass;
  expect_matrix_near(p.inertia_com,
                     {{{m / 12 * (b * b + c * c), 0, 0},
                       {0, m / 12 * (a * a + c * c), 0},
                       {0, 0, m / 12 * (a * a + b * b)}}},
                     1e-15);
  // About the origin (a corner): I_xx = m/3 (b² + c²), I_xy = −m a b / 4 (tensor convention).
  expect_matrix_near(p.inertia_origin,
                     {{{m / 3 * (b * b + c * c), -m * a * b / 4, -m * a * c / 4},
                       {-m * a * b / 4, m / 3 * (a * a + c * c), -m * b * c / 4},
                       {-m * a * c / 4, -m * b * c / 4, m / 3 * (a * a + b * b)}}},
                     1e-15);
  EXPECT_NEAR(p.products_origin.xy, m * a * b / 4, 1e-12);
  EXPECT_NEAR(p.products_origin.yz, m * b * c / 4, 1e-12);
  EXPECT_NEAR(p.products_origin.zx, m * a * c / 4, 1e-12);
  // Principal: ascending moments along z (smallest: a² + b²), y, x.
  EXPECT_NEAR(p.principal.moments[0], m / 12 * (a * a + b * b), 1e-12);
  EXPECT_NEAR(p.principal.moments[1], m / 12 * (a * a + c * c), 1e-12);
  EXPECT_NEAR(p.principal.moments[2], m / 12 * (b * b + c * c), 1e-12);
  EXPECT_NEAR(p.principal.axes[0].z, 1, 1e-15);
  EXPECT_NEAR(p.principal.axes[1].y, 1, 1e-15);
  EXPECT_NEAR(p.principal.axes[2].x, -1, 1e-15);  // right-handed: z × y = −x
  EXPECT_FALSE(p.principal.degenerate);
}

TEST(MassClosedForms, GivenMassSetsDensity) {
  MassOptions opt;
  opt.mass = 12;
  const MassProperties p = mass_properties(box_mesh(1, 2, 3), opt);
  EXPECT_DOUBLE_EQ(p.mass, 12);
  EXPECT_DOUBLE_EQ(p.density, 2);
  EXPECT_NEAR(p.inertia_com[0][0], 12.0 / 12 * (4 + 9), 1e-13);
}

TEST(MassClosedForms, RejectsDensityOrMassThatIsNotPositiveAndFinite) {
  // Zero or less describes no body (its masses and inertias would be negative or zero).
  for (double bad : {0.0, -0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    MassOptions density;
    density.density = bad;
    EXPECT_THROW(mass_properties(box_mesh(1, 1, 1), density), std::invalid_argument) << bad;
    MassOptions mass;
    mass.mass = bad;
    EXPECT_THROW(mass_properties(box_mesh(1, 1, 1), mass), std::invalid_argument) << bad;
  }
}

TEST(MassClosedForms, Tetrahedron) {
  // Tetrahedron (0, a e1, b e2, c e3): V = abc/6, c = (a, b, c)/4, and about the origin
  // ∫x² dV = a³bc/60, ∫xy dV = a²b²c/120.
  const double a = 3, b = 4, c = 5;
  const MassProperties p =
      mass_properties(tetrahedron_mesh({0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}));
  const double v = a * b * c / 6;
  EXPECT_NEAR(p.volume, v, 1e-14);
  EXPECT_NEAR(p.center_of_mass.x, a / 4, 1e-15);
  EXPECT_NEAR(p.center_of_mass.y, b / 4, 1e-15);
  EXPECT_NEAR(p.center_of_mass.z, c / 4, 1e-15);
  const double xx = a * a * a * b * c / 60, yy = a * b * b * b * c / 60,
               zz = a * b * c * c * c / 60;
  const double xy = a * a * b * b * c / 120, yz = a * b * b * c * c / 120,
               zx = a * a * b * c * c / 120;
  expect_matrix_near(p.inertia_origin,
                     {{{yy + zz, -xy, -zx}, {-xy, xx + zz, -yz}, {-zx, -yz, xx + yy}}}, 1e-14);
}

TEST(MassClosedForms, SphereConvergesToFourThirdsPiRCubed) {
  const double r = 1.5;
  const double exact_v = 4.0 / 3 * std::numbers::pi * r * r * r;
  const double exact_i = 2.0 / 5 * exact_v * r * r;  // solid sphere, density 1
  double previous = 1;
  for (int n : {8, 16, 32, 64, 128}) {
    const MassProperties p = mass_properties(uv_sphere(r, n, 2 * n));
    const double err = std::abs(p.volume - exact_v) / exact_v;
    EXPECT_LT(err, previous / 3) << n;  // second order: the error quarters as n doubles
    previous = err;
    EXPECT_NEAR(length(p.center_of_mass), 0, 1e-13);
    EXPECT_NEAR(p.inertia_com[2][2], exact_i, 3 * err * exact_i);
    EXPECT_NEAR(p.area, 4 * std::numbers::pi * r * r, 3 * err * 4 * std::numbers::pi * r * r);
    EXPECT_LT(p.gap_area, 1e-13);
    EXPECT_LT(p.volume, exact_v);  // inscribed polyhedron
  }
  EXPECT_LT(previous, 3e-4);
}

TEST(MassClosedForms, ConcavePolygonFacesAreExact) {
  // An L-shaped prism of height h whose top and bottom are single concave hexagons: the fan about
  // the first corner has a negative triangle, and volume, area and centroid still come out exact.
  // L = [0,2]×[0,1] ∪ [0,1]×[1,2]: area 3, centroid (5/6, 5/6).
  const double h = 0.75;
  const Vec3d outline[6] = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
  Mesh m;
  for (const Vec3d& v : outline) m.vertices.push_back(v);
  for (const Vec3d& v : outline) m.vertices.push_back(v + Vec3d{0, 0, h});
  m.add_face({5, 4, 3, 2, 1, 0});    // bottom, clockwise from above = outward (down)
  m.add_face({6, 7, 8, 9, 10, 11});  // top
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    m.add_face({i, j, j + 6, i + 6});
  }
  const MassProperties p = mass_properties(m);
  EXPECT_DOUBLE_EQ(p.volume, 3 * h);
  EXPECT_DOUBLE_EQ(p.area, 2 * 3 + 8 * h);
  EXPECT_NEAR(p.center_of_mass.x, 5.0 / 6, 1e-15);
  EXPECT_NEAR(p.center_of_mass.y, 5.0 / 6, 1e-15);
  EXPECT_NEAR(p.center_of_mass.z, h / 2, 1e-15);
  EXPECT_EQ(p.gap_area, 0);
  // Same as the explicit triangulation.
  const MassProperties t = mass_properties(triangulated(m));
  expect_matrix_near(p.inertia_com, t.inertia_com, 1e-15);
}

TEST(MassClosedForms, OpenBoxGapIsMissingCoplanarArea) {
  // Drop the top quad (area a b), or the top split into two triangles: the gap ½‖ΣF‖ is exactly the
  // missing area because the missing faces are coplanar (Cor. 4.1).
  const double a = 2, b = 3, c = 5;
  for (bool split : {false, true}) {
    Mesh m = split ? triangulated(box_mesh(a, b, c)) : box_mesh(a, b, c);
    Mesh open;
    open.vertices = m.vertices;
    for (std::size_t f = 0; f < m.face_count(); ++f) {
      bool top = true;
      for (std::size_t k = 0; k < m.face_size(f); ++k) top = top && m.vertices[m.face(f)[k]].z == c;
      if (top) continue;
      open.corners.insert(open.corners.end(), m.face(f), m.face(f) + m.face_size(f));
      open.face_offsets.push_back(static_cast<std::uint32_t>(open.corners.size()));
    }
    const MassProperties p = mass_properties(open);
    EXPECT_DOUBLE_EQ(p.gap_area, a * b);
    EXPECT_DOUBLE_EQ(p.area, 2 * (a * b + b * c + c * a) - a * b);
    // The missing top's carrier: ΣF = −F_top, normal −(0, 0, 2ab) (‖F‖ = 2 × area).
    EXPECT_DOUBLE_EQ(p.carrier_sum.e3, -2 * a * b);
  }
}

TEST(MassClosedForms, FlippingEveryFaceNegatesTheVolume) {
  const Mesh m = transformed(uv_sphere(1, 12, 24), [](Vec3d v) {
    return Vec3d{2 * v.x, v.y, 0.5 * v.z};
  });
  const MassProperties p = mass_properties(m), q = mass_properties(flipped(m));
  EXPECT_DOUBLE_EQ(q.volume, -p.volume);  // reported signed, never abs()'d
  EXPECT_LT(q.volume, 0);
  EXPECT_DOUBLE_EQ(q.mass, -p.mass);
  EXPECT_DOUBLE_EQ(q.area, p.area);
  // The centre of mass is a ratio of two negated sums: unchanged.
  EXPECT_NEAR(q.center_of_mass.x, p.center_of_mass.x, 1e-15);
  EXPECT_NEAR(q.center_of_mass.z, p.center_of_mass.z, 1e-15);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(q.inertia_com[i][j], -p.inertia_com[i][j], 1e-14);
}

TEST(MassClosedForms, TranslationInvariance) {
  const Mesh m = transformed(uv_sphere(1, 10, 20), [](Vec3d v) {
    return Vec3d{3 * v.x + 0.1 * v.y * v.y, v.y, 0.7 * v.z};
  });
  const MassProperties p = mass_properties(m);
  for (Vec3d t : {Vec3d{1e6, 0, 0}, Vec3d{0, -1e6, 0}, Vec3d{0, 0, 1e6}, Vec3d{1e6, -2e6, 3e6}}) {
    // Translating rounds the vertices; the properties must move with them, not with the digits
    // lost by accumulating about a distant origin (docs/conventions.md §13).
    const MassProperties q = mass_properties(transformed(m, [&](Vec3d v) { return v + t; }));
    EXPECT_NEAR(q.volume, p.volume, 1e-9 * p.volume);
    EXPECT_NEAR(length(q.center_of_mass - t - p.center_of_mass), 0, 1e-9);
    expect_matrix_near(q.inertia_com, p.inertia_com, 1e-9);
    EXPECT_NEAR(q.principal.moments[0], p.principal.moments[0], 1e-9 * p.principal.moments[2]);
    EXPECT_NEAR(q.principal.moments[2], p.principal.moments[2], 1e-9 * p.principal.moments[2]);
  }
}

TEST(MassClosedForms, RotationInvariance) {
  const Mesh m = transformed(uv_sphere(1, 10, 20), [](Vec3d v) {
    return Vec3d{3 * v.x, 1.5 * v.y, 0.7 * v.z + 0.2};
  });
  const MassProperties p = mass_properties(m);
  const Vec3d axis = Vec3d{1, 2, -2} / 3.0;
  const double angle = 0.83;
  const MassProperties q =
      mass_properties(transformed(m, [&](Vec3d v) { return rotate(v, axis, angle); }));
  EXPECT_NEAR(q.volume, p.volume, 1e-14 * p.volume);
  EXPECT_NEAR(length(q.center_of_mass - rotate(p.center_of_mass, axis, angle)), 0, 1e-14);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(q.principal.moments[i], p.principal.moments[i], 1e-13 * p.principal.moments[2]);
    // The axes turn with the body (up to the sign rule, which is frame dependent).
    const Vec3d turned = rotate(p.principal.axes[i], axis, angle);
    EXPECT_NEAR(std::abs(dot(turned, q.principal.axes[i])), 1, 1e-12) << i;
  }
  // The principal motor turns the coordinate frame into the body's principal frame.
  for (int i = 0; i < 3; ++i) {
    const Vec3d e{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0};
    const Vec3d moved = pga3::apply(q.principal_motor, pga3::direction(e.x, e.y, e.z)).weighted();
    EXPECT_NEAR(length(moved - q.principal.axes[i]), 0, 1e-14);
  }
  const auto com = pga3::apply(q.principal_motor, pga3::origin<double>());
  EXPECT_NEAR(length(com.euclidean() - q.center_of_mass), 0, 1e-14);
}

TEST(MassClosedForms, ResultDoesNotDependOnThreadCount) {
  // Enough faces for many chunks; bitwise equal sums whatever the number of threads.
  const Mesh m = uv_sphere(1, 160, 320);
  ASSERT_GT(m.face_count(), 3 * faces_per_chunk);
  MassOptions one, two, seven;
  one.threads = 1;
  two.threads = 2;
  seven.threads = 7;
  const MassProperties a = mass_properties(m, one), b = mass_properties(m, two),
                       c = mass_properties(m, seven);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.volume, c.volume);
  EXPECT_EQ(a.area, c.area);
  EXPECT_EQ(a.center_of_mass, c.center_of_mass);
  EXPECT_EQ(a.inertia_com, b.inertia_com);
  EXPECT_EQ(a.inertia_com, c.inertia_com);
}

TEST(MassClosedForms, DegenerateMomentsAreFlagged) {
  // A cube: three equal moments. A square prism: two. A 1 × 2 × 3 box: none.
  EXPECT_TRUE(mass_properties(box_mesh(2, 2, 2)).principal.degenerate);
  EXPECT_TRUE(mass_properties(box_mesh(1, 1, 3)).principal.degenerate);
  EXPECT_FALSE(mass_properties(box_mesh(1, 2, 3)).principal.degenerate);
  // Nearly equal within the tolerance (1e-7 relative) counts as equal; beyond it does not.
  EXPECT_TRUE(mass_properties(box_mesh(1, 1 + 1e-9, 3)).principal.degenerate);
  EXPECT_FALSE(mass_properties(box_mesh(1, 1 + 1e-5, 3)).principal.degenerate);
}

TEST(MassClosedForms, EmptyAndFlatMeshesHaveNoCentreOfMass) {
  const MassProperties empty = mass_properties(Mesh{});
  EXPECT_EQ(empty.volume, 0);
  EXPECT_TRUE(std::isnan(empty.center_of_mass.x));
  Mesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.add_face({0, 1, 2});
  flat.add_face({0, 2, 1});
  const MassProperties p = mass_properties(flat);
  EXPECT_EQ(p.volume, 0);
  EXPECT_DOUBLE_EQ(p.area, 1);
  EXPECT_TRUE(std::isnan(p.inertia_com[0][0]));
}

TEST(MassClosedForms, BadCornerIndexThrows) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.add_face({0, 1, 3});
  EXPECT_THROW(mass_properties(m), std::out_of_range);
}
