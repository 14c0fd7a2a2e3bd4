// Every R(3,0,1) case of golden/pga_basics.json (docs/conventions.md §1–§7): the dual table, point
// embedding, joins and meets with the grade types and with the general Multivector, the general
// products and involutions, norms, and the 3-D polygon area from boundary edges.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"
#include "support/golden.hpp"

namespace pgamesh::pga3 {
namespace {

using pgamesh::test::json;
using pgamesh::test::near_group;
using pgamesh::test::near_scalar;
using pgamesh::test::Tolerance;
using MV = Multivector<double>;

const json& golden() {
  static const json file = pgamesh::test::load_golden("pga_basics.json");
  return file;
}

int blade_index(const std::string& name) {
  for (int i = 0; i < 16; ++i)
    if (name == kBladeNames[i]) return i;
  ADD_FAILURE() << "unknown blade " << name;
  return 0;
}

MV from_blades(const json& j) {
  MV m;
  for (auto it = j.begin(); it != j.end(); ++it)
    m[blade_index(it.key())] = it.value().get<double>();
  return m;
}

std::vector<double> coeffs(const MV& m) {
  return {m.c.begin(), m.c.end()};
}

::testing::AssertionResult near_mv(const MV& got, const json& expected, Tolerance t) {
  return near_group(coeffs(got), coeffs(from_blades(expected)), t);
}

Vec3d vec(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

const json& find_case(const std::string& id) {
  for (const json& c : golden()["cases"])
    if (c["id"] == id) return c;
  throw std::runtime_error("no golden case " + id);
}

std::vector<const json*> cases_with_prefix(const std::string& prefix) {
  std::vector<const json*> out;
  for (const json& c : golden()["cases"])
    if (c["id"].get<std::string>().rfind(prefix, 0) == 0) out.push_back(&c);
  return out;
}

TEST(Pga3Golden, BasisNamesMatch) {
  const json& basis = golden()["basis"];
  ASSERT_EQ(basis.size(), 16u);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(basis[i].get<std::string>(), kBladeNames[i]);
}

TEST(Pga3Golden, DualTable) {
  const Tolerance exact{0, 0};
  for (const json& row : golden()["dual_table"]) {
    const MV b = basis_blade<double>(blade_index(row["blade"]));
    EXPECT_TRUE(near_mv(dual(b), row["dual"], exact)) << row["blade"];
    EXPECT_TRUE(near_mv(undual(b), row["undual"], exact)) << row["blade"];
    EXPECT_EQ(undual(dual(b)), b);
  }
  // The grade types' dual/undual agree with the table (docs/conventions.md §3).
  for (int i = 0; i < 16; ++i) {
    const MV b = basis_blade<double>(i);
    const int g = detail::blade_grade(i);
    if (g == 1) {
      EXPECT_EQ(to_multivector(dual(to_plane(b))), dual(b));
      EXPECT_EQ(to_multivector(undual(to_plane(b))), undual(b));
    } else if (g == 2) {
      EXPECT_EQ(to_multivector(dual(to_line(b))), dual(b));
      EXPECT_EQ(to_multivector(undual(to_line(b))), undual(b));
    } else if (g == 3) {
      EXPECT_EQ(to_multivector(dual(to_point(b))), dual(b));
      EXPECT_EQ(to_multivector(undual(to_point(b))), undual(b));
    }
  }
}

TEST(Pga3Golden, PointEmbedding) {
  const auto cases = cases_with_prefix("point_");
  ASSERT_EQ(cases.size(), 4u);
  for (const json* c : cases) {
    const Tolerance t = pgamesh::test::tolerance_of(golden(), *c);
    const Point<double> p = point(vec((*c)["input"]["point"]));
    const json& e = (*c)["expected"];
    EXPECT_TRUE(near_mv(to_multivector(p), e["blades"], t)) << (*c)["id"];
    EXPECT_TRUE(near_scalar(norm(p), e["norm"], t));
    EXPECT_TRUE(near_scalar(ideal_norm(p), e["ideal_norm"], t));
    EXPECT_TRUE(near_scalar(norm(to_multivector(p)), e["norm"], t));
    EXPECT_TRUE(near_scalar(ideal_norm(to_multivector(p)), e["ideal_norm"], t));
  }
}

// Joins, norms and meets of a, b, c, d and a plane, with the grade types and with Multivector.
TEST(Pga3Golden, JoinsAndMeets) {
  auto cases = cases_with_prefix("joins_");
  ASSERT_EQ(cases.size(), 6u);
  for (const json* c : cases) {
    SCOPED_TRACE((*c)["id"].get<std::string>());
    const Tolerance t = pgamesh::test::tolerance_of(golden(), *c);
    const json& in = (*c)["input"];
    const json& e = (*c)["expected"];
    const Point<double> a = point(vec(in["a"])), b = point(vec(in["b"])), cc = point(vec(in["c"])),
                        d = point(vec(in["d"]));
    const Plane<double> p = plane(in["plane"][0].get<double>(), in["plane"][1].get<double>(),
                                  in["plane"][2].get<double>(), in["plane"][3].get<double>());
    const auto o = origin<double>();

    const Line<double> ab = a & b;
    EXPECT_TRUE(near_mv(to_multivector(ab), e["line_ab"], t));
    EXPECT_TRUE(near_mv(to_multivector(a) & to_multivector(b), e["line_ab"], t));
    EXPECT_TRUE(near_scalar(norm(ab), e["line_ab_norm"], t));
    EXPECT_TRUE(near_scalar(ideal_norm(ab), e["line_ab_ideal_norm"], t));

    const Plane<double> abc = a & b & cc;
    EXPECT_TRUE(near_mv(to_multivector(abc), e["plane_abc"], t));
    EXPECT_TRUE(
        near_mv(to_multivector(a) & to_multivector(b) & to_multivector(cc), e["plane_abc"], t));
    EXPECT_TRUE(near_scalar(norm(abc), e["plane_abc_norm"], t));
    EXPECT_TRUE(near_scalar(ideal_norm(abc), e["plane_abc_ideal_norm"], t));
    EXPECT_TRUE(near_scalar(abc & o, e["plane_abc_join_origin"], t));
    EXPECT_TRUE(near_scalar(o & abc, e["origin_join_plane_abc"], t));
    EXPECT_TRUE(
        near_scalar((to_multivector(o) & to_multivector(abc))[kS], e["origin_join_plane_abc"], t));

    EXPECT_TRUE(near_scalar(join(a, b, cc, d), e["join_abcd"], t));
    EXPECT_TRUE(near_scalar(ab & (cc & d), e["join_abcd"], t));  // line ∨ line
    EXPECT_TRUE(near_scalar(p & a, e["plane_join_a"], t));
    EXPECT_TRUE(near_scalar(a & p, e["a_join_plane"], t));
    EXPECT_TRUE(near_scalar(side(p, a), e["plane_join_a"], t));  // eq. 4.10

    const Point<double> x = ab ^ p;
    EXPECT_TRUE(near_mv(to_multivector(x), e["meet_line_ab_plane"], t));
    EXPECT_TRUE(near_mv(to_multivector(ab) ^ to_multivector(p), e["meet_line_ab_plane"], t));
    if (e["meet_line_ab_plane_point"].is_null()) {
      EXPECT_EQ(x.weight(), 0.0);  // the parallel case: an ideal point, not a division by zero
    } else {
      const Vec3d xp = x.euclidean();
      EXPECT_TRUE(
          near_group({xp.x, xp.y, xp.z}, pgamesh::test::flatten(e["meet_line_ab_plane_point"]), t));
    }
    EXPECT_TRUE(near_mv(to_multivector(abc ^ p), e["meet_plane_abc_plane"], t));
    EXPECT_TRUE(near_mv(to_multivector(abc) ^ to_multivector(p), e["meet_plane_abc_plane"], t));
  }
}

TEST(Pga3Golden, ThreePlanes) {
  const auto cases = cases_with_prefix("three_planes_");
  ASSERT_EQ(cases.size(), 2u);
  for (const json* c : cases) {
    SCOPED_TRACE((*c)["id"].get<std::string>());
    const Tolerance t = pgamesh::test::tolerance_of(golden(), *c);
    std::vector<Plane<double>> ps;
    for (const json& q : (*c)["input"]["planes"])
      ps.push_back(
          plane(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(), q[3].get<double>()));
    const json& e = (*c)["expected"];
    const Point<double> x = meet(ps[0], ps[1], ps[2]);
    EXPECT_TRUE(near_mv(to_multivector(x), e["meet"], t));
    EXPECT_TRUE(near_mv(to_multivector(ps[0]) ^ to_multivector(ps[1]) ^ to_multivector(ps[2]),
                        e["meet"], t));
    const Vec3d xp = x.euclidean();
    EXPECT_TRUE(near_group({xp.x, xp.y, xp.z}, pgamesh::test::flatten(e["point"]), t));
    EXPECT_TRUE(near_mv(to_multivector(ps[0] ^ ps[1]), e["line_p1p2"], t));
  }
}

TEST(Pga3Golden, GeneralProductsAndInvolutions) {
  const auto cases = cases_with_prefix("multivector_");
  ASSERT_EQ(cases.size(), 2u);
  for (const json* c : cases) {
    SCOPED_TRACE((*c)["id"].get<std::string>());
    const Tolerance t = pgamesh::test::tolerance_of(golden(), *c);
    const MV x = from_blades((*c)["input"]["X"]), y = from_blades((*c)["input"]["Y"]);
    const json& e = (*c)["expected"];
    EXPECT_TRUE(near_mv(x * y, e["geometric"], t));
    EXPECT_TRUE(near_mv(x ^ y, e["outer"], t));
    EXPECT_TRUE(near_mv(x | y, e["inner"], t));
    EXPECT_TRUE(near_mv(left_contraction(x, y), e["left_contraction"], t));
    EXPECT_TRUE(near_mv(x & y, e["join"], t));
    EXPECT_TRUE(near_mv(~x, e["reverse_X"], t));
    EXPECT_TRUE(near_mv(grade_involution(x), e["involute_X"], t));
    EXPECT_TRUE(near_mv(clifford_conjugate(x), e["conjugate_X"], t));
    EXPECT_TRUE(near_mv(!x, e["dual_X"], t));
    EXPECT_TRUE(near_mv(undual(x), e["undual_X"], t));
    EXPECT_TRUE(near_scalar(norm(x), e["norm_X"], t));
    EXPECT_TRUE(near_scalar(ideal_norm(x), e["ideal_norm_X"], t));
    // ‖A‖∞ = ‖A ∨ o‖ = ‖A*‖ (docs/conventions.md §6); the sum of squares, not a grade-wise norm.
    EXPECT_TRUE(near_scalar(norm(dual(x)), e["ideal_norm_X"], t));
  }
}

// Area of a planar polygon in 3-D from its boundary edges: ½‖Σ E_i‖∞ = ½‖Σ (E_i ∨ o)‖
// (paper Table 1, corrected for 3-D in docs/conventions.md §6).
TEST(Pga3Golden, PolygonAreaFromEdges) {
  const json& c = find_case("polygon3d_pentagon");
  const Tolerance t = pgamesh::test::tolerance_of(golden(), c);
  std::vector<Point<double>> v;
  for (const json& q : c["input"]["polygon"]) v.push_back(point(vec(q)));
  Line<double> edges{};
  Plane<double> edges_o{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Line<double> e = v[i] & v[(i + 1) % v.size()];
    edges += e;
    edges_o += e & origin<double>();
  }
  const json& e = c["expected"];
  EXPECT_TRUE(near_mv(to_multivector(edges), e["edge_sum"], t));
  EXPECT_TRUE(near_mv(to_multivector(edges_o), e["edge_sum_join_origin"], t));
  EXPECT_TRUE(near_scalar(ideal_norm(edges) / 2, e["area"], t));
  EXPECT_TRUE(near_scalar(norm(edges_o) / 2, e["area"], t));
  EXPECT_NEAR(norm(edges), 0.0, 1e-14);  // a closed loop: the directions cancel
}

}  // namespace
}  // namespace pgamesh::pga3
