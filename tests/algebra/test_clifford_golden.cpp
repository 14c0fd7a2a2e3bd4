// The general engine against the golden files: pga_basics.json (R(3,0,1) products, involutions,
// duals, joins; project basis names) and cga.json (R(4,1) outer products of conformal points, in
// the null basis eo, e1, e2, e3, einf).
#include <gtest/gtest.h>

#include "test_clifford_util.hpp"

namespace pgamesh::clifford {
using pgamesh::test::from_golden;
using pgamesh::test::json;
using pgamesh::test::near_golden;

namespace {

Algebra pga3() {
  return *make_algebra("pga3");
}

Multivector pga_point(const Algebra& alg, const json& p) {
  // docs/conventions.md §2: (x,y,z) ↦ (e0 + x e1 + y e2 + z e3)*.
  Multivector v = basis_blade(1);
  for (int i = 0; i < 3; ++i) v = v + basis_blade(BladeMask{2} << i, p[i].get<double>());
  return dual(alg, v);
}

Multivector pga_plane(const json& p) {
  return basis_blade(2, p[0].get<double>()) + basis_blade(4, p[1].get<double>()) +
         basis_blade(8, p[2].get<double>()) + basis_blade(1, p[3].get<double>());
}

}  // namespace

TEST(CliffordGolden, Pga3BasisNamesAndDualTable) {
  const json file = pgamesh::test::load_golden("pga_basics.json");
  const Algebra alg = pga3();
  for (const auto& name : file["basis"]) {
    const auto b = alg.parse_blade(name.get<std::string>());
    ASSERT_TRUE(b) << name;
    EXPECT_EQ(alg.blade_name(b->first).first, name.get<std::string>());
  }
  const pgamesh::test::Tolerance t{};
  int checked = 0;
  for (const auto& row : file["dual_table"]) {
    const Multivector x = from_golden(alg, json{{row["blade"].get<std::string>(), 1.0}});
    EXPECT_TRUE(near_golden(alg, dual(alg, x), row["dual"], t)) << row["blade"];
    EXPECT_TRUE(near_golden(alg, undual(alg, x), row["undual"], t)) << row["blade"];
    ++checked;
  }
  EXPECT_EQ(checked, 16);
}

TEST(CliffordGolden, Pga3MultivectorProducts) {
  const json file = pgamesh::test::load_golden("pga_basics.json");
  const Algebra alg = pga3();
  int cases = 0;
  for (const auto& c : file["cases"]) {
    if (c["id"].get<std::string>().rfind("multivector_", 0) != 0) continue;
    ++cases;
    const auto t = pgamesh::test::tolerance_of(file, c);
    const Multivector x = from_golden(alg, c["input"]["X"]);
    const Multivector y = from_golden(alg, c["input"]["Y"]);
    const json& e = c["expected"];
    EXPECT_TRUE(near_golden(alg, geometric(alg, x, y), e["geometric"], t));
    EXPECT_TRUE(near_golden(alg, outer(alg, x, y), e["outer"], t));
    EXPECT_TRUE(near_golden(alg, inner(alg, x, y), e["inner"], t));
    EXPECT_TRUE(near_golden(alg, left_contraction(alg, x, y), e["left_contraction"], t));
    EXPECT_TRUE(near_golden(alg, regressive(alg, x, y), e["join"], t));
    EXPECT_TRUE(near_golden(alg, reverse(x), e["reverse_X"], t));
    EXPECT_TRUE(near_golden(alg, involution(x), e["involute_X"], t));
    EXPECT_TRUE(near_golden(alg, conjugate(x), e["conjugate_X"], t));
    EXPECT_TRUE(near_golden(alg, dual(alg, x), e["dual_X"], t));
    EXPECT_TRUE(near_golden(alg, undual(alg, x), e["undual_X"], t));
  }
  EXPECT_EQ(cases, 2);
}

TEST(CliffordGolden, Pga3JoinsAndMeets) {
  const json file = pgamesh::test::load_golden("pga_basics.json");
  const Algebra alg = pga3();
  int cases = 0;
  for (const auto& c : file["cases"]) {
    if (c["id"].get<std::string>().rfind("joins_", 0) != 0) continue;
    ++cases;
    const auto t = pgamesh::test::tolerance_of(file, c);
    const json& in = c["input"];
    const json& e = c["expected"];
    const Multivector a = pga_point(alg, in["a"]), b = pga_point(alg, in["b"]),
                      cc = pga_point(alg, in["c"]), d = pga_point(alg, in["d"]);
    const Multivector p = pga_plane(in["plane"]);
    const Multivector o = basis_blade(0b1110);  // e123
    const Multivector ab = regressive(alg, a, b);
    const Multivector abc = regressive(alg, ab, cc);
    EXPECT_TRUE(near_golden(alg, ab, e["line_ab"], t));
    EXPECT_TRUE(near_golden(alg, abc, e["plane_abc"], t));
    EXPECT_TRUE(pgamesh::test::near_scalar(scalar_part(regressive(alg, abc, o)),
                                           e["plane_abc_join_origin"].get<double>(), t));
    EXPECT_TRUE(pgamesh::test::near_scalar(scalar_part(regressive(alg, o, abc)),
                                           e["origin_join_plane_abc"].get<double>(), t));
    EXPECT_TRUE(pgamesh::test::near_scalar(scalar_part(regressive(alg, abc, d)),
                                           e["join_abcd"].get<double>(), t));
    EXPECT_TRUE(pgamesh::test::near_scalar(scalar_part(regressive(alg, p, a)),
                                           e["plane_join_a"].get<double>(), t));
    EXPECT_TRUE(pgamesh::test::near_scalar(scalar_part(regressive(alg, a, p)),
                                           e["a_join_plane"].get<double>(), t));
    EXPECT_TRUE(near_golden(alg, outer(alg, ab, p), e["meet_line_ab_plane"], t));
    EXPECT_TRUE(near_golden(alg, outer(alg, abc, p), e["meet_plane_abc_plane"], t));
  }
  EXPECT_GE(cases, 5);
}

TEST(CliffordGolden, Pga3ThreePlanes) {
  const json file = pgamesh::test::load_golden("pga_basics.json");
  const Algebra alg = pga3();
  int cases = 0;
  for (const auto& c : file["cases"]) {
    if (c["id"].get<std::string>().rfind("three_planes_", 0) != 0) continue;
    ++cases;
    const auto t = pgamesh::test::tolerance_of(file, c);
    const json& pl = c["input"]["planes"];
    const Multivector p1 = pga_plane(pl[0]), p2 = pga_plane(pl[1]), p3 = pga_plane(pl[2]);
    EXPECT_TRUE(near_golden(alg, outer(alg, outer(alg, p1, p2), p3), c["expected"]["meet"], t));
    if (c["expected"].contains("line_p1p2")) {
      EXPECT_TRUE(near_golden(alg, outer(alg, p1, p2), c["expected"]["line_p1p2"], t));
    }
  }
  EXPECT_EQ(cases, 2);
}

namespace {
// Conformal point X = x + ½ x² e∞ + e_o (docs/conventions.md §15), built in the null basis.
Multivector cga_point(const Algebra& alg, const json& p) {
  double x2 = 0;
  Multivector x = basis_blade(alg.parse_blade("eo")->first);
  for (int i = 0; i < 3; ++i) {
    const double xi = p[i].get<double>();
    x2 += xi * xi;
    x = x + basis_blade(BladeMask{2} << i, xi);
  }
  return x + basis_blade(16, 0.5 * x2);
}
}  // namespace

TEST(CliffordGolden, CgaOuterProductsOfPoints) {
  const json file = pgamesh::test::load_golden("cga.json");
  const Algebra alg = *make_algebra("cga3");
  const Multivector ei = basis_blade(16);
  int checked = 0;
  for (const auto& c : file["cases"]) {
    const auto t = pgamesh::test::tolerance_of(file, c);
    const std::string id = c["id"];
    const json& in = c["input"];
    const json& expected = c["expected"]["blades"];  // e∞ is "einf" there, an alias of "ei"
    Multivector got;
    if (id.rfind("point_", 0) == 0) {
      got = cga_point(alg, in["point"]);
      EXPECT_NEAR(scalar_product(alg, got, got), 0.0, 1e-12) << id;  // X² = 0
    } else if (id.rfind("pair_", 0) == 0) {
      got = outer(alg, cga_point(alg, in["p1"]), cga_point(alg, in["p2"]));
    } else if (id.rfind("line_", 0) == 0) {
      got = outer(alg, outer(alg, cga_point(alg, in["p1"]), cga_point(alg, in["p2"])), ei);
    } else if (id.rfind("plane_", 0) == 0) {
      got = outer(alg, outer(alg, cga_point(alg, in["p1"]), cga_point(alg, in["p2"])),
                  outer(alg, cga_point(alg, in["p3"]), ei));
    } else if (id.rfind("circle_", 0) == 0 || id.rfind("sphere_", 0) == 0) {
      got = scalar(1.0);
      for (const auto& p : in["points"]) got = outer(alg, got, cga_point(alg, p));
    } else {
      continue;
    }
    EXPECT_TRUE(near_golden(alg, got, expected, t)) << id;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

TEST(CliffordGolden, CgaMetricOfNullBasis) {
  const Algebra alg = *make_algebra("cga3");
  const Multivector eo = basis_blade(1), ei = basis_blade(16);
  // docs/conventions.md §15; exact through the change of basis.
  EXPECT_EQ(scalar_product(alg, eo, ei), -1.0);
  EXPECT_EQ(scalar_product(alg, eo, eo), 0.0);
  EXPECT_EQ(scalar_product(alg, ei, ei), 0.0);
  // N = e∞ ∧ e_o squares to +1; e_o e∞ = −1 + e_o ∧ e∞.
  const Multivector n = outer(alg, ei, eo);
  EXPECT_TRUE(pgamesh::test::mv_near(geometric(alg, n, n), scalar(1.0)));
  EXPECT_TRUE(pgamesh::test::mv_near(geometric(alg, eo, ei), scalar(-1.0) + basis_blade(17)));
  EXPECT_EQ(alg.blade_name(17).first, "eo^ei");
  EXPECT_EQ(alg.parse_blade("eo^einf")->first, 17u);
  EXPECT_EQ(alg.parse_blade("einf^eo")->second, -1.0);
}

}  // namespace pgamesh::clifford
