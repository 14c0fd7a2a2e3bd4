// PGA R(d,0,1) for compile-time d: agreement with the general engine for every d = 1…6, with the
// PGA3 fast path (joins, motors) for d = 3, the golden R(3,0,1) joins, and the embedding identities
// o ∨ v1 ∨ … ∨ vd = det[v1 … vd], S ∨ o = (−1)^d o ∨ S (docs/conventions.md §5).
#include <gtest/gtest.h>

#include <random>

#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/algebra/pgad.hpp"
#include "support/golden.hpp"

using namespace pgamesh;
using pgamesh::test::json;

namespace {

template <int D>
pgad::Multivector<D> random_pgad(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  pgad::Multivector<D> m;
  for (double& c : m.c) c = u(rng);
  return m;
}

template <int D>
clifford::Multivector to_general(const pgad::Multivector<D>& m) {
  std::vector<clifford::Term> t;
  for (clifford::BladeMask i = 0; i < m.size; ++i) t.push_back({i, m.c[i]});
  return clifford::from_terms(t);
}

template <int D>
::testing::AssertionResult same(const pgad::Multivector<D>& a, const clifford::Multivector& b,
                                double tol = 1e-12) {
  for (clifford::BladeMask i = 0; i < a.size; ++i)
    if (std::abs(a.c[i] - b[i]) > tol * (1 + std::abs(b[i])))
      return ::testing::AssertionFailure() << "blade " << i << ": " << a.c[i] << " vs " << b[i];
  return ::testing::AssertionSuccess();
}

template <int D>
pgad::Vec<D> random_vec(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-2, 2);
  pgad::Vec<D> v;
  for (double& x : v) x = u(rng);
  return v;
}

// Determinant by Gaussian elimination with partial pivoting (an independent reference).
double determinant(std::vector<std::vector<double>> a) {
  const std::size_t n = a.size();
  double det = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    if (a[p][c] == 0) return 0;
    if (p != c) {
      std::swap(a[p], a[c]);
      det = -det;
    }
    det *= a[c][c];
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return det;
}

template <int D>
void check_against_general_engine() {
  const clifford::Algebra alg = clifford::Algebra::signature(D, 0, 1);
  std::mt19937_64 rng(100 + D);
  for (int trial = 0; trial < 5; ++trial) {
    const auto a = random_pgad<D>(rng), b = random_pgad<D>(rng);
    const auto ga = to_general(a), gb = to_general(b);
    EXPECT_TRUE(same(pgad::geometric(a, b), clifford::geometric(alg, ga, gb))) << "d=" << D;
    EXPECT_TRUE(same(pgad::outer(a, b), clifford::outer(alg, ga, gb))) << "d=" << D;
    EXPECT_TRUE(same(pgad::join(a, b), clifford::regressive(alg, ga, gb))) << "d=" << D;
    EXPECT_TRUE(same(pgad::inner(a, b), clifford::inner(alg, ga, gb))) << "d=" << D;
    EXPECT_TRUE(same(pgad::left_contraction(a, b), clifford::left_contraction(alg, ga, gb)));
    EXPECT_TRUE(same(pgad::dual(a), clifford::dual(alg, ga))) << "d=" << D;
    EXPECT_TRUE(same(pgad::undual(a), clifford::undual(alg, ga))) << "d=" << D;
    EXPECT_TRUE(same(pgad::reverse(a), clifford::reverse(ga))) << "d=" << D;
    // a simple bivector (a translation or rotation generator) exponentiates identically
    const auto p = pgad::point<D>(random_vec<D>(rng)), q = pgad::point<D>(random_vec<D>(rng));
    const auto line = pgad::join(p, q);
    EXPECT_TRUE(same(pgad::exp(0.3 * line), clifford::exp(alg, 0.3 * to_general(line)), 1e-12));
  }
}

template <int D>
void check_embedding_identities() {
  std::mt19937_64 rng(200 + D);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<pgad::Vec<D>> v;
    for (int i = 0; i < D; ++i) v.push_back(random_vec<D>(rng));
    pgad::Multivector<D> s = pgad::point<D>(v[0]);
    for (int i = 1; i < D; ++i) s = pgad::join(s, pgad::point<D>(v[static_cast<std::size_t>(i)]));
    const auto o = pgad::origin<D>();
    std::vector<std::vector<double>> m(D, std::vector<double>(D));
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
            v[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];  // columns v_j
    const double det = determinant(m);
    EXPECT_NEAR(pgad::join(o, s).c[0], det, 1e-12 * (1 + std::abs(det))) << "d=" << D;
    const double sign = (D % 2) ? -1.0 : 1.0;
    EXPECT_NEAR(pgad::join(s, o).c[0], sign * det, 1e-12 * (1 + std::abs(det))) << "d=" << D;
    // the point round-trips through weight and position
    const auto x = random_vec<D>(rng);
    const auto px = 2.5 * pgad::point<D>(x);
    EXPECT_DOUBLE_EQ(pgad::weight(px), 2.5);
    for (int i = 0; i < D; ++i)
      EXPECT_NEAR(pgad::position(px)[static_cast<std::size_t>(i)], x[static_cast<std::size_t>(i)],
                  1e-15);
    // a translator 1 − ½ t e0 moves a point by t (docs/conventions.md §7 motor convention in any d)
    const auto t = random_vec<D>(rng);
    pgad::Multivector<D> tr = pgad::scalar<D>(1.0);
    for (int i = 0; i < D; ++i) tr[1u | (2u << i)] = -0.5 * t[static_cast<std::size_t>(i)];  // e0i
    const auto moved = pgad::position(pgad::sandwich(tr, pgad::point<D>(x)));
    for (int i = 0; i < D; ++i)
      EXPECT_NEAR(moved[static_cast<std::size_t>(i)],
                  x[static_cast<std::size_t>(i)] + t[static_cast<std::size_t>(i)], 1e-14);
  }
}

}  // namespace

TEST(Pgad, AgreesWithGeneralEngineInEveryDimension) {
  check_against_general_engine<1>();
  check_against_general_engine<2>();
  check_against_general_engine<3>();
  check_against_general_engine<4>();
  check_against_general_engine<5>();
  check_against_general_engine<6>();
}

TEST(Pgad, EmbeddingIdentitiesInEveryDimension) {
  check_embedding_identities<1>();
  check_embedding_identities<2>();
  check_embedding_identities<3>();
  check_embedding_identities<4>();
  check_embedding_identities<5>();
  check_embedding_identities<6>();
}

TEST(Pgad, AgreesWithPga3FastPath) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3d a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const auto pa = pgad::point<3>({a.x, a.y, a.z}), pb = pgad::point<3>({b.x, b.y, b.z}),
               pc = pgad::point<3>({c.x, c.y, c.z});
    const auto fa = pga3::point(a), fb = pga3::point(b), fc = pga3::point(c);
    // line: e01 = mask 0b0011, e02 = 0b0101, e03 = 0b1001, e12 = 0b0110, e31 = −e13 = −0b1010,
    // e23 = 0b1100
    const auto l = pgad::join(pa, pb);
    const pga3::Line<double> fl = pga3::join(fa, fb);
    EXPECT_NEAR(l[0b0011], fl.e01, 1e-12);
    EXPECT_NEAR(l[0b0101], fl.e02, 1e-12);
    EXPECT_NEAR(l[0b1001], fl.e03, 1e-12);
    EXPECT_NEAR(l[0b0110], fl.e12, 1e-12);
    EXPECT_NEAR(-l[0b1010], fl.e31, 1e-12);
    EXPECT_NEAR(l[0b1100], fl.e23, 1e-12);
    const auto f = pgad::join(l, pc);
    const pga3::Plane<double> ff = pga3::join(fa, fb, fc);
    EXPECT_NEAR(f[0b0001], ff.e0, 1e-11);
    EXPECT_NEAR(f[0b0010], ff.e1, 1e-11);
    EXPECT_NEAR(f[0b0100], ff.e2, 1e-11);
    EXPECT_NEAR(f[0b1000], ff.e3, 1e-11);
    // a motor: rotor about a random axis then a translation, applied to a point both ways
    const double angle = u(rng);
    const Vec3d axis = Vec3d{u(rng), u(rng), u(rng)} / length(Vec3d{u(rng), u(rng), u(rng)});
    const pga3::Motor<double> m =
        pga3::translator(Vec3d{u(rng), u(rng), u(rng)}) * pga3::rotor(angle, axis / length(axis));
    pgad::Multivector<3> gm{};
    gm[0] = m.s;
    gm[0b0011] = m.e01;
    gm[0b0101] = m.e02;
    gm[0b1001] = m.e03;
    gm[0b0110] = m.e12;
    gm[0b1010] = -m.e31;
    gm[0b1100] = m.e23;
    gm[0b1111] = m.e0123;
    const auto moved = pgad::position(pgad::sandwich(gm, pa));
    const Vec3d fast = pga3::apply(m, fa).euclidean();
    EXPECT_NEAR(moved[0], fast.x, 1e-11);
    EXPECT_NEAR(moved[1], fast.y, 1e-11);
    EXPECT_NEAR(moved[2], fast.z, 1e-11);
    // log/exp of the screw motor round-trips (d = 3 closed form)
    const auto back = pgad::exp(pgad::log(gm));
    for (std::size_t i = 0; i < gm.size; ++i) EXPECT_NEAR(back.c[i], gm.c[i], 1e-10);
  }
}

TEST(Pgad, GoldenJoinsInR301) {
  const json file = test::load_golden("pga_basics.json");
  int cases = 0;
  for (const auto& c : file["cases"]) {
    if (c["id"].get<std::string>().rfind("joins_", 0) != 0) continue;
    ++cases;
    const auto t = test::tolerance_of(file, c);
    auto pt = [](const json& j) {
      return pgad::point<3>({j[0].get<double>(), j[1].get<double>(), j[2].get<double>()});
    };
    const json& in = c["input"];
    const json& e = c["expected"];
    const auto ab = pgad::join(pt(in["a"]), pt(in["b"]));
    const auto abc = pgad::join(ab, pt(in["c"]));
    EXPECT_TRUE(test::near_scalar(pgad::norm(ab), e["line_ab_norm"].get<double>(), t));
    EXPECT_TRUE(test::near_scalar(pgad::ideal_norm(ab), e["line_ab_ideal_norm"].get<double>(), t));
    EXPECT_TRUE(test::near_scalar(pgad::norm(abc), e["plane_abc_norm"].get<double>(), t));
    EXPECT_TRUE(
        test::near_scalar(pgad::ideal_norm(abc), e["plane_abc_ideal_norm"].get<double>(), t));
    EXPECT_TRUE(
        test::near_scalar(pgad::join(abc, pt(in["d"])).c[0], e["join_abcd"].get<double>(), t));
    EXPECT_TRUE(test::near_group({abc[1], abc[2], abc[4], abc[8]},
                                 {e["plane_abc"].value("e0", 0.0), e["plane_abc"].value("e1", 0.0),
                                  e["plane_abc"].value("e2", 0.0), e["plane_abc"].value("e3", 0.0)},
                                 t));
    const auto& pl = in["plane"];
    const auto p = pgad::hyperplane<3>(
        {pl[0].get<double>(), pl[1].get<double>(), pl[2].get<double>()}, pl[3].get<double>());
    EXPECT_TRUE(
        test::near_scalar(pgad::join(p, pt(in["a"])).c[0], e["plane_join_a"].get<double>(), t));
  }
  EXPECT_GE(cases, 5);
}

TEST(Pgad, TwoDimensionalMotors) {
  // R(2,0,1): rotation about the origin by θ is exp(−½ θ e12)... with e12 = (e1 e2): the rotor
  // cos(θ/2) − sin(θ/2) e12 rotates +θ (counter-clockwise), as in 3-D about the z axis.
  const double theta = 0.9;
  const auto r = pgad::exp(pgad::blade<2>(0b110, -theta / 2));
  const auto moved = pgad::position(pgad::sandwich(r, pgad::point<2>({1.0, 0.0})));
  EXPECT_NEAR(moved[0], std::cos(theta), 1e-15);
  EXPECT_NEAR(moved[1], std::sin(theta), 1e-15);
  const auto l = pgad::log(r);
  EXPECT_NEAR(l[0b110], -theta / 2, 1e-15);
}

TEST(Pgad, FourDimensionalDoubleRotation) {
  // A non-simple bivector in R(4,0,1): B = a e12 + b e34. exp(B) = exp(a e12) exp(b e34), and the
  // invariant decomposition gives log back (test_pgad_log.cpp has the random cases).
  const auto b12 = pgad::blade<4>(0b00110, 0.4), b34 = pgad::blade<4>(0b11000, -1.1);
  const auto e = pgad::exp(b12 + b34);
  const auto expected = pgad::geometric(pgad::exp(b12), pgad::exp(b34));
  for (std::size_t i = 0; i < e.size; ++i) EXPECT_NEAR(e.c[i], expected.c[i], 1e-14);
  const auto l = pgad::log(e);
  const auto b = b12 + b34;
  for (std::size_t i = 0; i < l.size; ++i) EXPECT_NEAR(l.c[i], b.c[i], 1e-14);
}
