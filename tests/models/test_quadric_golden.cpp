// Every field of every case of tests/data/golden/quadrics.json against the three models.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "pgamesh/models/quadric_convert.hpp"

using namespace pgamesh;
using nlohmann::json;
using quadric::Quadric;

namespace {

json load_golden() {
  std::ifstream in(std::string(PGAMESH_GOLDEN_DIR) + "/quadrics.json");
  EXPECT_TRUE(in.good()) << "cannot open quadrics.json in " << PGAMESH_GOLDEN_DIR;
  return json::parse(in);
}

const json& golden() {
  static const json j = load_golden();
  return j;
}

struct Tol {
  double rel = 1e-12, abs = 1e-12;
};

Tol tol_of(const json& c) {
  Tol t{golden()["tolerance_default"]["rel"].get<double>(),
        golden()["tolerance_default"]["abs"].get<double>()};
  if (c.contains("tolerance")) {
    t.rel = c["tolerance"].value("rel", t.rel);
    t.abs = c["tolerance"].value("abs", t.abs);
  }
  return t;
}

Vec3d vec3(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Quadric quadric_of(const json& j) {
  Quadric q;
  for (std::size_t n = 0; n < 10; ++n) q.k[n] = j[n].get<double>();
  return q;
}

std::array<double, 3> as_array(const Vec3d& v) {
  return {v.x, v.y, v.z};
}

template <class Got>
void expect_array(const Got& got, const json& expected, Tol t, const std::string& what) {
  ASSERT_EQ(got.size(), expected.size()) << what;
  double scale = 0;
  for (const auto& e : expected) scale = std::max(scale, std::abs(e.get<double>()));
  for (std::size_t n = 0; n < got.size(); ++n)
    EXPECT_NEAR(got[n], expected[n].get<double>(), t.abs + t.rel * scale)
        << what << "[" << n << "]";
}

void expect_blades(const std::vector<std::pair<std::string, double>>& got, const json& expected,
                   Tol t, const std::string& what) {
  std::map<std::string, double> g(got.begin(), got.end());
  double scale = 0;
  for (const auto& [k, v] : expected.items()) scale = std::max(scale, std::abs(v.get<double>()));
  const double bound = t.abs + t.rel * scale;
  for (const auto& [k, v] : expected.items()) {
    const double have = g.count(k) ? g[k] : 0.0;
    EXPECT_NEAR(have, v.get<double>(), bound) << what << " blade " << k;
  }
  for (const auto& [k, v] : g)
    if (!expected.contains(k)) {
      EXPECT_NEAR(v, 0.0, bound) << what << " unexpected blade " << k;
    }
}

}  // namespace

TEST(QuadricGolden, FileHasAllCases) {
  ASSERT_EQ(golden()["schema"], "pgamesh-golden/1");
  EXPECT_EQ(golden()["cases"].size(), 24u);
}

TEST(QuadricGolden, CoefficientsAndModelElements) {
  for (const json& c : golden()["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tol t = tol_of(c);
    const Quadric q = quadric_of(c["input"]["coefficients"]);
    expect_array(q.k, c["expected"]["coefficients"], t, "coefficients");
    expect_blades(dpga::nonzero_blades(dpga::quadric(q)), c["expected"]["dpga_Q"], t, "dpga_Q");
    expect_blades(dcga::nonzero_blades(dcga::quadric(q)), c["expected"]["dcga_Q"], t, "dcga_Q");
    expect_blades(qcga::nonzero_blades(qcga::dual_quadric(q)), c["expected"]["qcga_qstar"], t,
                  "qcga_qstar");
    // The reciprocal operators give the coefficients back in every model.
    expect_array(dpga::coefficients(dpga::quadric(q)).k, c["expected"]["coefficients"], t, "W^k.Q");
    expect_array(dcga::coefficients(dcga::quadric(q)).k, c["expected"]["coefficients"], t, "T^k.Q");
    expect_array(qcga::coefficients(qcga::dual_quadric(q)).k, c["expected"]["coefficients"], t,
                 "Q^k.q*");
  }
}

TEST(QuadricGolden, ValuesInEveryModel) {
  for (const json& c : golden()["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tol t = tol_of(c);
    const Quadric q = quadric_of(c["input"]["coefficients"]);
    const auto qd = dpga::quadric(q);
    const auto qc = dcga::quadric(q);
    const auto qs = qcga::dual_quadric(q);
    const json& pts = c["input"]["eval_points"];
    std::vector<double> v0, v1, v2, v3;
    for (const json& p : pts) {
      v0.push_back(quadric::value(q, vec3(p)));
      v1.push_back(dpga::value(qd, vec3(p)));
      v2.push_back(dcga::value(qc, vec3(p)));
      v3.push_back(qcga::value(qs, vec3(p)));
    }
    expect_array(v0, c["expected"]["values"], t, "values");
    expect_array(v1, c["expected"]["values"], t, "dpga values");
    expect_array(v2, c["expected"]["values"], t, "dcga values");
    expect_array(v3, c["expected"]["values"], t, "qcga values");
  }
}

TEST(QuadricGolden, SurfacePointsGradientsTangentPlanes) {
  for (const json& c : golden()["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tol t = tol_of(c);
    const Quadric q = quadric_of(c["input"]["coefficients"]);
    const auto qs = qcga::dual_quadric(q);
    const auto qd = dpga::quadric(q);
    const auto qc = dcga::quadric(q);
    for (const json& sp : c["expected"]["surface_points"]) {
      const Vec3d p = vec3(sp["point"]);
      const double f = sp["F"].get<double>();
      EXPECT_NEAR(quadric::value(q, p), f, t.abs + t.rel * std::abs(f));
      expect_array(as_array(quadric::gradient(q, p)), sp["gradient"], t, "gradient");
      expect_array(as_array(qcga::normal(qs, p)), sp["gradient"], t, "qcga normal eq. 45");
      expect_array(as_array(dcga::gradient(qc, p)), sp["gradient"], t, "dcga normal eq. 14-15");
      expect_array(quadric::tangent_plane(q, p), sp["tangent_plane"], t, "tangent_plane");
      // QCGA corrected eq. 46: π* = n + (n·p) e∞ reads n·x − n·p at any x.
      const auto pi = qcga::tangent_plane(qs, p);
      const std::array<double, 4> pq{pi.v[0], pi.v[1], pi.v[2], -3 * pi.v[9]};
      expect_array(pq, sp["tangent_plane"], t, "qcga tangent plane");
      // DPGA eq. 38: the polar plane is the tangent plane on the surface (F(p) ≈ 1e-16 here).
      const auto pp = dpga::polar_plane(qd, p);
      expect_array(std::array<double, 3>{pp[0], pp[1], pp[2]}, sp["gradient"], t, "dpga polar");
      EXPECT_NEAR(pp[3], sp["tangent_plane"][3].get<double>(), 1e-10);
    }
  }
}

TEST(QuadricGolden, LineIntersections) {
  for (const json& c : golden()["cases"]) {
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tol t = tol_of(c);
    const Quadric q = quadric_of(c["input"]["coefficients"]);
    for (const json& li : c["expected"]["line_intersections"]) {
      const auto hit = quadric::intersect_line(q, vec3(li["origin"]), vec3(li["direction"]));
      EXPECT_EQ(quadric::to_string(hit.kind), li["kind"].get<std::string>());
      expect_array(hit.quadratic, li["quadratic_At2_Bt_C"], t, "A, B, C");
      ASSERT_EQ(static_cast<std::size_t>(hit.count), li["t"].size());
      for (int n = 0; n < hit.count; ++n) {
        const double te = li["t"][static_cast<std::size_t>(n)].get<double>();
        EXPECT_NEAR(hit.t[static_cast<std::size_t>(n)], te, 1e-10 * (1 + std::abs(te)));
        expect_array(as_array(hit.points[static_cast<std::size_t>(n)]),
                     li["points"][static_cast<std::size_t>(n)], Tol{1e-10, 1e-10}, "point");
      }
      const auto hq =
          qcga::intersect_line(qcga::dual_quadric(q), vec3(li["origin"]), vec3(li["direction"]));
      EXPECT_EQ(quadric::to_string(hq.kind), li["kind"].get<std::string>()) << "qcga";
    }
  }
}

TEST(QuadricGolden, RotationAndCorrectedRotor) {
  int cases = 0;
  for (const json& c : golden()["cases"]) {
    if (!c["input"].contains("rotation")) continue;
    ++cases;
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tol t = tol_of(c);
    const Quadric q = quadric_of(c["input"]["coefficients"]);
    const int i = c["input"]["rotation"]["plane_axes"][0].get<int>();
    const int j = c["input"]["rotation"]["plane_axes"][1].get<int>();
    const double th = c["input"]["rotation"]["angle"].get<double>();
    const json& expected = c["expected"]["rotated_coefficients"];
    expect_array(quadric::rotate(q, quadric::plane_rotation(i, j, th)).k, expected, t, "direct");
    const auto r = dpga::rotor(i, j, th);
    expect_blades(dpga::nonzero_blades(r), c["expected"]["dpga_rotor"], t, "dpga_rotor");
    expect_array(dpga::coefficients(dpga::rotate(dpga::quadric(q), i, j, th)).k, expected,
                 Tol{1e-12, 1e-12}, "R Q R~");
    expect_array(dcga::coefficients(dcga::transform(dcga::rotor(i, j, th), dcga::quadric(q))).k,
                 expected, Tol{1e-12, 1e-12}, "dcga rotor");
  }
  EXPECT_EQ(cases, 17);
}

TEST(QuadricGolden, NinePointsEq70ClosedFormAndEngine) {
  int cases = 0;
  for (const json& c : golden()["cases"]) {
    if (!c["input"].contains("nine_points")) continue;
    SCOPED_TRACE(c["id"].get<std::string>());
    std::array<Vec3d, 9> pts;
    for (std::size_t n = 0; n < 9; ++n) pts[n] = vec3(c["input"]["nine_points"][n]);
    const double tol = c["expected"]["nine_point_tolerance_abs"].get<double>();
    const json& expected = c["expected"]["nine_point_coefficients_normalized"];
    const Quadric closed = quadric::normalized(qcga::coefficients(qcga::quadric_from_points(pts)));
    expect_array(closed.k, expected, Tol{0, tol}, "closed form");
    if (cases++ < 3) {  // the full R(9,6) computation costs milliseconds: three cases
      const auto ga = qcga::from_clifford(qcga::quadric_from_points_ga(pts));
      const Quadric viaga = quadric::normalized(qcga::coefficients(ga));
      expect_array(viaga.k, expected, Tol{0, tol}, "engine eq. 70");
      // eq. 70 gives no einf4..6 part and equal einf1..3 parts.
      const double s = *std::max_element(
          ga.v.begin(), ga.v.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
      for (std::size_t k = 12; k < 15; ++k) EXPECT_NEAR(ga.v[k], 0.0, 1e-9 * std::abs(s));
      EXPECT_NEAR(ga.v[9], ga.v[10], 1e-9 * std::abs(s));
      EXPECT_NEAR(ga.v[10], ga.v[11], 1e-9 * std::abs(s));
    }
  }
  EXPECT_EQ(cases, 17);
}
