// The density or mass given to mass_properties must be a positive finite number: zero or less
// describes no body (its masses and inertias would be negative or zero).
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "support/solids.hpp"

namespace pgamesh::test {
namespace {

TEST(MassOptions, DensityAndMassMustBePositiveAndFinite) {
  const Mesh cube = box_mesh(1, 1, 1);
  for (double bad : {0.0, -0.0, -1.0, std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN()}) {
    MassOptions density;
    density.density = bad;
    EXPECT_THROW(mass_properties(cube, density), std::invalid_argument) << bad;
    MassOptions mass;
    mass.mass = bad;
    EXPECT_THROW(mass_properties(cube, mass), std::invalid_argument) << bad;
  }
  MassOptions good;
  good.mass = 3;
  EXPECT_EQ(mass_properties(cube, good).density, 3.0);
}

}  // namespace
}  // namespace pgamesh::test
