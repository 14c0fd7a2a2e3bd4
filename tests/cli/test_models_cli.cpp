// `pgamesh cga`, `pgamesh quadric` and `pgamesh fit` end to end: every object of cga.json and
// every quadric of quadrics.json (elements in the three models, values, gradients, tangent planes,
// line intersections, rotations, nine-point fits) against the golden values; fits of generated
// noisy spheres, cylinders, planes and exact quadrics against their known parameters; bad input
// (exit 1, naming the problem) and bad usage (exit 2).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "pgamesh/core/number_text.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::flatten;
using pgamesh::test::json;
using pgamesh::test::near_group;
using pgamesh::test::near_scalar;
using pgamesh::test::parse_json;
using pgamesh::test::run_cli;
using pgamesh::test::TempFile;
using pgamesh::test::Tolerance;

namespace {

// s += sep + x, with sep only when s is not empty (appended piece by piece: GCC 12's -Wrestrict
// misfires on `"literal" + std::string&&`).
void append(std::string& s, const char* sep, const std::string& x) {
  if (!s.empty()) s += sep;
  s += x;
}

std::string triple(const json& p) {
  return pgamesh::format_number(p[0].get<double>()) + "," +
         pgamesh::format_number(p[1].get<double>()) + "," +
         pgamesh::format_number(p[2].get<double>());
}

std::string numbers(const json& a) {
  std::string s;
  for (const auto& x : a) {
    if (!s.empty()) s += ",";
    s += pgamesh::format_number(x.get<double>());
  }
  return s;
}

json run_json(const std::string& args) {
  const CliRun r = run_cli(args + " --json");
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  try {
    return parse_json(r.out);
  } catch (const std::exception&) {
    ADD_FAILURE() << "not JSON: " << r.out;
    return json::object();
  }
}

::testing::AssertionResult same_blades(const json& got, const json& expected, Tolerance t) {
  std::vector<double> g, e;
  for (auto it = expected.begin(); it != expected.end(); ++it) {
    e.push_back(it.value().get<double>());
    g.push_back(got.contains(it.key()) ? got[it.key()].get<double>() : 0.0);
  }
  for (auto it = got.begin(); it != got.end(); ++it)
    if (!expected.contains(it.key())) {
      e.push_back(0.0);
      g.push_back(it.value().get<double>());
    }
  return near_group(g, e, t);
}

std::vector<double> normalized(std::vector<double> v) {
  double n = 0, big = 0;
  for (double x : v) {
    n += x * x;
    big = std::max(big, std::abs(x));
  }
  n = std::sqrt(n);
  double sign = 1;
  for (double x : v)
    if (std::abs(x) >= 1e-3 * big) {
      sign = x < 0 ? -1 : 1;
      break;
    }
  for (double& x : v) x *= sign / n;
  return v;
}

}  // namespace

// ---- pgamesh cga
// -----------------------------------------------------------------------------------

TEST(CgaCli, ObjectsAndParametersMatchGolden) {
  const json file = pgamesh::test::load_golden("cga.json");
  int cases = 0;
  for (const auto& c : file["cases"]) {
    const std::string id = c["id"];
    const std::string kind = id.substr(0, id.find('_'));
    if (kind == "point") continue;
    const json& in = c["input"];
    const json& ex = c["expected"];
    const Tolerance t = pgamesh::test::tolerance_of(file, c);
    std::string points;
    if (in.contains("points"))
      for (const auto& p : in["points"]) append(points, ";", triple(p));
    for (const char* k : {"p1", "p2", "p3"})
      if (in.contains(k)) append(points, ";", triple(in[k]));
    const json got = run_json("cga --" + kind + " --points '" + points + "'");
    EXPECT_EQ(got["object"], kind) << id;
    EXPECT_TRUE(same_blades(got["blades"], ex["blades"], t)) << id;
    if (kind == "pair") {
      EXPECT_TRUE(near_group(flatten(got["center"]), flatten(ex["center"]), t)) << id;
      EXPECT_TRUE(near_scalar(got["radius"], ex["half_distance_r"], t)) << id;
      EXPECT_TRUE(near_scalar(got["radius2"], std::pow(ex["half_distance_r"].get<double>(), 2), t));
      EXPECT_TRUE(near_group(flatten(got["direction"]), flatten(ex["direction_p2_to_p1"]), t))
          << id;
      if (!ex.contains("points_unordered")) {
        EXPECT_TRUE(near_group(flatten(got["points"]), flatten(ex["points_larger_norm_first"]), t))
            << id;
      }
    } else if (kind == "line") {
      std::vector<double> d = flatten(ex["direction"]);
      const double n = std::hypot(d[0], d[1], d[2]);
      for (double& x : d) x /= n;
      EXPECT_TRUE(near_group(flatten(got["direction"]), d, t)) << id;
      EXPECT_TRUE(near_group(flatten(got["closest_point"]), flatten(ex["closest_point"]), t)) << id;
    } else if (kind == "circle") {
      EXPECT_TRUE(near_group(flatten(got["center"]), flatten(ex["center"]), t)) << id;
      EXPECT_TRUE(near_scalar(got["radius"], ex["radius"], t)) << id;
      EXPECT_TRUE(near_group(flatten(got["normal"]), flatten(ex["unit_normal"]), t)) << id;
    } else if (kind == "plane") {
      EXPECT_TRUE(near_group(flatten(got["normal"]), flatten(ex["unit_normal"]), t)) << id;
      EXPECT_TRUE(near_scalar(got["distance"], ex["signed_distance"], t)) << id;
      EXPECT_TRUE(near_group(flatten(got["closest_point"]), flatten(ex["distance_vector"]), t))
          << id;
    } else if (kind == "sphere") {
      EXPECT_TRUE(near_group(flatten(got["center"]), flatten(ex["center"]), t)) << id;
      EXPECT_TRUE(near_scalar(got["radius"], ex["radius"], t)) << id;
      EXPECT_TRUE(near_scalar(got["radius2"], std::pow(ex["radius"].get<double>(), 2), t)) << id;
    }
    ++cases;
  }
  EXPECT_EQ(cases, 14);
}

TEST(CgaCli, ReadableOutput) {
  const CliRun r = run_cli("cga --sphere --points '3,2,3;1,4,3;1,2,5;-1,2,3'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("sphere through 4 points"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("center        (1, 2, 3)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radius        2\n"), std::string::npos) << r.out;
}

TEST(CgaCli, BadInputAndUsage) {
  const struct {
    const char* args;
    int status;
    const char* message;
  } cases[] = {
      {"--pair --points '1,2,3;1,2,3'", 1, "coincide"},
      {"--circle --points '0,0,0;1,1,1;2,2,2'", 1, "collinear"},
      {"--sphere --points '0,0,0;1,0,0;0,1,0;1,1,0'", 1, "coplanar"},
      {"--plane --points '0,0,nan;1,0,0;0,1,0'", 1, "not finite"},
      {"--line --points '0,0,0;inf,0,0'", 1, "not finite"},
      {"--circle --points '0,0,0;1,0,0'", 2, "--circle needs 3 points"},
      {"--points '0,0,0;1,0,0'", 2, "exactly one of --pair"},
      {"--pair --line --points '0,0,0;1,0,0'", 2, "exactly one of --pair"},
      {"--pair --points '0,0,0;1,x,0'", 2, "'x' is not a number"},
      {"--pair --points '0,0;1,0,0'", 2, "needs 3 comma-separated numbers"},
      {"--pair", 2, "--points"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli(std::string("cga ") + c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out, "") << c.args;
  }
}

// ---- pgamesh quadric
// -------------------------------------------------------------------------------

TEST(QuadricCli, EveryModelMatchesGolden) {
  const json file = pgamesh::test::load_golden("quadrics.json");
  const std::pair<const char*, const char*> models[] = {
      {"qcga", "qcga_qstar"}, {"dcga", "dcga_Q"}, {"dpga", "dpga_Q"}};
  int cases = 0;
  for (const auto& c : file["cases"]) {
    const std::string id = c["id"];
    const json& in = c["input"];
    const json& ex = c["expected"];
    const Tolerance t = pgamesh::test::tolerance_of(file, c);
    std::string args = "quadric --coefficients " + numbers(in["coefficients"]);
    for (const auto& p : in["eval_points"]) args += " --point " + triple(p);
    for (const auto& s : ex["surface_points"]) args += " --point " + triple(s["point"]);
    for (const auto& l : ex["line_intersections"])
      args += " --line " + triple(l["origin"]) + "," + triple(l["direction"]);
    if (in.contains("rotation"))
      args += " --rotate " + pgamesh::format_number(in["rotation"]["plane_axes"][0].get<double>()) +
              "," + pgamesh::format_number(in["rotation"]["plane_axes"][1].get<double>()) + "," +
              pgamesh::format_number(in["rotation"]["angle"].get<double>());
    for (const auto& [model, key] : models) {
      const json got = run_json(args + " --model " + model);
      const std::string what = id + " " + model;
      EXPECT_EQ(got["model"], model);
      EXPECT_TRUE(near_group(flatten(got["coefficients"]), flatten(ex["coefficients"]), t)) << what;
      EXPECT_TRUE(same_blades(got["element"], ex[key], t)) << what;
      const std::size_t n_eval = in["eval_points"].size();
      ASSERT_EQ(got["points"].size(), n_eval + ex["surface_points"].size()) << what;
      std::vector<double> values;
      for (std::size_t k = 0; k < n_eval; ++k) values.push_back(got["points"][k]["value"]);
      EXPECT_TRUE(near_group(values, flatten(ex["values"]), t)) << what;
      for (std::size_t k = 0; k < ex["surface_points"].size(); ++k) {
        const json& s = ex["surface_points"][k];
        const json& g = got["points"][n_eval + k];
        EXPECT_TRUE(near_group(flatten(g["gradient"]), flatten(s["gradient"]), t)) << what;
        EXPECT_TRUE(near_group(flatten(g["tangent_plane"]), flatten(s["tangent_plane"]), t))
            << what;
        EXPECT_NEAR(g["value"].get<double>(), s["F"].get<double>(), 1e-12) << what;
      }
      ASSERT_EQ(got["lines"].size(), ex["line_intersections"].size()) << what;
      for (std::size_t k = 0; k < got["lines"].size(); ++k) {
        const json& l = ex["line_intersections"][k];
        const json& g = got["lines"][k];
        EXPECT_EQ(g["kind"], l["kind"]) << what << " line " << k;
        EXPECT_TRUE(near_group(flatten(g["t"]), flatten(l["t"]), t)) << what << " line " << k;
        EXPECT_TRUE(near_group(flatten(g["points"]), flatten(l["points"]), t)) << what;
      }
      if (in.contains("rotation")) {
        EXPECT_TRUE(near_group(flatten(got["rotated_coefficients"]),
                               flatten(ex["rotated_coefficients"]), {1e-12, 1e-12}))
            << what;
      }
    }
    if (in.contains("nine_points")) {
      std::string pts;
      for (const auto& p : in["nine_points"]) append(pts, ";", triple(p));
      const json got = run_json("quadric --through '" + pts + "'");
      const double tol = ex["nine_point_tolerance_abs"];
      EXPECT_TRUE(near_group(normalized(flatten(got["coefficients"])),
                             flatten(ex["nine_point_coefficients_normalized"]), {0, tol}))
          << id;
      EXPECT_EQ(got["fit"]["points"], 9);
      EXPECT_LT(got["fit"]["geometric_max"].get<double>(), 1e-8) << id;
    }
    ++cases;
  }
  EXPECT_GE(cases, 20);
}

TEST(QuadricCli, TypeTranslationAndReadableOutput) {
  // Unit sphere moved by (1, 2, 3): (x−1)² + (y−2)² + (z−3)² − 1 = x² + y² + z² − 2x − 4y − 6z
  // + 13.
  for (const char* model : {"qcga", "dcga", "dpga"}) {
    const json got = run_json(std::string("quadric --coefficients 1,1,1,0,0,0,0,0,0,-1 --model ") +
                              model + " --translate 1,2,3");
    EXPECT_EQ(got["type"], "sphere");
    EXPECT_TRUE(near_group(flatten(got["translated_coefficients"]),
                           {1, 1, 1, 0, 0, 0, -2, -4, -6, 13}, {1e-15, 1e-15}))
        << model;
  }
  const CliRun r = run_cli("quadric --coefficients 1,1,0,0,0,0,0,0,0,-1 --line 0,0,0,1,0,0");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("elliptic_cylinder"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("two (-1, 0, 0) (1, 0, 0)"), std::string::npos) << r.out;
}

TEST(QuadricCli, BadInputAndUsage) {
  const struct {
    const char* args;
    int status;
    const char* message;
  } cases[] = {
      {"--through '1,0,0;0,1,0;0,0,1;1,1,0;0,1,1;1,0,1;2,0,0;0,2,0'", 1, "at least 9 points"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --line 0,0,0,0,0,0", 1, "direction is zero"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,nan", 1, "NaN"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --point 1,nan,0", 1, "not finite"},
      {"--coefficients 1,1,1", 2, "needs 10 comma-separated numbers"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --through '0,0,0'", 2, "exactly one of"},
      {"--point 1,2,3", 2, "exactly one of"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --model cga", 2, "--model must be"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --rotate 1,1,0.5", 2, "must differ"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --rotate 0,3,0.5", 2, "axes 0 (x)"},
      {"--coefficients 1,1,1,0,0,0,0,0,0,-1 --line 0,0,0,1", 2, "needs 6"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli(std::string("quadric ") + c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}

// ---- pgamesh fit
// -----------------------------------------------------------------------------------

namespace {

// Deterministic noise in [−1, 1) (a linear congruential generator: the same file on every run).
struct Noise {
  unsigned long long state = 12345;
  double operator()() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / 4503599627370496.0 - 1.0;
  }
};

std::string csv(const std::vector<std::array<double, 3>>& points, char sep = ',') {
  std::string s = "x,y,z\n";
  for (const auto& p : points)
    s += pgamesh::format_number(p[0]) + sep + pgamesh::format_number(p[1]) + sep +
         pgamesh::format_number(p[2]) + "\n";
  return s;
}

// n points of the sphere (c, r) spread by a golden-angle spiral, radii off by up to ±noise.
std::vector<std::array<double, 3>> sphere_points(std::array<double, 3> c, double r, int n,
                                                 double noise) {
  Noise rnd;
  std::vector<std::array<double, 3>> out;
  for (int k = 0; k < n; ++k) {
    const double z = 1 - 2 * (k + 0.5) / n, s = std::sqrt(1 - z * z);
    const double phi = k * std::numbers::pi * (3 - std::sqrt(5.0));
    const double rr = r + noise * rnd();
    out.push_back({c[0] + rr * s * std::cos(phi), c[1] + rr * s * std::sin(phi), c[2] + rr * z});
  }
  return out;
}

}  // namespace

TEST(FitCli, NoisySphereGivesItsCentreAndRadius) {
  const double noise = 1e-4;
  const TempFile f(".csv", csv(sphere_points({1, -2, 5}, 3, 2000, noise)));
  const json got = run_json("fit '" + f.path() + "' --sphere");
  EXPECT_EQ(got["shape"], "sphere");
  EXPECT_EQ(got["points"], 2000);
  EXPECT_TRUE(near_group(flatten(got["center"]), {1, -2, 5}, {0, 2e-5}));
  EXPECT_NEAR(got["radius"].get<double>(), 3, 2e-5);
  EXPECT_LT(got["rms"].get<double>(), noise);  // uniform noise: rms = noise/√3
  EXPECT_GT(got["rms"].get<double>(), 0.4 * noise);
  EXPECT_LE(got["max_distance"].get<double>(), 1.2 * noise);
  // The same sphere as a quadric: (x−1)² + (y+2)² + (z−5)² − 9, normalized.
  const json q = run_json("fit '" + f.path() + "' --quadric");
  EXPECT_TRUE(q["type"] == "sphere" || q["type"] == "ellipsoid") << q["type"];  // noise: λ differ
  EXPECT_TRUE(near_group(normalized(flatten(q["coefficients"])),
                         normalized({1, 1, 1, 0, 0, 0, -2, 4, -10, 21}), {0, 1e-4}));
  EXPECT_LT(q["max_distance"].get<double>(), 2e-4);
}

TEST(FitCli, NoisyCylinderAndPlane) {
  // Cylinder of radius 2 about the axis through (1, 1, 0) with direction (0, 0.6, 0.8).
  Noise rnd;
  const double noise = 1e-4;
  std::vector<std::array<double, 3>> cyl, plane;
  const double u[3] = {1, 0, 0}, v[3] = {0, 0.8, -0.6}, d[3] = {0, 0.6, 0.8};
  for (int k = 0; k < 1500; ++k) {
    const double a = 2 * std::numbers::pi * k / 97.0, h = -3 + 6.0 * k / 1500,
                 r = 2 + noise * rnd();
    std::array<double, 3> p{};
    for (int i = 0; i < 3; ++i)
      p[static_cast<std::size_t>(i)] =
          (i < 2 ? 1.0 : 0.0) + r * (std::cos(a) * u[i] + std::sin(a) * v[i]) + h * d[i];
    cyl.push_back(p);
    // plane 0.6 y + 0.8 z = 2 (normal d, distance 2), points spread over it
    const double s = rnd() * 5, t = rnd() * 5, off = noise * rnd();
    plane.push_back({s * u[0] + t * v[0] + (2 + off) * d[0], s * u[1] + t * v[1] + (2 + off) * d[1],
                     s * u[2] + t * v[2] + (2 + off) * d[2]});
  }
  const TempFile fc(".xyz", csv(cyl, ' '));
  const json c = run_json("fit '" + fc.path() + "' --cylinder");
  EXPECT_NEAR(c["radius"].get<double>(), 2, 2e-5);
  EXPECT_TRUE(near_group(flatten(c["axis_direction"]), {0, 0.6, 0.8}, {0, 1e-5}));
  // the axis point nearest the centroid lies on the axis: (p − (1,1,0)) ∥ d
  const auto p = flatten(c["axis_point"]);
  EXPECT_NEAR(p[0], 1, 2e-5);
  EXPECT_NEAR((p[1] - 1) * 0.8 - p[2] * 0.6, 0, 2e-5);
  EXPECT_LE(c["max_distance"].get<double>(), 1.2 * noise);
  const TempFile fp(".csv", csv(plane));
  const json pl = run_json("fit '" + fp.path() + "' --plane");
  EXPECT_TRUE(near_group(flatten(pl["normal"]), {0, 0.6, 0.8}, {0, 1e-6}));
  EXPECT_NEAR(pl["distance"].get<double>(), 2, 1e-5);
  EXPECT_LE(pl["max_distance"].get<double>(), 1.2 * noise);
}

TEST(FitCli, MeshVerticesAndBadInput) {
  // The octahedron with vertices at distance 2 from (1, 1, 1): its vertices fit that sphere
  // exactly.
  const TempFile obj(".obj",
                     "v 3 1 1\nv -1 1 1\nv 1 3 1\nv 1 -1 1\nv 1 1 3\nv 1 1 -1\n"
                     "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n");
  const json got = run_json("fit '" + obj.path() + "' --sphere");
  EXPECT_TRUE(near_group(flatten(got["center"]), {1, 1, 1}, {0, 1e-14}));
  EXPECT_NEAR(got["radius"].get<double>(), 2, 1e-14);
  const CliRun text = run_cli("fit '" + obj.path() + "' --sphere");
  EXPECT_NE(text.out.find("sphere fitted to 6 points"), std::string::npos) << text.out;

  const TempFile eight(".csv", "1,0,0\n0,1,0\n0,0,1\n-1,0,0\n0,-1,0\n0,0,-1\n1,1,0\n0,1,1\n");
  const TempFile flat(".csv", "0,0,0\n1,0,0\n0,1,0\n1,1,0\n2,3,0\n");
  const TempFile nan(".xyz", "0 0 0\n1 0 0\nnan 1 0\n0 0 1\n1 1 1\n");
  const TempFile junk(".csv", "x,y,z\n1,2,3\n1,2,oops\n");
  const struct {
    std::string args;
    int status;
    const char* message;
  } cases[] = {
      {"fit '" + eight.path() + "' --quadric", 1, "at least 9 points"},
      {"fit '" + flat.path() + "' --sphere", 1, "coplanar"},
      {"fit '" + nan.path() + "' --plane", 1, "finite"},
      {"fit '" + junk.path() + "' --plane", 1, ":3:"},
      {"fit /nonexistent.csv --plane", 1, "/nonexistent.csv"},
      {"fit '" + eight.path() + "'", 2, "exactly one of"},
      {"fit '" + eight.path() + "' --plane --sphere", 2, "exactly one of"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cli(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
}
