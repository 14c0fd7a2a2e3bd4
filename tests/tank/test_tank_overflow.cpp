// Coordinates whose figures overflow a double are refused by the front door (std::range_error)
// and by make_tank (std::invalid_argument), never returned as inf or nan.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/tank/tank.hpp"
#include "support/solids.hpp"

namespace pgamesh::test {
namespace {

TEST(TankOverflow, HugeCubeIsRefusedByTheFrontDoorAndTheTank) {
  const Mesh huge = box_mesh(1e120, 1e120, 1e120);  // volume 1e360
  EXPECT_THROW(analyze_mesh(huge, MeshSource{}), std::range_error);
  EXPECT_THROW(tank::make_tank(huge), std::invalid_argument);
  // Volume 1e300 fits, but not the inertia 1e500 / 6, nor the squares 1e400 under the norm of a
  // face's vector area: refused by both.
  const Mesh large = box_mesh(1e100, 1e100, 1e100);
  EXPECT_THROW(analyze_mesh(large, MeshSource{}), std::range_error);
  EXPECT_THROW(tank::make_tank(large), std::invalid_argument);
  // Side 2^200: every figure fits, and is exact.
  const double side = std::ldexp(1.0, 200);
  EXPECT_EQ(tank::make_tank(box_mesh(side, side, side)).volume, std::ldexp(1.0, 600));
}

}  // namespace
}  // namespace pgamesh::test
