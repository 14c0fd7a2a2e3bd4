// Carriers by join and their norms: paper Tables 3 and 4 on a unit tetrahedron.
#include <gtest/gtest.h>

#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::pga3 {

TEST(Pga3Join, TetrahedronCarriers) {
  const auto o = origin<double>();
  const auto a = point(1.0, 0.0, 0.0), b = point(0.0, 1.0, 0.0), c = point(0.0, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(norm(a & b), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(norm(a & b & c) / 2, std::sqrt(3.0) / 2);
  // docs/conventions.md §8: o on the left gives +V.
  EXPECT_DOUBLE_EQ((o & (a & b & c)) / 6, 1.0 / 6);
  EXPECT_DOUBLE_EQ(((a & b & c) & o) / 6, -1.0 / 6);
}

}  // namespace pgamesh::pga3
