// Algebraic identities of the general engine on random inputs in R(3,0,1), R(4,1), R(4,4) (DPGA's
// null basis), R(8,2) (DCGA), R(9,6) (QCGA), and the change-of-basis path against geometric
// products computed directly from the bilinear form (an independent recursion on the user basis).
#include <gtest/gtest.h>

#include <map>

#include "test_clifford_util.hpp"

namespace pgamesh::clifford {
using pgamesh::test::mv_near;
using pgamesh::test::random_mv;
using pgamesh::test::random_vector;

namespace {

struct Case {
  const char* name;
  Algebra alg;
  int max_grade;  // random elements stay sparse so R(9,6) tests run fast
};

std::vector<Case> algebras() {
  return {{"R(3,0,1)", *make_algebra("pga3"), 4},     {"R(4,1)", *make_algebra("4,1,0"), 5},
          {"cga3", *make_algebra("cga3"), 5},         {"R(4,4) dpga", *make_algebra("dpga"), 5},
          {"R(4,4) diag", *make_algebra("4,4,0"), 5}, {"R(8,2) dcga", *make_algebra("dcga"), 4},
          {"R(9,6) qcga", *make_algebra("qcga"), 4}};
}

// ---- the reference: the geometric product straight from the Gram matrix, no change of basis ----
// Blades u_J are outer products of user generators. For a vector u_i:
//   u_i u_J = u_i ⌋ u_J + u_i ∧ u_J,  u_i ⌋ (u_j1 ∧ … ∧ u_jk) = Σ_m (−1)^(m−1) (u_i·u_jm) u_(J∖jm),
// and for a blade u_J = u_j1 ∧ R:  u_J Y = u_j1 (R Y) − (u_j1 ⌋ R) Y.
using Dict = std::map<BladeMask, double>;

void add(Dict& d, BladeMask m, double c) {
  d[m] += c;
}

Dict vector_times(const Algebra& alg, int i, const Dict& y) {
  Dict out;
  const BladeMask bit = BladeMask{1} << i;
  for (const auto& [m, c] : y) {
    if (!(m & bit)) add(out, m | bit, reorder_sign(bit, m) * c);
    int pos = 0;
    for (int j = 0; j < alg.dimension(); ++j) {
      if (!(m >> j & 1)) continue;
      const double g = alg.inner(i, j);
      if (g != 0) add(out, m & ~(BladeMask{1} << j), ((pos & 1) ? -1.0 : 1.0) * g * c);
      ++pos;
    }
  }
  return out;
}

Dict blade_times(const Algebra& alg, BladeMask blade, const Dict& y) {
  if (blade == 0) return y;
  const int j1 = std::countr_zero(blade);
  const BladeMask rest = blade & (blade - 1);
  Dict out = vector_times(alg, j1, blade_times(alg, rest, y));
  int pos = 0;  // subtract (u_j1 ⌋ R) Y
  for (int j = 0; j < alg.dimension(); ++j) {
    if (!(rest >> j & 1)) continue;
    const double g = alg.inner(j1, j);
    if (g != 0) {
      const Dict part = blade_times(alg, rest & ~(BladeMask{1} << j), y);
      for (const auto& [m, c] : part) add(out, m, -((pos & 1) ? -1.0 : 1.0) * g * c);
    }
    ++pos;
  }
  return out;
}

Multivector direct_geometric(const Algebra& alg, const Multivector& x, const Multivector& y) {
  Dict yd;
  for (const auto& t : y.terms) yd[t.mask] = t.coeff;
  Dict out;
  for (const auto& t : x.terms)
    for (const auto& [m, c] : blade_times(alg, t.mask, yd)) add(out, m, t.coeff * c);
  std::vector<Term> terms;
  for (const auto& [m, c] : out) terms.push_back({m, c});
  return from_terms(terms);
}

Multivector homogeneous(const Algebra& alg, std::mt19937_64& rng, int k, int count) {
  Multivector x = random_mv(alg, rng, count, k);
  return grade(x, k).is_zero() ? grade(random_mv(alg, rng, count + 4, k), k) : grade(x, k);
}

// ---- the fast paths against the plain definitions ----------------------------------------------

TEST(CliffordIdentities, ReorderSignCountsTranspositions) {
  // reorder_sign by one masked parity against the count of pairs i ∈ a, j ∈ b with i > j.
  for (BladeMask a = 0; a < 256; ++a)
    for (BladeMask b = 0; b < 256; ++b) {
      int swaps = 0;
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < i; ++j) swaps += (a >> i & 1) && (b >> j & 1);
      ASSERT_EQ(reorder_sign(a, b), (swaps & 1) ? -1.0 : 1.0) << a << " " << b;
    }
  EXPECT_EQ(reorder_sign(0x80000000u, 1u), -1.0);  // the top bit
  for (BladeMask m : {0u, 1u, 0b1011u, 0xffffffu, 0x80000001u}) {
    int bits = 0;
    for (BladeMask r = m; r != 0; r >>= 1) bits += static_cast<int>(r & 1u);
    EXPECT_EQ(grade_of(m), bits);
    EXPECT_EQ(odd_parity(m), (bits & 1) == 1);
  }
}

TEST(CliffordIdentities, SandwichEqualsTwoProducts) {
  // The small-algebra sandwich (stack arrays, one change of basis each way) against V X Ṽ by two
  // geometric products, also on the null bases (cga3 through the cached blade images).
  std::mt19937_64 rng(11);
  for (const auto& c : algebras()) {
    for (int trial = 0; trial < 10; ++trial) {
      const Multivector v = random_mv(c.alg, rng, 8, c.max_grade);
      const Multivector x = random_mv(c.alg, rng, 8, c.max_grade);
      EXPECT_TRUE(mv_near(sandwich(c.alg, v, x),
                          geometric(c.alg, geometric(c.alg, v, x), reverse(v)), 1e-12))
          << c.name;
    }
  }
}

TEST(CliffordIdentities, OuterWithAVectorMatchesTheGeneralKernel) {
  // A ∧ v takes the vector fast path; (−1)^k v ∧ A_k takes the general pair kernel.
  std::mt19937_64 rng(12);
  for (const auto& c : algebras()) {
    for (int trial = 0; trial < 10; ++trial) {
      const Multivector v = random_vector(c.alg, rng);
      const Multivector a = random_mv(c.alg, rng, 10, c.max_grade);
      Multivector expected;
      for (int k = 0; k <= c.alg.dimension(); ++k)
        expected = expected + involution_sign(k) * outer(c.alg, v, grade(a, k));
      EXPECT_TRUE(mv_near(outer(c.alg, a, v), expected, 1e-14)) << c.name;
    }
  }
}

}  // namespace

TEST(CliffordIdentities, ChangeOfBasisMatchesDirectBilinearForm) {
  std::mt19937_64 rng(7);
  for (const auto& c : algebras()) {
    for (int trial = 0; trial < 20; ++trial) {
      const Multivector a = random_mv(c.alg, rng, 6, std::min(c.max_grade, 4));
      const Multivector b = random_mv(c.alg, rng, 6, std::min(c.max_grade, 4));
      EXPECT_TRUE(mv_near(geometric(c.alg, a, b), direct_geometric(c.alg, a, b))) << c.name;
    }
    // Generators: u_i u_j + u_j u_i = 2 u_i·u_j.
    for (int i = 0; i < c.alg.dimension(); ++i)
      for (int j = 0; j < c.alg.dimension(); ++j) {
        const Multivector ui = basis_blade(BladeMask{1} << i), uj = basis_blade(BladeMask{1} << j);
        EXPECT_TRUE(mv_near(geometric(c.alg, ui, uj) + geometric(c.alg, uj, ui),
                            scalar(2 * c.alg.inner(i, j))))
            << c.name << " " << i << "," << j;
      }
  }
}

TEST(CliffordIdentities, EigenDecompositionPathForAGeneralForm) {
  // A full, indefinite, non-degenerate Gram matrix: no null pairs, so the eigen path is used.
  const Algebra alg = Algebra::bilinear_form({{2.0, 0.5, -0.25, 0.0},
                                              {0.5, -1.0, 0.75, 0.3},
                                              {-0.25, 0.75, 0.5, -0.6},
                                              {0.0, 0.3, -0.6, 1.5}},
                                             {"a", "b", "c", "d"});
  EXPECT_FALSE(alg.is_diagonal());
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const Multivector x = random_mv(alg, rng, 8, 4), y = random_mv(alg, rng, 8, 4);
    EXPECT_TRUE(mv_near(geometric(alg, x, y), direct_geometric(alg, x, y), 1e-11));
    EXPECT_TRUE(mv_near(alg.from_orthogonal(alg.to_orthogonal(x)), x, 1e-12));
  }
  EXPECT_EQ(alg.blade_name(0b1011).first, "a^b^d");
}

TEST(CliffordIdentities, AssociativityAndReversion) {
  std::mt19937_64 rng(3);
  for (const auto& c : algebras()) {
    for (int trial = 0; trial < 10; ++trial) {
      const Multivector a = random_mv(c.alg, rng, 6, c.max_grade);
      const Multivector b = random_mv(c.alg, rng, 6, c.max_grade);
      const Multivector d = random_mv(c.alg, rng, 6, c.max_grade);
      EXPECT_TRUE(mv_near(geometric(c.alg, geometric(c.alg, a, b), d),
                          geometric(c.alg, a, geometric(c.alg, b, d)), 1e-11))
          << c.name;
      EXPECT_TRUE(
          mv_near(outer(c.alg, outer(c.alg, a, b), d), outer(c.alg, a, outer(c.alg, b, d)), 1e-11))
          << c.name;
      EXPECT_TRUE(mv_near(regressive(c.alg, regressive(c.alg, a, b), d),
                          regressive(c.alg, a, regressive(c.alg, b, d)), 1e-11))
          << c.name;
      // (A B)~ = B~ A~, (A ∧ B)~ = B~ ∧ A~
      EXPECT_TRUE(
          mv_near(reverse(geometric(c.alg, a, b)), geometric(c.alg, reverse(b), reverse(a))))
          << c.name;
      EXPECT_TRUE(mv_near(reverse(outer(c.alg, a, b)), outer(c.alg, reverse(b), reverse(a))))
          << c.name;
      // involution is an automorphism, conjugation an anti-automorphism
      EXPECT_TRUE(mv_near(involution(geometric(c.alg, a, b)),
                          geometric(c.alg, involution(a), involution(b))))
          << c.name;
      EXPECT_TRUE(
          mv_near(conjugate(geometric(c.alg, a, b)), geometric(c.alg, conjugate(b), conjugate(a))))
          << c.name;
    }
  }
}

TEST(CliffordIdentities, DualityOfJoinAndMeet) {
  std::mt19937_64 rng(5);
  for (const auto& c : algebras()) {
    const int n = c.alg.dimension();
    for (int trial = 0; trial < 10; ++trial) {
      const Multivector a = random_mv(c.alg, rng, 6, c.max_grade);
      const Multivector b = random_mv(c.alg, rng, 6, c.max_grade);
      EXPECT_TRUE(mv_near(undual(c.alg, dual(c.alg, a)), a)) << c.name;
      EXPECT_TRUE(mv_near(dual(c.alg, undual(c.alg, a)), a)) << c.name;
      // (A ∨ B)* = A* ∧ B* and (A ∧ B)* = A* ∨ B*: join and meet are dual to each other.
      EXPECT_TRUE(mv_near(dual(c.alg, regressive(c.alg, a, b)),
                          outer(c.alg, dual(c.alg, a), dual(c.alg, b))))
          << c.name;
      EXPECT_TRUE(mv_near(dual(c.alg, outer(c.alg, a, b)),
                          regressive(c.alg, dual(c.alg, a), dual(c.alg, b))))
          << c.name;
      // Graded antisymmetry A_r ∨ B_s = (−1)^((n−r)(n−s)) B_s ∨ A_r.
      const int r = 1 + trial % (n - 1), s = 1 + (trial * 3) % (n - 1);
      const Multivector ar = homogeneous(c.alg, rng, r, 5), bs = homogeneous(c.alg, rng, s, 5);
      const double sign = (((n - r) * (n - s)) & 1) ? -1.0 : 1.0;
      EXPECT_TRUE(mv_near(regressive(c.alg, ar, bs), sign * regressive(c.alg, bs, ar))) << c.name;
    }
  }
}

TEST(CliffordIdentities, ContractionIdentities) {
  std::mt19937_64 rng(9);
  for (const auto& c : algebras()) {
    for (int trial = 0; trial < 10; ++trial) {
      const Multivector a = random_mv(c.alg, rng, 5, 3), b = random_mv(c.alg, rng, 5, 3);
      const Multivector d = random_mv(c.alg, rng, 5, c.max_grade);
      // (A ∧ B) ⌋ C = A ⌋ (B ⌋ C) and C ⌊ (B ∧ A) = (C ⌊ B) ⌊ A
      EXPECT_TRUE(mv_near(left_contraction(c.alg, outer(c.alg, a, b), d),
                          left_contraction(c.alg, a, left_contraction(c.alg, b, d)), 1e-11))
          << c.name;
      EXPECT_TRUE(mv_near(right_contraction(c.alg, d, outer(c.alg, b, a)),
                          right_contraction(c.alg, right_contraction(c.alg, d, b), a), 1e-11))
          << c.name;
      // a X = a ⌋ X + a ∧ X for a vector; X a = X ⌊ a + X ∧ a
      const Multivector v = random_vector(c.alg, rng);
      EXPECT_TRUE(
          mv_near(geometric(c.alg, v, d), left_contraction(c.alg, v, d) + outer(c.alg, v, d)))
          << c.name;
      EXPECT_TRUE(
          mv_near(geometric(c.alg, d, v), right_contraction(c.alg, d, v) + outer(c.alg, d, v)))
          << c.name;
      // a ⌋ (B_k ∧ C) = (a ⌋ B_k) ∧ C + (−1)^k B_k ∧ (a ⌋ C): the contraction is a derivation
      const int k = 1 + trial % 3;
      const Multivector bk = homogeneous(c.alg, rng, k, 4);
      EXPECT_TRUE(mv_near(left_contraction(c.alg, v, outer(c.alg, bk, a)),
                          outer(c.alg, left_contraction(c.alg, v, bk), a) +
                              involution_sign(k) * outer(c.alg, bk, left_contraction(c.alg, v, a))))
          << c.name;
      // scalar product and the symmetric inner product of equal grades agree
      const Multivector b2 = homogeneous(c.alg, rng, 2, 5), c2 = homogeneous(c.alg, rng, 2, 5);
      EXPECT_NEAR(scalar_product(c.alg, b2, c2), scalar_part(inner(c.alg, b2, c2)), 1e-12);
      // commutator of vectors is their outer product
      const Multivector w = random_vector(c.alg, rng);
      EXPECT_TRUE(mv_near(commutator(c.alg, v, w), outer(c.alg, v, w))) << c.name;
    }
  }
}

TEST(CliffordIdentities, MetricDualIsDualToOuter) {
  // (A ∧ B) I⁻¹ = A ⌋ (B I⁻¹) in non-degenerate algebras (outer and contraction are dual).
  std::mt19937_64 rng(13);
  for (const char* name : {"4,1,0", "cga3", "dpga", "dcga"}) {
    const Algebra alg = *make_algebra(name);
    for (int trial = 0; trial < 8; ++trial) {
      const Multivector a = random_mv(alg, rng, 4, 3), b = random_mv(alg, rng, 4, 3);
      EXPECT_TRUE(mv_near(metric_dual(alg, outer(alg, a, b)),
                          left_contraction(alg, a, metric_dual(alg, b)), 1e-11))
          << name;
    }
  }
  EXPECT_THROW(metric_dual(*make_algebra("pga3"), scalar(1.0)), std::domain_error);
}

TEST(CliffordIdentities, VersorsInversesAndExponentials) {
  std::mt19937_64 rng(17);
  for (const auto& c : algebras()) {
    // A versor: product of three random vectors; V V⁻¹ = 1 when V Ṽ ≠ 0.
    Multivector v = random_vector(c.alg, rng);
    v = geometric(c.alg, v, random_vector(c.alg, rng));
    v = geometric(c.alg, v, random_vector(c.alg, rng));
    if (std::abs(norm_squared(c.alg, v)) > 1e-3) {
      EXPECT_TRUE(mv_near(geometric(c.alg, v, inverse(c.alg, v)), scalar(1.0), 1e-10)) << c.name;
    }
    // exp of a simple bivector (B² scalar): closed form equals the series on B/2 squared.
    const Multivector x = random_vector(c.alg, rng), y = random_vector(c.alg, rng);
    const Multivector bv = 0.7 * outer(c.alg, x, y);
    const Multivector e = exp(c.alg, bv);
    const Multivector half = exp(c.alg, 0.5 * bv);
    EXPECT_TRUE(mv_near(geometric(c.alg, half, half), e, 1e-11)) << c.name;
    EXPECT_NEAR(norm_squared(c.alg, e), 1.0, 1e-11) << c.name;  // R R~ = 1 for a rotor
  }
  EXPECT_THROW(inverse(*make_algebra("pga3"), basis_blade(1)), std::domain_error);  // e0
}

TEST(CliffordIdentities, ExpSeriesForNonSimpleBivectors) {
  // In R(4,0) B = a e12 + b e34 is not simple; exp(B) = exp(a e12) exp(b e34) (commuting parts).
  const Algebra alg = *make_algebra("4,0,0");
  const Multivector b12 = basis_blade(0b0011, 0.8), b34 = basis_blade(0b1100, -1.3);
  const Multivector expected = geometric(alg, exp(alg, b12), exp(alg, b34));
  EXPECT_TRUE(mv_near(exp(alg, b12 + b34), expected, 1e-13));
  EXPECT_NEAR(exp(alg, b12)[0], std::cos(0.8), 1e-15);
}

TEST(CliffordIdentities, Pga3MotorExpLogRoundTrip) {
  // Screw motors: log(exp(L)) = L for non-simple L; the motor moves a point as docs/conventions.md
  // §7 says.
  const Algebra alg = *make_algebra("pga3");
  std::mt19937_64 rng(19);
  for (int trial = 0; trial < 20; ++trial) {
    const Multivector l = grade(random_mv(alg, rng, 12, 2), 2);
    const Multivector m = exp(alg, l);
    EXPECT_NEAR(scalar_part(geometric(alg, m, reverse(m))), 1.0, 1e-12);
    EXPECT_TRUE(mv_near(geometric(alg, m, reverse(m)), scalar(1.0), 1e-12));
    if (std::sqrt(norm_squared(alg, grade(l, 2))) < 3.0) {  // principal branch |ψ| < π
      EXPECT_TRUE(mv_near(log(alg, m), l, 1e-10));
    }
  }
  // T = 1 − ½ (t_x e01 + t_y e02 + t_z e03) translates the origin to t (docs/conventions.md §7).
  const Multivector t = scalar(1.0) - 0.5 * (basis_blade(0b0011, 1.0) + basis_blade(0b0101, 2.0) +
                                             basis_blade(0b1001, 3.0));
  const Multivector o = basis_blade(0b1110);
  const Multivector moved = sandwich(alg, t, o);
  EXPECT_NEAR(moved[0b1110], 1.0, 1e-15);
  const auto x_blade = alg.parse_blade("e032");
  EXPECT_NEAR(x_blade->second * moved[x_blade->first], 1.0, 1e-15);
  const auto y_blade = alg.parse_blade("e013");
  EXPECT_NEAR(y_blade->second * moved[y_blade->first], 2.0, 1e-15);
  const auto z_blade = alg.parse_blade("e021");
  EXPECT_NEAR(z_blade->second * moved[z_blade->first], 3.0, 1e-15);
  EXPECT_TRUE(mv_near(exp(alg, log(alg, t)), t, 1e-15));
}

TEST(CliffordIdentities, QcgaOuterOfNineVectorsIsDualToNinePoints) {
  // Nine vectors in R(9,6): the 9-blade is non-zero, antisymmetric under a swap, and vanishes
  // when a vector repeats; it has at most C(15,9) = 5005 terms.
  const Algebra alg = *make_algebra("qcga");
  std::mt19937_64 rng(23);
  std::vector<Multivector> v;
  for (int i = 0; i < 9; ++i) v.push_back(random_vector(alg, rng));
  Multivector w = scalar(1.0), swapped = scalar(1.0);
  for (int i = 0; i < 9; ++i) w = outer(alg, w, v[static_cast<std::size_t>(i)]);
  for (int i : {1, 0, 2, 3, 4, 5, 6, 7, 8})
    swapped = outer(alg, swapped, v[static_cast<std::size_t>(i)]);
  EXPECT_EQ(grades_present(w), 1u << 9);
  EXPECT_LE(w.terms.size(), 5005u);
  EXPECT_GT(w.terms.size(), 4000u);
  EXPECT_TRUE(mv_near(w + swapped, Multivector{}, 1e-12));
  EXPECT_TRUE(outer(alg, w, v[3]).is_zero() || max_abs_coeff(outer(alg, w, v[3])) < 1e-12);
}

}  // namespace pgamesh::clifford
