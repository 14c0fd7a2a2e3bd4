// Comparisons for tests that run two routes to one topology report or one set of mass properties
// (the triangle layout of the topology pass against its polygon layout, a moved mesh against a
// copied one, a streamed file against the read mesh): every field, doubles bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::test {

// Bitwise equality of doubles (NaN equal to NaN, −0 different from +0).
inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

#define EXPECT_SAME(a, b) \
  EXPECT_TRUE(::pgamesh::test::same_bits((a), (b))) << #a << ": " << (a) << " vs " << (b)
#define EXPECT_SAME_VEC(a, b)  \
  do {                         \
    EXPECT_SAME((a).x, (b).x); \
    EXPECT_SAME((a).y, (b).y); \
    EXPECT_SAME((a).z, (b).z); \
  } while (0)

// Face lists (zero-area, small, duplicated): every field.
void expect_same_faces(const std::vector<FaceLocation>& a, const std::vector<FaceLocation>& b);

// Edge lists (boundary, non-manifold, inconsistent): every field.
void expect_same_edges(const std::vector<EdgeLocation>& a, const std::vector<EdgeLocation>& b);

// Every field of two reports, doubles bit for bit.
void expect_same_report(const TopologyReport& a, const TopologyReport& b);

// Every figure of two mass property results, doubles bit for bit, with their counts and warnings.
void expect_same_mass(const MassProperties& a, const MassProperties& b);

}  // namespace pgamesh::test
