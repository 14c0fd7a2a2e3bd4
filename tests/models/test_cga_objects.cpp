// pgamesh::cga beyond the golden file: closed forms, duals, intersections, motors, objects far
// from the origin, nearly degenerate inputs, every error, and the null-basis products against the
// general Clifford engine (cga3).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/models/cga.hpp"
#include "support/model_checks.hpp"

using namespace pgamesh;
using namespace pgamesh::cga;

using pgamesh::test::expect_near;
using pgamesh::test::pi;

namespace {

Vec3d on_sphere(Vec3d c, double r, double theta, double phi) {
  return c + r * Vec3d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                       std::cos(theta)};
}

const clifford::Algebra& engine() {
  static const clifford::Algebra a = *clifford::make_algebra("cga3");
  return a;
}

// The same blade masks in both: e_o = bit 0, e1..e3 = bits 1-3, e_∞ = bit 4 (outer-product blades).
template <GradeMask G>
clifford::Multivector to_engine(const Multivector<G>& x) {
  std::vector<clifford::Term> t;
  for (std::size_t i = 0; i < x.size; ++i) t.push_back({x.blades[i], x.c[i]});
  return clifford::from_terms(t);
}

template <GradeMask G>
::testing::AssertionResult same(const Multivector<G>& x, const clifford::Multivector& y,
                                double tol) {
  double scale = 1;
  for (const auto& t : y.terms) scale = std::max(scale, std::abs(t.coeff));
  for (clifford::BladeMask m = 0; m < 32; ++m) {
    const int i = Multivector<G>::index_of(m);
    const double got = i < 0 ? 0.0 : x.c[static_cast<std::size_t>(i)];
    if (std::abs(got - y[m]) > tol * scale)
      return ::testing::AssertionFailure()
             << "blade " << blade_key(m) << ": " << got << " vs " << y[m];
  }
  return ::testing::AssertionSuccess();
}

Full random_full(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Full x;
  for (double& c : x.c) c = u(rng);
  return x;
}

}  // namespace

// ---- the products against the general engine --------------------------------------------------

TEST(CgaAlgebra, ProductsMatchTheGeneralEngine) {
  std::mt19937_64 rng(7);
  const auto& alg = engine();
  for (int trial = 0; trial < 20; ++trial) {
    const Full a = random_full(rng), b = random_full(rng);
    const auto ea = to_engine(a), eb = to_engine(b);
    EXPECT_TRUE(same(a * b, clifford::geometric(alg, ea, eb), 1e-13));
    EXPECT_TRUE(same(a ^ b, clifford::outer(alg, ea, eb), 1e-13));
    EXPECT_TRUE(same(left_contraction(a, b), clifford::left_contraction(alg, ea, eb), 1e-13));
    EXPECT_TRUE(same(right_contraction(a, b), clifford::right_contraction(alg, ea, eb), 1e-13));
    EXPECT_TRUE(same(a | b, clifford::inner(alg, ea, eb), 1e-13));
    EXPECT_NEAR(scalar_product(a, b), clifford::scalar_product(alg, ea, eb), 1e-13);
    EXPECT_TRUE(same(cga::dual(a), clifford::metric_dual(alg, ea), 1e-13));
    EXPECT_TRUE(same(graded::reverse(a), clifford::reverse(ea), 0));
  }
}

TEST(CgaAlgebra, ObjectsAndSandwichMatchTheGeneralEngine) {
  const auto& alg = engine();
  auto pt = [&](Vec3d p) {
    return clifford::from_terms({{1, 1.0}, {2, p.x}, {4, p.y}, {8, p.z}, {16, 0.5 * dot(p, p)}});
  };
  const Vec3d a{0.3, -1.2, 2.0}, b{1.5, 0.4, -0.7}, c{-2.0, 0.9, 0.1}, d{0.2, 2.2, 1.3};
  const auto ni = clifford::basis_blade(16);
  EXPECT_TRUE(same(up(a), pt(a), 0));
  const auto epair = clifford::outer(alg, pt(a), pt(b));
  const auto ecircle = clifford::outer(alg, epair, pt(c));
  const auto esphere = clifford::outer(alg, ecircle, pt(d));
  EXPECT_TRUE(same(point_pair(a, b), epair, 1e-14));
  EXPECT_TRUE(same(circle(a, b, c), ecircle, 1e-14));
  EXPECT_TRUE(same(sphere(a, b, c, d), esphere, 1e-14));
  EXPECT_TRUE(same(line(a, b), clifford::outer(alg, epair, ni), 1e-14));
  EXPECT_TRUE(same(plane(a, b, c), clifford::outer(alg, ecircle, ni), 1e-14));
  const Versor m = motor(rotor({1, 2, 3}, 0.7), {0.5, -1, 2});
  EXPECT_TRUE(
      same(apply(m, circle(a, b, c)), clifford::sandwich(alg, to_engine(m), ecircle), 1e-13));
  // The engine's own null-basis metric: X·Y = −½|x − y|².
  EXPECT_NEAR(clifford::scalar_product(alg, pt(a), pt(b)), -0.5 * dot(a - b, a - b), 1e-13);
  EXPECT_NEAR(scalar_product(up(a), up(b)), -0.5 * dot(a - b, a - b), 1e-13);
}

TEST(CgaAlgebra, BladeKeysAndParsing) {
  EXPECT_EQ(blade_key(eo_mask | e1_mask | einf_mask), "eo^e1^einf");
  EXPECT_EQ(blade_key(0), "1");
  EXPECT_EQ(parse_blade_key("e1^e2^einf"), e1_mask | e2_mask | einf_mask);
  EXPECT_EQ(parse_blade_key("eo^ei"), eo_mask | einf_mask);
  EXPECT_MODEL_ERROR(parse_blade_key("e2^e1"), "order");
  EXPECT_MODEL_ERROR(parse_blade_key("e7"), "not a blade key");
  const Trivector l = line({1, 2, 3}, {0, 1, 5});
  const auto named = blades(l);
  EXPECT_EQ(from_blades<8u>(named).c, l.c);
  EXPECT_MODEL_ERROR(from_blades<2u>(named), "grade");
  EXPECT_EQ(named.front().first, "eo^e1^einf");
  EXPECT_EQ(to_string(up({0, 0, 0})), "1 eo");
}

TEST(CgaAlgebra, PseudoscalarAndDuals) {
  EXPECT_DOUBLE_EQ(norm_squared(pseudoscalar()), -1.0);  // I² = −1, Ĩ = I
  std::mt19937_64 rng(3);
  const Full x = random_full(rng);
  const Full back = undual(cga::dual(x));
  for (std::size_t i = 0; i < x.size; ++i) EXPECT_NEAR(back.c[i], x.c[i], 1e-15);
  // The metric dual is not the Hodge complement: they differ on blades with e_o or e_∞.
  EXPECT_NE(cga::dual(eo()).c, graded::dual(eo()).c);
}

// ---- points ---------------------------------------------------------------------------------

TEST(CgaPoints, UpDownAndDistance) {
  const Vec3d p{1.5, -2, 0.25};
  EXPECT_EQ(down(up(p)), p);
  EXPECT_EQ(down(3.0 * up(p)), p);
  EXPECT_DOUBLE_EQ(weight(up(p)), 1.0);
  EXPECT_NEAR(distance(p, {4.5, 2, 0.25}), 5.0, 1e-14);
  EXPECT_MODEL_ERROR(down(einf()), "weight");
  EXPECT_MODEL_ERROR(normalize_point(dual_plane({0, 0, 1}, 2)), "weight");
}

// ---- closed forms ---------------------------------------------------------------------------

TEST(CgaClosedForms, SphereThroughFourPointsOfAKnownSphere) {
  const Vec3d c{1, -2, 0.5};
  const double r = 3;
  const Quadvector s = sphere(on_sphere(c, r, 0.3, 0.1), on_sphere(c, r, 1.2, 2.0),
                              on_sphere(c, r, 2.0, 4.0), on_sphere(c, r, 2.7, 5.5));
  const RoundParams sp = sphere_params(s);
  expect_near(sp.center, c, 1e-13);
  EXPECT_NEAR(sp.radius, r, 1e-13);
  const RoundParams rp = round_params(s);
  expect_near(rp.center, c, 1e-13);
  EXPECT_NEAR(rp.radius, r, 1e-13);
  // Its dual is a multiple of up(c) − ½ r² e_∞ (Hitzer eq. 50), read the same way.
  const RoundParams dp = sphere_params(cga::dual(s), Form::dual);
  expect_near(dp.center, c, 1e-13);
  EXPECT_NEAR(dp.radius, r, 1e-13);
  // A fifth point of the sphere is on it: S ∧ X = 0.
  const auto on = s ^ up(on_sphere(c, r, 1.7, 3.3));
  EXPECT_NEAR(on.c[0], 0, 1e-12);
  // Parameters → object → parameters.
  const RoundParams back = sphere_params(sphere_from_center(c, r));
  expect_near(back.center, c, 1e-14);
  EXPECT_NEAR(back.radius, r, 1e-14);
  EXPECT_EQ(cga::dual(sphere_from_center(c, r)).c, dual_sphere(c, r).c);
}

TEST(CgaClosedForms, CircleCarrierPlaneAndParameters) {
  const Vec3d c{0.5, 1, -2}, n = Vec3d{1, 2, 2} / 3.0;
  const double r = 1.25;
  Vec3d u = cross(n, Vec3d{1, 0, 0});
  u = u / length(u);
  const Vec3d v = cross(n, u);
  auto at = [&](double t) { return c + r * (std::cos(t) * u + std::sin(t) * v); };
  const Trivector x = circle(at(0.2), at(2.1), at(4.4));  // counter-clockwise about n
  const CircleParams cp = circle_params(x);
  expect_near(cp.round.center, c, 1e-14);
  EXPECT_NEAR(cp.round.radius, r, 1e-14);
  expect_near(cp.normal, n, 1e-14);
  const PlaneParams carrier_plane = plane_params(cp.carrier);
  expect_near(carrier_plane.normal, n, 1e-14);
  EXPECT_NEAR(carrier_plane.distance, dot(n, c), 1e-14);
  const Full k = carrier(x);
  EXPECT_EQ(classify(k), Kind::plane);
  // From parameters, in both forms, read back the same.
  for (const CircleParams& q : {circle_params(circle_from_center(c, 3.0 * n, r)),
                                circle_params(dual_circle(c, n, r), Form::dual)}) {
    expect_near(q.round.center, c, 1e-14);
    EXPECT_NEAR(q.round.radius, r, 1e-14);
    expect_near(q.normal, n, 1e-14);
  }
  // The dual circle is the meet of its plane and sphere: a point of the circle is on both.
  const Bivector dc = dual_circle(c, n, r);
  const auto on = up(at(1.0)) | dc;  // X ⌋ (π ∧ σ) = 0 for X on the circle
  for (double co : on.c) EXPECT_NEAR(co, 0, 1e-13);
}

TEST(CgaClosedForms, LineSphereIntersectionPoints) {
  const Vector s = dual_sphere({1, 2, 3}, 2);
  // A line through the centre along e1 cuts the sphere at (−1, 2, 3) and (3, 2, 3).
  const Trivector hits = s ^ dual_line({-5, 2, 3}, {1, 0, 0});
  EXPECT_EQ(classify(hits, Form::dual), Kind::point_pair);
  const auto p = pair_points(hits, Form::dual);
  expect_near(p[0], {3, 2, 3}, 1e-14);  // larger norm first
  expect_near(p[1], {-1, 2, 3}, 1e-14);
  // An oblique chord: x = (1, 2 + t, 3 + t)/… at distance 1 from the centre along e3.
  const Trivector chord = s ^ dual_line({1, 2, 4}, {1, 1, 0});
  const auto q = pair_points(chord, Form::dual);
  const double h = std::sqrt(3.0 / 2.0);  // half-chord √(r² − 1) / √2 along each of e1, e2
  expect_near(q[0], {1 + h, 2 + h, 4}, 1e-14);
  expect_near(q[1], {1 - h, 2 - h, 4}, 1e-14);
  // A line missing the sphere gives an imaginary pair; a tangent line a tangent.
  const Trivector miss = s ^ dual_line({1, 2, 6}, {1, 0, 0});
  EXPECT_EQ(classify(miss, Form::dual), Kind::imaginary_point_pair);
  EXPECT_TRUE(pair_params(miss, Form::dual).round.imaginary);
  EXPECT_MODEL_ERROR(pair_points(miss, Form::dual), "imaginary");
  EXPECT_EQ(classify(s ^ dual_line({1, 2, 5}, {1, 0, 0}), Form::dual), Kind::tangent);
}

TEST(CgaClosedForms, MeetsOfSpheresAndPlanes) {
  const Vector s1 = dual_sphere({0, 0, 0}, 2), s2 = dual_sphere({2, 0, 0}, 2);
  const CircleParams cc = circle_params(meet_dual(s1, s2), Form::dual);
  expect_near(cc.round.center, {1, 0, 0}, 1e-15);
  EXPECT_NEAR(cc.round.radius, std::sqrt(3.0), 1e-15);
  EXPECT_EQ(classify(meet_dual(s1, dual_sphere({5, 0, 0}, 1)), Form::dual), Kind::imaginary_circle);
  EXPECT_EQ(classify(meet_dual(s1, dual_plane({0, 0, 1}, 2)), Form::dual), Kind::tangent);
  const LineParams lp =
      line_params(meet_dual(dual_plane({0, 0, 1}, 1), dual_plane({0, 1, 0}, 2)), Form::dual);
  expect_near(lp.closest_point, {0, 2, 1}, 1e-15);
  EXPECT_NEAR(std::abs(lp.unit_direction.x), 1.0, 1e-15);
}

TEST(CgaClosedForms, PlanesInBothForms) {
  const PlaneParams a = plane_params(plane_from_normal({0, 0, 2}, 1.5));
  expect_near(a.normal, {0, 0, 1}, 0);
  EXPECT_DOUBLE_EQ(a.distance, 1.5);
  const PlaneParams b = plane_params(dual_plane({0, 3, 4}, -2), Form::dual);
  expect_near(b.normal, {0, 0.6, 0.8}, 1e-16);
  EXPECT_DOUBLE_EQ(b.distance, -2);
  // dual() of a point-built plane is −w (n̂ + δ e_∞): the same plane, opposite orientation.
  const Quadvector p = plane({0, 0, 1}, {1, 0, 1}, {0, 1, 1});
  const PlaneParams direct = plane_params(p), dualp = plane_params(cga::dual(p), Form::dual);
  expect_near(direct.normal, {0, 0, 1}, 0);
  expect_near(dualp.normal, {0, 0, -1}, 0);
  EXPECT_DOUBLE_EQ(dualp.distance, -1);
  EXPECT_NEAR(distance_to_plane({3, 4, 5}, dual_plane({0, 0, 1}, 1)), 4, 1e-15);
  EXPECT_NEAR(distance_to_sphere({1, 2, 8}, dual_sphere({1, 2, 3}, 2)), 3, 1e-15);
  EXPECT_NEAR(distance_to_sphere({1, 2, 3.5}, dual_sphere({1, 2, 3}, 2)), -1.5, 1e-15);
}

TEST(CgaClosedForms, LinesAndFlatPoints) {
  const Trivector l = line_from_point({1, 2, 3}, {0, 0, 2});
  const LineParams lp = line_params(l);
  expect_near(lp.closest_point, {1, 2, 0}, 1e-15);
  expect_near(lp.unit_direction, {0, 0, 1}, 0);
  const LineParams dl = line_params(dual_line({1, 2, 3}, {0, 0, 2}), Form::dual);
  expect_near(dl.closest_point, {1, 2, 0}, 1e-15);
  EXPECT_EQ(classify(flat_point({1, 2, 3})), Kind::flat_point);
  expect_near(location(flat_point({1, 2, 3})), {1, 2, 3}, 0);
  // A point on the line satisfies L ∧ X = 0.
  const auto on = l ^ up({1, 2, -7});
  for (double c : on.c) EXPECT_NEAR(c, 0, 1e-13);
}

TEST(CgaKinds, ClassifiesEveryKind) {
  EXPECT_EQ(classify(Full{}), Kind::zero);
  EXPECT_EQ(classify(widen<1u>(Multivector<1u>{{2.0}})), Kind::scalar);
  EXPECT_EQ(classify(up({1, 2, 3})), Kind::point);
  EXPECT_EQ(classify(up({1, 2, 3}), Form::dual), Kind::point);
  EXPECT_EQ(classify(einf(2.0)), Kind::point_at_infinity);
  EXPECT_EQ(classify(dual_sphere({1, 2, 3}, 1)), Kind::vector);
  EXPECT_EQ(classify(dual_sphere({1, 2, 3}, 1), Form::dual), Kind::sphere);
  EXPECT_EQ(classify(dual_sphere_r2({1, 2, 3}, -1), Form::dual), Kind::imaginary_sphere);
  EXPECT_EQ(classify(dual_plane({1, 2, 3}, 1), Form::dual), Kind::plane);
  EXPECT_EQ(classify(e1() ^ einf()), Kind::direction);
  EXPECT_EQ(classify(pseudoscalar()), Kind::space);
  EXPECT_EQ(classify(widen<63>(up({1, 0, 0})) + widen<63>(e1() ^ e2())), Kind::mixed_grades);
  EXPECT_EQ(classify((e1() ^ e2()) + (e3() ^ einf())), Kind::not_a_blade);
  EXPECT_EQ(classify(circle({1, 0, 0}, {0, 1, 0}, {-1, 0, 0})), Kind::circle);
  EXPECT_STREQ(kind_name(Kind::imaginary_circle), "imaginary circle");
}

// ---- motors --------------------------------------------------------------------------------

TEST(CgaMotors, RotorTranslatorDilator) {
  // Rodrigues: rotation by θ about the unit axis a.
  const Vec3d a = Vec3d{1, 2, 2} / 3.0, x{0.3, -1.1, 2.5};
  const double th = 0.8;
  const Vec3d rod =
      std::cos(th) * x + std::sin(th) * cross(a, x) + (1 - std::cos(th)) * dot(a, x) * a;
  expect_near(apply_to_point(rotor(a, th), x), rod, 1e-14);
  expect_near(apply_to_point(translator({1, -2, 3}), x), x + Vec3d{1, -2, 3}, 1e-15);
  expect_near(apply_to_point(dilator(2.5), x), 2.5 * x, 1e-14);
  expect_near(apply_to_point(rotor_about({1, 1, 0}, {0, 0, 1}, pi / 2), {2, 1, 0}), {1, 2, 0},
              1e-15);
  // Composition: translate after rotating = motor(R, t).
  const Versor m = motor(rotor(a, th), {1, 2, 3});
  expect_near(apply_to_point(m, x), rod + Vec3d{1, 2, 3}, 1e-14);
  expect_near(apply_to_point(compose(translator({1, 2, 3}), rotor(a, th)), x), rod + Vec3d{1, 2, 3},
              1e-14);
  expect_near(apply_to_point(inverse(m), apply_to_point(m, x)), x, 1e-14);
  EXPECT_NEAR(norm_squared(m), 1.0, 1e-15);
  // Objects move as wholes: a sphere's centre and radius, a circle's normal.
  const Quadvector s = sphere_from_center({1, 0, 0}, 2);
  const RoundParams moved = sphere_params(apply(m, s));
  expect_near(moved.center, apply_to_point(m, {1, 0, 0}), 1e-14);
  EXPECT_NEAR(moved.radius, 2, 1e-14);
  EXPECT_NEAR(sphere_params(apply(dilator(3), s)).radius, 6, 1e-14);
  const CircleParams cm =
      circle_params(apply(rotor({1, 0, 0}, pi / 2), circle_from_center({}, {0, 0, 1}, 1)));
  expect_near(cm.normal, {0, -1, 0}, 1e-15);
  // The sandwich keeps points null.
  const Vector y = apply(m, up(x));
  EXPECT_NEAR(scalar_product(y, y), 0, 1e-13);
}

// ---- far from the origin and nearly degenerate -----------------------------------------------

TEST(CgaFarFromOrigin, ObjectsAtAMillion) {
  const Vec3d c{1e6, -2e6, 3e6};
  const double r = 1.5;
  const Vec3d p1 = on_sphere(c, r, 0.3, 0.1), p2 = on_sphere(c, r, 1.2, 2.0),
              p3 = on_sphere(c, r, 2.0, 4.0), p4 = on_sphere(c, r, 2.7, 5.5);
  // Centres are read from linear parts and keep ~1e-16 of |c|. Shape parameters cannot: the
  // coefficients hold ½|x|² ≈ 7e12 to ±ε·7e12 ≈ 1.6e-3, and a radius r read from them moves by
  // about ε|c|²/r ≈ 1e-3 (docs/models-cga.md §7; measured 4.5e-4 … 8.6e-4 for r = 1.5).
  const RoundParams sp = sphere_params(sphere(p1, p2, p3, p4));
  expect_near(sp.center, c, 1e-8);
  EXPECT_NEAR(sp.radius, r, 2e-3);
  const RoundParams rp = round_params(sphere(p1, p2, p3, p4));
  expect_near(rp.center, c, 1e-8);
  EXPECT_NEAR(rp.radius, r, 2e-3);
  const CircleParams cp = circle_params(circle(p1, p2, p3));
  const CircleParams local = circle_params(circle(p1 - c, p2 - c, p3 - c));
  expect_near(cp.round.center, local.round.center + c, 1e-8);
  EXPECT_NEAR(cp.round.radius, local.round.radius, 2e-3);
  const auto pts = pair_points(point_pair(p1, p2));  // measured 5e-5
  const bool order = dot(p1, p1) >= dot(p2, p2);
  expect_near(pts[0], order ? p1 : p2, 2e-4);
  expect_near(pts[1], order ? p2 : p1, 2e-4);
  const PlaneParams pl = plane_params(plane(p1, p2, p3));
  const Vec3d n = cross(p2 - p1, p3 - p1);
  expect_near(pl.normal, n / length(n), 1e-9);
  EXPECT_NEAR(pl.distance, dot(n / length(n), p1), 1e-6);
  expect_near(line_params(line(p1, p2)).closest_point,
              p1 - dot(p1, (p2 - p1) / length(p2 - p1)) * ((p2 - p1) / length(p2 - p1)), 1e-3);
  EXPECT_EQ(classify(sphere(p1, p2, p3, p4)), Kind::sphere);
  EXPECT_EQ(classify(circle(p1, p2, p3)), Kind::circle);
  EXPECT_EQ(classify(point_pair(p1, p2)), Kind::point_pair);
  // Motors keep their digits there too.
  expect_near(apply_to_point(translator({1, 1, 1}), c), c + Vec3d{1, 1, 1}, 1e-9);
}

TEST(CgaNearlyDegenerate, FourNearlyCoplanarPoints) {
  // Four points within a unit patch on the top of a sphere of radius 1000: their heights differ
  // by < 1e-3, yet the sphere through them is recovered.
  const Vec3d c{0, 0, -1000};
  const double r = 1000;
  auto top = [&](double x, double y) {
    return Vec3d{x, y, c.z + std::sqrt(r * r - x * x - y * y)};
  };
  const RoundParams sp =
      sphere_params(sphere(top(0.5, 0), top(0, 0.5), top(-0.5, 0.1), top(0.2, -0.5)));
  EXPECT_NEAR(sp.radius, r, 1e-6 * r);
  expect_near(sp.center, c, 1e-6 * r);
  // Nearly collinear: a circle through three points 1e-6 off a line.
  const CircleParams cp = circle_params(circle({0, 0, 0}, {1, 1e-6, 0}, {2, 0, 0}));
  EXPECT_NEAR(cp.round.radius, (1 + 1e-12) / 2e-6, 1e-3);
}

// ---- errors -----------------------------------------------------------------------------------

TEST(CgaErrors, EveryBadInputNamesTheProblem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_MODEL_ERROR(point_pair({1, 2, 3}, {1, 2, 3}), "coincide");
  EXPECT_MODEL_ERROR(point_pair({nan, 0, 0}, {1, 2, 3}), "not finite");
  EXPECT_MODEL_ERROR(line({1, 2, 3}, {1, 2, 3}), "coincide");
  EXPECT_MODEL_ERROR(line_from_point({1, 2, 3}, {0, 0, 0}), "direction is zero");
  EXPECT_MODEL_ERROR(line_from_point({1, 2, 3}, {0, nan, 0}), "not finite");
  EXPECT_MODEL_ERROR(circle({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), "collinear");
  EXPECT_MODEL_ERROR(circle({0, 0, 0}, {0, 0, 0}, {2, 2, 2}), "coincide");
  EXPECT_MODEL_ERROR(plane({0, 0, 0}, {1, 0, 0}, {3, 0, 0}), "collinear");
  EXPECT_MODEL_ERROR(sphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}), "coplanar");
  EXPECT_MODEL_ERROR(sphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}), "coincide");
  EXPECT_MODEL_ERROR(sphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}), "not finite");
  EXPECT_MODEL_ERROR(dual_sphere({0, 0, 0}, -1), "radius");
  EXPECT_MODEL_ERROR(dual_plane({0, 0, 0}, 1), "normal is zero");
  EXPECT_MODEL_ERROR(dual_circle({0, 0, 0}, {0, 0, 0}, 1), "normal is zero");
  EXPECT_MODEL_ERROR(rotor({0, 0, 0}, 1), "axis");
  EXPECT_MODEL_ERROR(dilator(0), "scale");
  EXPECT_MODEL_ERROR(line_params(circle({1, 0, 0}, {0, 1, 0}, {-1, 0, 0})), "direction");
  EXPECT_MODEL_ERROR(sphere_params(plane({1, 0, 0}, {0, 1, 0}, {0, 0, 1})), "plane");
  EXPECT_MODEL_ERROR(pair_params(line({1, 0, 0}, {0, 1, 0})), "grade-2");
  EXPECT_MODEL_ERROR(round_params(line({1, 0, 0}, {0, 1, 0})), "flat");
  EXPECT_MODEL_ERROR(location(e1() ^ einf()), "no location");
  // ModelError is an invalid_argument.
  EXPECT_THROW(dilator(-1), std::invalid_argument);
}
