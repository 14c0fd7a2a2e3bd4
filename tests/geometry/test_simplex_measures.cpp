// Simplices of every dimension k ≤ d in R(d,0,1): magnitude ‖S‖/k! (Def. 4.2) against the Gram
// determinant sqrt(det(EᵀE))/k!, the boundary form (Thm 4.1), and 4-D 5-cells against the
// Cayley–Menger determinant (exact rational arithmetic with GMP when available).
#include <gtest/gtest.h>

#include <random>

#include "pgamesh/geometry/simplex.hpp"
#include "support/golden.hpp"

#ifdef PGAMESH_HAVE_GMP
#include <gmpxx.h>
#endif

using namespace pgamesh;
using geometry::factorial;

namespace {

template <class T>
T determinant(
    std::vector<std::vector<T>> a) {  // fraction-free enough for exact T, pivoting for double
  const std::size_t n = a.size();
  T det = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && a[p][c] == 0) ++p;
    if (p == n) return 0;
    if (p != c) {
      std::swap(a[p], a[c]);
      det = -det;
    }
    det *= a[c][c];
    for (std::size_t r = c + 1; r < n; ++r) {
      const T f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
    }
  }
  return det;
}

// sqrt(det(EᵀE)) / k! with E the edge vectors v_i − v0: the k-volume, independent of PGA.
template <int D>
double gram_magnitude(const std::vector<pgad::Vec<D>>& v) {
  const std::size_t k = v.size() - 1;
  if (k == 0) return 1.0;
  std::vector<std::vector<double>> g(k, std::vector<double>(k));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      double s = 0;
      for (int c = 0; c < D; ++c) {
        const auto C = static_cast<std::size_t>(c);
        s += (v[i + 1][C] - v[0][C]) * (v[j + 1][C] - v[0][C]);
      }
      g[i][j] = s;
    }
  return std::sqrt(std::max(0.0, determinant(g))) / factorial(static_cast<int>(k));
}

template <int D>
void check_all_k() {
  std::mt19937_64 rng(300 + D);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k <= D; ++k) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<pgad::Vec<D>> v(static_cast<std::size_t>(k + 1));
      for (auto& p : v)
        for (double& x : p) x = u(rng);
      const double expected = gram_magnitude<D>(v);
      EXPECT_NEAR(geometry::magnitude<D>(v), expected, 1e-12 * (1 + expected))
          << "d=" << D << " k=" << k;
      if (k >= 1) {
        EXPECT_NEAR(geometry::magnitude_from_boundary<D>(v), expected, 1e-12 * (1 + expected))
            << "d=" << D << " k=" << k;
      }
      // the carrier has grade d − k; swapping two vertices flips its orientation
      const auto s = geometry::carrier<D>(v);
      for (clifford::BladeMask m = 0; m < s.size; ++m)
        if (clifford::grade_of(m) != D - k) {
          EXPECT_EQ(s.c[m], 0.0);
        }
      if (k >= 1) {
        std::swap(v[0], v[1]);
        const auto swapped = geometry::carrier<D>(v);
        for (std::size_t m = 0; m < s.size; ++m) EXPECT_NEAR(swapped.c[m], -s.c[m], 1e-12);
      }
    }
  }
}

}  // namespace

TEST(SimplexMagnitude, EveryKInEveryDimensionAgainstGramDeterminant) {
  check_all_k<1>();
  check_all_k<2>();
  check_all_k<3>();
  check_all_k<4>();
  check_all_k<5>();
  check_all_k<6>();
}

TEST(SimplexMagnitude, ClosedFormsInThreeDimensions) {
  // unit right triangle: area ½; regular tetrahedron of edge √2 (alternate cube corners): 1/3.
  const std::vector<pgad::Vec<3>> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_DOUBLE_EQ(geometry::magnitude<3>(tri), 0.5);
  const std::vector<pgad::Vec<3>> tet = {{0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_NEAR(geometry::magnitude<3>(tet), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(geometry::magnitude_from_boundary<3>(tet), 1.0 / 3.0, 1e-15);
  const std::vector<pgad::Vec<3>> edge = {{1, 2, 3}, {4, 6, 3}};
  EXPECT_DOUBLE_EQ(geometry::magnitude<3>(edge), 5.0);
}

TEST(SimplexMagnitude, GoldenFiveCellInR401) {
  const auto file = test::load_golden("pga_basics.json");
  for (const auto& c : file["cases"]) {
    if (c["id"] != "pga4_5cell") continue;
    std::vector<pgad::Vec<4>> v;
    for (const auto& p : c["input"]["points"])
      v.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>(), p[3].get<double>()});
    const auto t = test::tolerance_of(file, c);
    const auto s = geometry::carrier<4>(v);
    EXPECT_TRUE(test::near_scalar(s.c[0], c["expected"]["join"].get<double>(), t));
    EXPECT_TRUE(test::near_scalar(geometry::magnitude<4>(v),
                                  c["expected"]["hypervolume"].get<double>(), t));
    EXPECT_TRUE(test::near_scalar(pgad::ideal_norm(geometry::boundary_carrier<4>(v)),
                                  c["expected"]["boundary_ideal_norm"].get<double>(), t));
    return;
  }
  FAIL() << "pga4_5cell not in the golden file";
}

TEST(SimplexMagnitude, FiveCellsAgainstCayleyMenger) {
  // 288 V² = … for tetrahedra; for a 4-simplex: V² = −det(CM) / 9216, CM the 6×6 bordered matrix
  // of squared distances. Integer vertices make the join an exact integer in double arithmetic.
  std::mt19937_64 rng(41);
  std::uniform_int_distribution<int> u(-9, 9);
  for (int trial = 0; trial < 25; ++trial) {
    std::vector<pgad::Vec<4>> v(5);
    for (auto& p : v)
      for (double& x : p) x = u(rng);
    const double join = geometry::carrier<4>(v).c[0];  // 4! × signed hypervolume
#ifdef PGAMESH_HAVE_GMP
    std::vector<std::vector<mpq_class>> cm(6, std::vector<mpq_class>(6, 1));
#else
    std::vector<std::vector<double>> cm(6, std::vector<double>(6, 1));
#endif
    cm[0][0] = 0;
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = 0; j < 5; ++j) {
        double d2 = 0;
        for (std::size_t c = 0; c < 4; ++c) d2 += (v[i][c] - v[j][c]) * (v[i][c] - v[j][c]);
        cm[i + 1][j + 1] = d2;
      }
#ifdef PGAMESH_HAVE_GMP
    // (4!)² V² = 576 · (−det / 9216) = −det / 16, exactly.
    const mpq_class join2 = -determinant(cm) / 16;
    EXPECT_EQ(join2, mpq_class(join) * mpq_class(join)) << "trial " << trial;
#else
    EXPECT_NEAR(-determinant(cm) / 16, join * join, 1e-9 * (1 + join * join));
#endif
    EXPECT_NEAR(geometry::magnitude<4>(v), std::abs(join) / 24, 1e-12 * (1 + std::abs(join)));
  }
}

TEST(SimplexMagnitude, RejectsTooManyVertices) {
  const std::vector<pgad::Vec<2>> four = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  EXPECT_THROW(geometry::carrier<2>(four), std::invalid_argument);
}
