// Every case of golden/fuel_slices.json (exact values for the float64 meshes) through the
// reference pass, plus the gauge table and the inverse cases.
#include <gtest/gtest.h>

#include "pgamesh/tank/fuel_state.hpp"
#include "support/golden.hpp"
#include "tank/tank_test_support.hpp"

using namespace pgamesh;
using namespace pgamesh::tank;
using pgamesh::test::flatten;
using pgamesh::test::json;
using pgamesh::test::json_vec3;
using pgamesh::test::near_group;
using pgamesh::test::near_scalar;

namespace {

void check_slice_case(const json& file, const json& c, const FuelState& st) {
  const auto tol = pgamesh::test::tolerance_of(file, c);
  const json& e = c["expected"];
  EXPECT_TRUE(near_scalar(st.volume, e["volume"].get<double>(), tol)) << "volume";
  EXPECT_TRUE(near_scalar(st.fraction, e["fraction"].get<double>(), tol)) << "fraction";
  EXPECT_TRUE(near_scalar(st.wetted_area, e["wetted_area"].get<double>(), tol)) << "wetted";
  EXPECT_TRUE(near_scalar(st.surface_area, e["surface_area"].get<double>(), tol)) << "surface";
  if (e["center_of_mass"].is_null()) {
    EXPECT_FALSE(st.has_center);
  } else {
    ASSERT_TRUE(st.has_center);
    const Vec3d g = st.center_of_mass;
    EXPECT_TRUE(near_group({g.x, g.y, g.z}, flatten(e["center_of_mass"]), tol)) << "COM";
  }
  const auto& f = e["kept_carrier_sum"];
  auto blade = [&](const char* k) { return f.contains(k) ? f[k].get<double>() : 0.0; };
  EXPECT_TRUE(
      near_group({st.carrier_sum.e0, st.carrier_sum.e1, st.carrier_sum.e2, st.carrier_sum.e3},
                 {blade("e0"), blade("e1"), blade("e2"), blade("e3")}, tol))
      << "carrier sum";
  // The free surface measured from its boundary segments agrees with the gap ½‖F‖.
  EXPECT_NEAR(st.surface.area, st.surface_area, 1e-12 * (1 + st.surface_area));
}

}  // namespace

TEST(FuelGolden, AllSlices) {
  const json file = pgamesh::test::load_golden("fuel_slices.json");
  int slices = 0;
  for (const json& c : file["cases"]) {
    const json& in = c["input"];
    if (!in.contains("level") || !c["expected"].contains("volume")) continue;
    SCOPED_TRACE(c["id"].get<std::string>());
    const Tank t = make_tank(pgamesh::test::load_golden_obj(in["mesh"].get<std::string>()));
    const FuelState st = fuel_naive(t, fuel_plane(json_vec3(in["up"]), in["level"].get<double>()));
    check_slice_case(file, c, st);
    ++slices;
  }
  EXPECT_EQ(slices, 17);
}
