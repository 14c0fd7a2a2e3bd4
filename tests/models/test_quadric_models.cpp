// The three models against each other and against the general engine: closed forms of the QCGA
// and DPGA point tests, the corrected DPGA rotor against the engine's exp, conversions, DCGA
// translation and quartics.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "pgamesh/algebra/clifford/products.hpp"
#include "pgamesh/models/quadric_convert.hpp"

using namespace pgamesh;
using quadric::Quadric;

namespace {

Quadric random_quadric(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  Quadric q;
  for (double& c : q.k) c = u(rng);
  return q;
}

Vec3d random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3, 3);
  return {u(rng), u(rng), u(rng)};
}

void expect_quadric_near(const Quadric& a, const Quadric& b, double tol) {
  for (std::size_t n = 0; n < 10; ++n) EXPECT_NEAR(a.k[n], b.k[n], tol) << "coefficient " << n;
}

}  // namespace

TEST(QuadricModels, QcgaClosedFormsAgainstEngine) {
  std::mt19937 rng(7);
  const auto& alg = qcga::algebra();
  for (int n = 0; n < 20; ++n) {
    const Quadric q = random_quadric(rng);
    const Vec3d p = random_point(rng), r = random_point(rng);
    const auto qs = qcga::dual_quadric(q);
    const auto x = qcga::point(p);
    const double engine =
        clifford::scalar_product(alg, qcga::to_clifford(x), qcga::to_clifford(qs));
    EXPECT_NEAR(qcga::value(qs, p), engine, 1e-12 * (1 + std::abs(engine)));
    EXPECT_NEAR(qcga::inner(x, qs), engine, 1e-12 * (1 + std::abs(engine)));
    EXPECT_NEAR(engine, quadric::value(q, p), 1e-11 * (1 + std::abs(engine)));
    // eq. 68: x1·x2 = −½|x1 − x2|², and points are null.
    const auto y = qcga::to_clifford(qcga::point(r));
    const double d2 = (p[0] - r[0]) * (p[0] - r[0]) + (p[1] - r[1]) * (p[1] - r[1]) +
                      (p[2] - r[2]) * (p[2] - r[2]);
    EXPECT_NEAR(clifford::scalar_product(alg, qcga::to_clifford(x), y), -0.5 * d2, 1e-11);
    EXPECT_NEAR(clifford::scalar_product(alg, qcga::to_clifford(x), qcga::to_clifford(x)), 0,
                1e-11);
    // Reciprocal operators of eq. 60 on the engine give the coefficients.
    const auto& v = qs;
    const Quadric back = qcga::coefficients(v);
    expect_quadric_near(back, q, 1e-14);
    // Corrected tangent plane eq. 46 contains p: x·π* = 0 on the engine too.
    const auto pi = qcga::tangent_plane(qs, p);
    EXPECT_NEAR(clifford::scalar_product(alg, qcga::to_clifford(x), qcga::to_clifford(pi)), 0,
                1e-10);
    // point_coordinates undoes a scaled embedding (eqs. 62, 69).
    qcga::Vector scaled = x;
    for (double& c : scaled.v) c *= -2.5;
    const Vec3d got = qcga::point_coordinates(scaled);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], p[k], 1e-13);
  }
}

TEST(QuadricModels, QcgaEq70MatchesClosedFormOnRandomEllipsoid) {
  const Quadric e = quadric::translate(quadric::rotate(quadric::ellipsoid({0, 0, 0}, {2, 1, 0.5}),
                                                       quadric::axis_rotation({1, 2, 3}, 0.4)),
                                       {0.3, -0.2, 0.5});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::array<Vec3d, 9> pts;
  const quadric::Mat3 r = quadric::axis_rotation({1, 2, 3}, 0.4);
  for (auto& p : pts) {
    const double th = std::acos(2 * u(rng) - 1), ph = 2 * M_PI * u(rng);
    const Vec3d l{2 * std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), 0.5 * std::cos(th)};
    for (int k = 0; k < 3; ++k)
      p[k] = r[k][0] * l[0] + r[k][1] * l[1] + r[k][2] * l[2] + Vec3d{0.3, -0.2, 0.5}[k];
  }
  const Quadric want = quadric::normalized(e);
  const Quadric closed = quadric::normalized(qcga::coefficients(qcga::quadric_from_points(pts)));
  const Quadric ga = quadric::normalized(
      qcga::coefficients(qcga::from_clifford(qcga::quadric_from_points_ga(pts))));
  expect_quadric_near(closed, want, 1e-10);
  expect_quadric_near(ga, want, 1e-10);
}

TEST(QuadricModels, DpgaGradedAgainstEngineInNullBasis) {
  std::mt19937 rng(11);
  const auto& alg = dpga::algebra();
  for (int n = 0; n < 10; ++n) {
    const Quadric q = random_quadric(rng);
    const Vec3d p = random_point(rng);
    const auto qd = dpga::quadric(q);
    const auto qn = dpga::to_null_basis(qd);
    const auto pn = dpga::to_null_basis(dpga::point(p));
    const auto psn = dpga::to_null_basis(dpga::dual_point(p));
    // (p ⌋ Q)·p* on the engine's null basis = the graded value = F(p).
    const double engine =
        clifford::scalar_product(alg, clifford::left_contraction(alg, pn, qn), psn);
    EXPECT_NEAR(dpga::value(qd, p), engine, 1e-11 * (1 + std::abs(engine)));
    EXPECT_NEAR(engine, quadric::value(q, p), 1e-11 * (1 + std::abs(engine)));
    // The embedding in the null basis is x w0 + y w1 + z w2 + w3 (as pgamesh calc builds it).
    std::map<std::string, double> pm;
    for (const auto& [k, v] : dpga::nonzero_blades(dpga::point(p))) pm[k] = v;
    EXPECT_NEAR(pm["w0"], p[0], 1e-15);
    EXPECT_NEAR(pm["w3"], 1, 1e-15);
    EXPECT_EQ(pm.count("w0*"), 0u);
    // Polar plane (eq. 38) = (∇F, g x + h y + i z + 2j).
    const auto pl = dpga::polar_plane(qd, p);
    const Vec3d gr = quadric::gradient(q, p);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(pl[k], gr[k], 1e-12 * (1 + std::abs(gr[k])));
    EXPECT_NEAR(pl[3], q.k[6] * p[0] + q.k[7] * p[1] + q.k[8] * p[2] + 2 * q.k[9], 1e-12 * 10);
  }
}

TEST(QuadricModels, DpgaCorrectedRotorAgainstEngineExpAndNotTheShear) {
  const auto& alg = dpga::algebra();
  auto wv = [](int k) { return clifford::basis_blade(clifford::BladeMask{1} << k); };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      const double th = 0.37 + 0.1 * i - 0.05 * j;
      const auto b =
          clifford::outer(alg, wv(i), wv(4 + j)) - clifford::outer(alg, wv(j), wv(4 + i));
      const auto series = clifford::exp(alg, -th * b);
      const auto closed = dpga::to_null_basis(dpga::rotor(i, j, th));
      const auto diff = clifford::pruned(series - closed, 1e-13);
      EXPECT_TRUE(diff.is_zero()) << i << j;
      // R R̃ = 1, and the rotor moves p and p* alike: a rotation.
      const auto r = dpga::rotor(i, j, th);
      const auto rr = graded::project<dpga::Algebra::even_grades>(r * ~r);
      EXPECT_NEAR(graded::scalar_part(rr), 1, 1e-14);
      const Vec3d p{1, 2, 0.5};
      const Vec3d want = [&] {
        const auto m = quadric::plane_rotation(i, j, th);
        return Vec3d{m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2],
                     m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2],
                     m[2][0] * p[0] + m[2][1] * p[1] + m[2][2] * p[2]};
      }();
      const auto moved = graded::sandwich(r, dpga::point(p));
      const auto moved_star = graded::sandwich(r, dpga::dual_point(p));
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(2 * graded::scalar_product(moved, dpga::w_star(k)), want[k], 1e-13);
        EXPECT_NEAR(2 * graded::scalar_product(moved_star, dpga::w(k)), want[k], 1e-13);
      }
    }
  // The printed eq. 73 element 1 + ½θ w0 w1* is a shear: (1, 2, 0.5) ↦ (1.7, 2, 0.5) for θ = 0.7.
  const auto s = dpga::shear(0, 1, 0.35);
  const auto moved = graded::sandwich(s, dpga::point({1, 2, 0.5}));
  EXPECT_NEAR(2 * graded::scalar_product(moved, dpga::w_star(0)), 1.7, 1e-14);
  EXPECT_NEAR(2 * graded::scalar_product(moved, dpga::w_star(1)), 2.0, 1e-14);
}

TEST(QuadricModels, ConversionsRoundTrip) {
  std::mt19937 rng(5);
  for (int n = 0; n < 10; ++n) {
    const Quadric q = random_quadric(rng);
    const auto qs = qcga::dual_quadric(q);
    expect_quadric_near(dpga::coefficients(dpga::from_qcga(qs)), q, 1e-13);                // eq. 71
    expect_quadric_near(qcga::coefficients(qcga::from_dpga(dpga::quadric(q))), q, 1e-13);  // eq. 74
    expect_quadric_near(dcga::coefficients(dcga::from_qcga(qs)), q, 1e-13);
    expect_quadric_near(qcga::coefficients(qcga::from_dcga(dcga::quadric(q))), q, 1e-13);
    expect_quadric_near(dpga::coefficients(dpga::from_dcga(dcga::from_dpga(dpga::quadric(q)))), q,
                        1e-13);
    EXPECT_EQ(qcga::from_dpga(dpga::from_qcga(qs)), qcga::dual_quadric(qcga::coefficients(qs)));
  }
}

TEST(QuadricModels, SectionEightPipeline) {
  // Breuils §8: nine points -> QCGA (eq. 70) -> DPGA (eq. 71) -> rotate (corrected rotor) -> QCGA
  // (eq. 74): the rotated points lie on the result.
  const Quadric e = quadric::ellipsoid({0.3, -0.2, 0.5}, {2, 1, 0.5});
  std::array<Vec3d, 9> pts;
  for (int n = 0; n < 9; ++n) {
    const double th = 0.3 + 0.31 * n, ph = 0.7 * n * n + 0.2;
    pts[static_cast<std::size_t>(n)] = {0.3 + 2 * std::sin(th) * std::cos(ph),
                                        -0.2 + std::sin(th) * std::sin(ph),
                                        0.5 + 0.5 * std::cos(th)};
  }
  const auto qs = qcga::quadric_from_points(pts);
  const auto qrot = qcga::from_dpga(dpga::rotate(dpga::from_qcga(qs), 0, 2, 0.9));
  const auto m = quadric::plane_rotation(0, 2, 0.9);
  for (const Vec3d& p : pts) {
    const Vec3d pr{m[0][0] * p[0] + m[0][2] * p[2], p[1], m[2][0] * p[0] + m[2][2] * p[2]};
    EXPECT_NEAR(qcga::value(qrot, pr), 0, 1e-12);
  }
  (void)e;
}

TEST(QuadricModels, DcgaTranslationAndRotationMatchDirectTransform) {
  std::mt19937 rng(13);
  for (int n = 0; n < 5; ++n) {
    const Quadric q = random_quadric(rng);
    const Vec3d t = random_point(rng);
    const auto moved = dcga::transform(dcga::translator(t), dcga::quadric(q));
    expect_quadric_near(dcga::coefficients(moved), quadric::translate(q, t), 1e-11);
    const Vec3d p = random_point(rng);
    EXPECT_NEAR(dcga::value(moved, {p[0] + t[0], p[1] + t[1], p[2] + t[2]}), quadric::value(q, p),
                1e-10);
    const auto rot = dcga::transform(dcga::rotor(1, 2, 0.8), dcga::quadric(q));
    expect_quadric_near(dcga::coefficients(rot),
                        quadric::rotate(q, quadric::plane_rotation(1, 2, 0.8)), 1e-12);
    // DPGA rotation agrees with DCGA and the direct transform.
    expect_quadric_near(dpga::coefficients(dpga::rotate(dpga::quadric(q), 1, 2, 0.8)),
                        dcga::coefficients(rot), 1e-12);
  }
}

TEST(QuadricModels, DcgaPointTangentPlaneAndCoordinates) {
  const Quadric q = quadric::sphere({0.5, -1, 2}, 1.5);
  const Vec3d p{0.5 + 1.5, -1, 2};
  const auto pi = dcga::tangent_plane(dcga::quadric(q), p);
  // Π·X = −(n·x − n·p)² vanishes at p and grows quadratically off the plane.
  EXPECT_NEAR(clifford::scalar_product(dcga::algebra(), pi, dcga::point(p)), 0, 1e-12);
  const Vec3d off{p[0] + 0.5, p[1] + 7, p[2] - 3};
  const double np = quadric::gradient(q, p)[0] * 0.5;
  EXPECT_NEAR(clifford::scalar_product(dcga::algebra(), pi, dcga::point(off)), -np * np, 1e-10);
  const auto x = -3.0 * dcga::point({1.25, -0.5, 4});
  const Vec3d c = dcga::point_coordinates(x);
  EXPECT_NEAR(c[0], 1.25, 1e-13);
  EXPECT_NEAR(c[1], -0.5, 1e-13);
  EXPECT_NEAR(c[2], 4, 1e-13);
  // T_m·X = m(x) for all 15 monomials of eq. 4.
  const Vec3d r{0.7, -1.3, 0.4};
  const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const std::array<double, 15> mono = {
      r[0] * r[0], r[1] * r[1], r[2] * r[2], r[0] * r[1], r[0] * r[2], r[1] * r[2], r[0],   r[1],
      r[2],        1,           r2,          r[0] * r2,   r[1] * r2,   r[2] * r2,   r2 * r2};
  const auto xr = dcga::point(r);
  for (int m = 0; m < 15; ++m)
    EXPECT_NEAR(clifford::scalar_product(dcga::algebra(), dcga::extraction_operator(m), xr),
                mono[static_cast<std::size_t>(m)], 1e-13)
        << dcga::monomial_names[static_cast<std::size_t>(m)];
  // Reciprocity T^m·T_n = δ_mn (eq. 52).
  for (int m = 0; m < 10; ++m)
    for (int n = 0; n < 10; ++n)
      EXPECT_NEAR(clifford::scalar_product(dcga::algebra(), dcga::reciprocal_operator(m),
                                           dcga::extraction_operator(n)),
                  m == n ? 1.0 : 0.0, 1e-15);
}

TEST(QuadricModels, DcgaQuartics) {
  const double big = 2, small = 0.5;
  const auto s = dcga::torus(big, small);
  const auto t = dcga::quartic(s);
  for (double u : {0.0, 0.7, 2.1, 4.0})
    for (double v : {0.0, 1.1, 3.0, 5.5}) {
      const Vec3d p{(big + small * std::cos(v)) * std::cos(u),
                    (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)};
      EXPECT_NEAR(dcga::value(s, p), 0, 1e-12);
      EXPECT_NEAR(dcga::value(t, p), 0, 1e-12);
    }
  const Vec3d centre{0, 0, 0};  // (R² − ρ²)² at the origin
  EXPECT_NEAR(dcga::value(t, centre), std::pow(big * big - small * small, 2), 1e-12);
  EXPECT_NEAR(dcga::value(t, {1, 2, 3}), dcga::value(s, {1, 2, 3}), 1e-10);
  // A translated torus (DCGA versor) has its surface moved.
  const auto moved = dcga::transform(dcga::translator({1, -2, 0.5}), t);
  EXPECT_NEAR(dcga::value(moved, {1 + big + small, -2, 0.5}), 0, 1e-10);
  // Dupin cyclide: the points (x, 0, 0) with x = ±(b ± μ)… check the value against the closed form
  // and that the z = 0 section contains the circles' extreme points.
  const auto d = dcga::dupin_cyclide(2.0, 1.0, 1.5);
  const auto dq = dcga::quartic(d);
  for (double x : {-3.0, -0.4, 0.8, 2.7})
    EXPECT_NEAR(dcga::value(dq, {x, 0.3, -0.2}), dcga::value(d, {x, 0.3, -0.2}), 1e-10);
  // On y = z = 0: (x² + b² − μ²)² = 4(a x − c μ)²  ⇒ x² + b² − μ² = ±2(a x − c μ).
  const double a = 2, c = 1, mu = 1.5, b2 = a * a - c * c;
  const double x0 =
      a + std::sqrt(a * a - (b2 - mu * mu) - 2 * c * mu);  // root of x² − 2a x + … = 0
  EXPECT_NEAR(dcga::value(d, {x0, 0, 0}), 0, 1e-10);
  EXPECT_THROW(dcga::dupin_cyclide(1, 2, 0.5), ModelError);
}

TEST(QuadricModels, BladeKeysAreGoldenSpelling) {
  std::map<std::string, double> m;
  for (const auto& [k, v] : dpga::nonzero_blades(dpga::rotor(0, 2, 0.6))) m[k] = v;
  EXPECT_EQ(m.size(), 4u);
  EXPECT_TRUE(m.count("1") && m.count("w0^w2*") && m.count("w2^w0*") && m.count("w0^w2^w0*^w2*"));
  std::map<std::string, double> c;
  for (const auto& [k, v] :
       dcga::nonzero_blades(dcga::quadric(Quadric{{0, 0, 0, 0, 0, 0, 0, 0, 0, 1}})))
    c[k] = v;
  EXPECT_EQ(c.size(), 1u);
  EXPECT_EQ(c["einf1^einf2"], -1);
  const auto qb = qcga::nonzero_blades(qcga::point({1, 0, 0}));
  EXPECT_EQ(qb.front().first, "e1");
  EXPECT_EQ(qb.back().first, "einf1");
}
