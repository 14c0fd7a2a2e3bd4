// Every field of every case of tests/data/golden/cga.json (Hitzer's objects in R(4,1), null basis
// e_o, e1, e2, e3, e_∞) against pgamesh::cga.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "pgamesh/models/cga.hpp"
#include "support/golden.hpp"

using namespace pgamesh;
using namespace pgamesh::cga;
using pgamesh::test::json;
using pgamesh::test::near_group;
using pgamesh::test::near_scalar;
using pgamesh::test::Tolerance;

namespace {

Vec3d vec(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

std::vector<double> flat(Vec3d v) {
  return {v.x, v.y, v.z};
}

// Compares the element's blades with a golden blade dictionary (missing keys are zero).
template <GradeMask G>
::testing::AssertionResult near_blades(const Multivector<G>& x, const json& expected, Tolerance t) {
  std::map<std::string, double> got, want = pgamesh::test::blades(expected);
  for (const auto& [k, c] : blades(x)) got[k] = c;
  std::set<std::string> keys;
  for (const auto& [k, c] : got) keys.insert(k);
  for (const auto& [k, c] : want) keys.insert(k);
  std::vector<double> g, w;
  for (const auto& k : keys) {
    g.push_back(got.count(k) ? got[k] : 0.0);
    w.push_back(want.count(k) ? want[k] : 0.0);
  }
  auto r = near_group(g, w, t);
  if (!r) r << " (blades: got " << to_string(x) << ")";
  return r;
}

using Checks = std::map<std::string, std::function<void(const json&)>>;

// Runs the check of every expected field; a field without a check fails the test.
void check_all(const json& c, const Checks& checks) {
  for (auto it = c["expected"].begin(); it != c["expected"].end(); ++it) {
    const auto f = checks.find(it.key());
    if (f == checks.end()) {
      ADD_FAILURE() << c["id"] << ": no check for field " << it.key();
      continue;
    }
    SCOPED_TRACE(c["id"].get<std::string>() + "." + it.key());
    f->second(it.value());
  }
}

}  // namespace

// Outside the anonymous namespace: the TEST_F classes derive from it (GCC's -Wsubobject-linkage
// in a unity build).
class CgaGolden : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { file_ = new json(pgamesh::test::load_golden("cga.json")); }
  static void TearDownTestSuite() {
    delete file_;
    file_ = nullptr;
  }
  // Cases whose id starts with prefix.
  static std::vector<json> cases(const std::string& prefix) {
    std::vector<json> out;
    for (const auto& c : (*file_)["cases"])
      if (c["id"].get<std::string>().rfind(prefix, 0) == 0) out.push_back(c);
    return out;
  }
  static Tolerance tol(const json& c) { return pgamesh::test::tolerance_of(*file_, c); }
  static json* file_;
};

json* CgaGolden::file_ = nullptr;

TEST_F(CgaGolden, FileHasTheExpectedCases) {
  EXPECT_EQ((*file_)["cases"].size(), 16u);
  std::size_t n = 0;
  for (const char* p : {"point_", "pair_", "line_", "circle_", "plane_", "sphere_"})
    n += cases(p).size();
  EXPECT_EQ(n, (*file_)["cases"].size()) << "a case kind without a test";
}

TEST_F(CgaGolden, Points) {
  const auto cs = cases("point_");
  ASSERT_EQ(cs.size(), 2u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const Vec3d p = vec(c["input"]["point"]);
    const double s = c["input"]["scaled_by"].get<double>();
    const Vector x = up(p);
    check_all(c, {
                     {"blades", [&](const json& e) { EXPECT_TRUE(near_blades(x, e, t)); }},
                     {"scaled_blades",
                      [&](const json& e) {
                        const Vector xs = s * x;
                        EXPECT_TRUE(near_blades(xs, e, t));
                        // Normalising by −X·e_∞ gives the unit point back.
                        EXPECT_TRUE(near_blades(normalize_point(xs), c["expected"]["blades"], t));
                        EXPECT_TRUE(near_group(flat(down(xs)), flat(p), t));
                        EXPECT_DOUBLE_EQ(-scalar_product(xs, einf()), s);
                      }},
                     {"X_dot_X",
                      [&](const json& e) {
                        EXPECT_TRUE(near_scalar(scalar_product(x, x), e.get<double>(), t));
                      }},
                 });
  }
}

TEST_F(CgaGolden, PointPairs) {
  const auto cs = cases("pair_");
  ASSERT_EQ(cs.size(), 5u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const Vec3d p1 = vec(c["input"]["p1"]), p2 = vec(c["input"]["p2"]);
    const Bivector v2 = point_pair(p1, p2);
    const PairParams pp = pair_params(v2);
    const bool unordered = c["expected"].value("points_unordered", false);
    check_all(c,
              {
                  {"blades", [&](const json& e) { EXPECT_TRUE(near_blades(v2, e, t)); }},
                  {"u",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(pp.u), pgamesh::test::flatten(e), t));
                   }},
                  {"v",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(pp.v), pgamesh::test::flatten(e), t));
                   }},
                  {"gamma",
                   [&](const json& e) { EXPECT_TRUE(near_scalar(pp.gamma, e.get<double>(), t)); }},
                  {"points_larger_norm_first",
                   [&](const json& e) {
                     const auto pts = pair_points(v2);
                     const std::vector<double> w0 = pgamesh::test::flatten(e[0]),
                                               w1 = pgamesh::test::flatten(e[1]);
                     // The pair is read about its centre: the points carry its digits, not 1e-12 of
                     // |p|.
                     const Tolerance tp{1e-12, 1e-12};
                     if (unordered && !near_group(flat(pts[0]), w0, tp)) {
                       EXPECT_TRUE(near_group(flat(pts[0]), w1, tp));
                       EXPECT_TRUE(near_group(flat(pts[1]), w0, tp));
                     } else {
                       EXPECT_TRUE(near_group(flat(pts[0]), w0, tp));
                       EXPECT_TRUE(near_group(flat(pts[1]), w1, tp));
                     }
                   }},
                  {"center",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(pp.round.center), pgamesh::test::flatten(e), t));
                     EXPECT_TRUE(near_group(flat(location(v2)), pgamesh::test::flatten(e), t));
                   }},
                  {"half_distance_r",
                   [&](const json& e) {
                     EXPECT_TRUE(near_scalar(pp.round.radius, e.get<double>(), t));
                     EXPECT_FALSE(pp.round.imaginary);
                     EXPECT_EQ(classify(v2), Kind::point_pair);
                   }},
                  {"direction_p2_to_p1",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(pp.direction), pgamesh::test::flatten(e), t));
                   }},
                  {"V2_squared",
                   [&](const json& e) {
                     EXPECT_TRUE(near_scalar(scalar_product(v2, v2), e.get<double>(), t));
                   }},
                  {"points_unordered", [&](const json& e) { EXPECT_TRUE(e.get<bool>()); }},
              });
  }
}

TEST_F(CgaGolden, Lines) {
  const auto cs = cases("line_");
  ASSERT_EQ(cs.size(), 2u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const Vec3d p1 = vec(c["input"]["p1"]), p2 = vec(c["input"]["p2"]);
    const Trivector l = line(p1, p2);
    const LineParams lp = line_params(l);
    check_all(c,
              {
                  {"blades",
                   [&](const json& e) {
                     EXPECT_TRUE(near_blades(l, e, t));
                     EXPECT_TRUE(
                         near_blades(up(p1) ^ up(p2) ^ einf(), e, t));  // Hitzer eq. 16 as written
                   }},
                  {"direction",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(lp.direction), pgamesh::test::flatten(e), t));
                   }},
                  {"moment_cross",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(lp.moment), pgamesh::test::flatten(e), t));
                   }},
                  {"closest_point",
                   [&](const json& e) {
                     EXPECT_TRUE(near_group(flat(lp.closest_point), pgamesh::test::flatten(e), t));
                     EXPECT_TRUE(near_group(flat(location(l)), pgamesh::test::flatten(e), t));
                     EXPECT_EQ(classify(l), Kind::line);
                   }},
              });
  }
}

TEST_F(CgaGolden, Circles) {
  const auto cs = cases("circle_");
  ASSERT_EQ(cs.size(), 3u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const auto& in = c["input"]["points"];
    const Vec3d a = vec(in[0]), b = vec(in[1]), d = vec(in[2]);
    const Trivector v3 = circle(a, b, d);
    const CircleParams cp = circle_params(v3);
    check_all(
        c,
        {
            {"blades",
             [&](const json& e) {
               EXPECT_TRUE(near_blades(v3, e, t));
               EXPECT_TRUE(near_blades(up(a) ^ up(b) ^ up(d), e, t));  // Hitzer eq. 20 as written
             }},
            {"center",
             [&](const json& e) {
               EXPECT_TRUE(near_group(flat(cp.round.center), pgamesh::test::flatten(e), t));
             }},
            {"radius",
             [&](const json& e) {
               EXPECT_TRUE(near_scalar(cp.round.radius, e.get<double>(), t));
               EXPECT_EQ(classify(v3), Kind::circle);
             }},
            {"plane_bivector_Ic",
             [&](const json& e) {
               const std::vector<double> got = {cp.plane_bivector[0], cp.plane_bivector[1],
                                                cp.plane_bivector[2]};
               const std::vector<double> want = {e.value("e1^e2", 0.0), e.value("e1^e3", 0.0),
                                                 e.value("e2^e3", 0.0)};
               EXPECT_TRUE(near_group(got, want, t));
             }},
            {"unit_normal",
             [&](const json& e) {
               EXPECT_TRUE(near_group(flat(cp.normal), pgamesh::test::flatten(e), t));
               // The carrier plane V3 ∧ e_∞ has the same normal and contains the centre.
               const PlaneParams pl = plane_params(cp.carrier);
               EXPECT_TRUE(near_group(flat(pl.normal), pgamesh::test::flatten(e), t));
               EXPECT_NEAR(dot(pl.normal, cp.round.center), pl.distance, 1e-12);
             }},
            {"V3_squared",
             [&](const json& e) {
               EXPECT_TRUE(near_scalar(scalar_product(v3, v3), e.get<double>(), t));
             }},
        });
  }
}

TEST_F(CgaGolden, Planes) {
  const auto cs = cases("plane_");
  ASSERT_EQ(cs.size(), 2u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const Vec3d p1 = vec(c["input"]["p1"]), p2 = vec(c["input"]["p2"]), p3 = vec(c["input"]["p3"]);
    const Quadvector v = plane(p1, p2, p3);
    const PlaneParams pp = plane_params(v);
    check_all(
        c, {
               {"blades",
                [&](const json& e) {
                  EXPECT_TRUE(near_blades(v, e, t));
                  EXPECT_TRUE(near_blades(up(p1) ^ up(p2) ^ up(p3) ^ einf(), e, t));
                }},
               {"unit_normal",
                [&](const json& e) {
                  EXPECT_TRUE(near_group(flat(pp.normal), pgamesh::test::flatten(e), t));
                  EXPECT_EQ(classify(v), Kind::plane);
                }},
               {"signed_distance",
                [&](const json& e) { EXPECT_TRUE(near_scalar(pp.distance, e.get<double>(), t)); }},
               {"distance_vector",
                [&](const json& e) {
                  EXPECT_TRUE(near_group(flat(pp.foot), pgamesh::test::flatten(e), t));
                  EXPECT_TRUE(near_group(flat(location(v)), pgamesh::test::flatten(e), t));
                }},
           });
  }
}

TEST_F(CgaGolden, Spheres) {
  const auto cs = cases("sphere_");
  ASSERT_EQ(cs.size(), 2u);
  for (const auto& c : cs) {
    const Tolerance t = tol(c);
    const auto& in = c["input"]["points"];
    const Vec3d a = vec(in[0]), b = vec(in[1]), d = vec(in[2]), f = vec(in[3]);
    const Quadvector v4 = sphere(a, b, d, f);
    const RoundParams sp = sphere_params(v4);
    const RoundParams rp = round_params(v4);  // the general round formula agrees
    check_all(c, {
                     {"blades",
                      [&](const json& e) {
                        EXPECT_TRUE(near_blades(v4, e, t));
                        EXPECT_TRUE(near_blades(up(a) ^ up(b) ^ up(d) ^ up(f), e, t));
                      }},
                     {"center",
                      [&](const json& e) {
                        EXPECT_TRUE(near_group(flat(sp.center), pgamesh::test::flatten(e), t));
                        EXPECT_TRUE(near_group(flat(rp.center), pgamesh::test::flatten(e), t));
                      }},
                     {"radius",
                      [&](const json& e) {
                        EXPECT_TRUE(near_scalar(sp.radius, e.get<double>(), t));
                        EXPECT_TRUE(near_scalar(rp.radius, e.get<double>(), t));
                        EXPECT_EQ(classify(v4), Kind::sphere);
                      }},
                     {"center_point_blades",
                      [&](const json& e) { EXPECT_TRUE(near_blades(up(sp.center), e, t)); }},
                 });
  }
}
