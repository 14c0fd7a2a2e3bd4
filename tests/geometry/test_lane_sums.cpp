// The lanes of chunked_sums.hpp: four faces summed at once in Double4 give, lane by lane, the bits
// of the same formulas in double; a chunk's sum is (lane 0 + lane 1) + (lane 2 + lane 3); faces
// handed over one at a time (StreamedChunkSums) sum to chunked_sums' bits on any thread count; and
// four binary STL records read as lanes are the records read one by one.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "detail/simd/double4.hpp"
#include "geometry/chunked_sums.hpp"
#include "io/stl_binary.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {
namespace {

// Doubles compared by their bits (so −0 ≠ +0 and NaN = the same NaN).
void expect_same_bits(double a, double b, const char* what, int lane) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
      << what << " lane " << lane << ": " << a << " vs " << b;
}

void expect_same_sums(const BoundarySums& a, const BoundarySums& b, int lane) {
  expect_same_bits(a.area2, b.area2, "area2", lane);
  expect_same_bits(a.carrier_sum.e0, b.carrier_sum.e0, "carrier e0", lane);
  expect_same_bits(a.carrier_sum.e1, b.carrier_sum.e1, "carrier e1", lane);
  expect_same_bits(a.carrier_sum.e2, b.carrier_sum.e2, "carrier e2", lane);
  expect_same_bits(a.carrier_sum.e3, b.carrier_sum.e3, "carrier e3", lane);
  expect_same_bits(a.volume6, b.volume6, "volume6", lane);
  expect_same_bits(a.moment24.x, b.moment24.x, "moment x", lane);
  expect_same_bits(a.moment24.y, b.moment24.y, "moment y", lane);
  expect_same_bits(a.moment24.z, b.moment24.z, "moment z", lane);
  for (int i = 0; i < 6; ++i) expect_same_bits(a.second120[i], b.second120[i], "second", lane);
}

// Coordinates of many magnitudes: unit ones, tiny triangles far from the reference, huge ones.
Vec3d random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> scale(-30, 30);
  const double s = std::ldexp(1.0, scale(rng));
  return {s * unit(rng), s * unit(rng), s * unit(rng)};
}

TEST(LaneSums, Double4LanesAreTheDoubleFormulasBitForBit) {
  std::mt19937_64 rng(20261125);
  BasicBoundarySums<Double4> four;
  BoundarySums one[4];
  for (int group = 0; group < 2000; ++group) {
    Vec3d v[4][3];
    for (auto& face : v)
      for (Vec3d& p : face) p = random_point(rng);
    if (group % 7 == 0) v[1][2] = v[1][1];  // a collapsed triangle: zero carrier, zero volume
    const Vec3<Double4> a = lanes(v[0][0], v[1][0], v[2][0], v[3][0]);
    const Vec3<Double4> b = lanes(v[0][1], v[1][1], v[2][1], v[3][1]);
    const Vec3<Double4> c = lanes(v[0][2], v[1][2], v[2][2], v[3][2]);
    const Vec3d ref{0.25, -3, 7};
    const Vec3<Double4> ref4{ref.x, ref.y, ref.z};
    Double4 norm4;
    const pga3::Plane<Double4> f4 = add_triangle(four, a - ref4, b - ref4, c - ref4, norm4);
    for (int j = 0; j < 4; ++j) {
      double norm = 0;
      const pga3::Plane<double> f =
          add_triangle(one[j], v[j][0] - ref, v[j][1] - ref, v[j][2] - ref, norm);
      expect_same_bits(norm4.lane(j), norm, "carrier norm", j);
      expect_same_bits(f4.e0.lane(j), f.e0, "carrier e0", j);
      expect_same_bits(f4.e3.lane(j), f.e3, "carrier e3", j);
    }
  }
  for (int j = 0; j < 4; ++j) expect_same_sums(lane(four, j), one[j], j);
}

TEST(LaneSums, SquareRootIsCorrectlyRoundedInEveryLane) {
  const Double4 x(2.0, 1e-300, 0.0, 1e300);
  const Double4 r = sqrt(x);
  for (int j = 0; j < 4; ++j) EXPECT_EQ(r.lane(j), std::sqrt(x.lane(j)));
  EXPECT_TRUE(std::isnan(sqrt(Double4(-1.0)).lane(3)));
}

TEST(LaneSums, ChunkSumIsLaneZeroPlusOneThenTwoPlusThree) {
  // One chunk of four faces, 2^53, 1, −2^53, 1/2, one per lane: (2^53 + 1) + (−2^53 + 1/2) rounds
  // both halves to ±2^53 (ties to even) and gives 0. Face by face the sum would be 1/2, pairing
  // lanes 0 + 2 and 1 + 3 would give 3/2, and folding from the right 1.
  const double big = std::ldexp(1.0, 53);
  const double face[4] = {big, 1, -big, 0.5};
  const double sum =
      chunked_sums<double>(4, 1, [&](LanedSums<double>& s, std::size_t b, std::size_t e) {
        for (std::size_t f = b; f < e; ++f) s[f] += face[f];
      });
  EXPECT_EQ(sum, 0.0);
}

TEST(LaneSums, StreamedFacesSumAsChunkedOnAnyThreadCount) {
  // Three and a half chunks of values whose sum depends on the order of the additions.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> scale(-40, 40);
  std::vector<double> value(7 * faces_per_chunk / 2 + 3);
  for (double& v : value) v = std::ldexp(unit(rng), scale(rng));
  StreamedChunkSums<double> streamed;
  for (double v : value) {
    streamed.current() += v;
    streamed.next();
  }
  // The same, spelled out: per chunk, four lanes in face order, (L0 + L1) + (L2 + L3); the chunks
  // in order.
  double expected = 0;
  for (std::size_t begin = 0; begin < value.size(); begin += faces_per_chunk) {
    double l[4] = {0, 0, 0, 0};
    for (std::size_t f = begin; f < std::min(value.size(), begin + faces_per_chunk); ++f)
      l[(f - begin) % 4] += value[f];
    expected += (l[0] + l[1]) + (l[2] + l[3]);
  }
  EXPECT_EQ(streamed.total(), expected);
  for (unsigned threads : {1u, 2u, 5u}) {
    const double chunked = chunked_sums<double>(
        value.size(), threads, [&](LanedSums<double>& s, std::size_t b, std::size_t e) {
          for (std::size_t f = b; f < e; ++f) s[f] += value[f];
        });
    EXPECT_EQ(chunked, expected) << threads << " threads";
  }
}

// Four records of layout L and nothing after them, read as lanes and one by one: the same
// doubles, and the lane reader stays inside the records (ASan would see it read past them).
template <TriangleRecordLayout L>
void expect_four_records_read_as_lanes() {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> coordinate(-1e6f, 1e6f);
  std::vector<unsigned char> records(4 * L.stride);
  for (unsigned char& b : records) b = static_cast<unsigned char>(byte(rng));
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t k = 0; k < 9; ++k) {
      const float x = coordinate(rng);
      std::uint32_t u = std::bit_cast<std::uint32_t>(x);
      if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap32(u);
      std::memcpy(records.data() + L.stride * r + L.coords + 4 * k, &u, 4);
    }
  Vec3<Double4> four[3];
  stl_triangles4<L>(records.data(), four);
  for (int j = 0; j < 4; ++j) {
    Vec3d one[3];
    stl_triangle<L>(records.data() + L.stride * static_cast<std::size_t>(j), one);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(four[k].x.lane(j), one[k].x) << "record " << j << " vertex " << k;
      EXPECT_EQ(four[k].y.lane(j), one[k].y) << "record " << j << " vertex " << k;
      EXPECT_EQ(four[k].z.lane(j), one[k].z) << "record " << j << " vertex " << k;
    }
  }
}

TEST(LaneSums, FourStlRecordsReadAsLanesAreTheRecordsReadOneByOne) {
  expect_four_records_read_as_lanes<stl_record_layout>();
}

// A GLB's packed positions: 36-byte records, the coordinates from byte 0 (loads at 0, 16, 20).
TEST(LaneSums, FourPackedTrianglesReadAsLanesAreTheTrianglesReadOneByOne) {
  expect_four_records_read_as_lanes<packed_triangle_layout>();
}

}  // namespace
}  // namespace pgamesh
