// The double kernels compiled in the library for more than one instruction set (pga3/isa.hpp,
// docs/pga3.md "Speed"): every variant against the header formula it is compiled from, in this
// test's own compilation — the batch loops, the motor product and the sandwiches bit for bit, the
// join bit for bit up to the sign of a zero (its AVX2 variant runs the four-lane form of
// join.hpp). test_pga3_kernels.cpp checks the lane and four-lane forms against the generic
// formulas. The baseline variant is called explicitly, so
// the fallback is tested on every processor; the AVX2 variant runs where the processor has it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "pga3_random.hpp"
#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/algebra/pga3/isa.hpp"

namespace pgamesh::pga3 {
namespace {

using detail::Isa;
using test::random_motor;
using test::random_plane;
using test::random_point;

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  // memcmp may not be handed the null data() of an empty vector, even for zero bytes.
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}
template <class Element>
bool same_bits(const Element& a, const Element& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
// Equal coefficient by coefficient, bit for bit except that a zero may carry the other sign.
template <class Element>
bool same_values(const Element& a, const Element& b) {
  constexpr std::size_t n = sizeof(Element) / sizeof(double);
  double x[n], y[n];
  std::memcpy(x, &a, sizeof a), std::memcpy(y, &b, sizeof b);
  for (std::size_t k = 0; k < n; ++k)
    if (!(x[k] == y[k]) || (x[k] != 0 && std::memcmp(&x[k], &y[k], sizeof(double)) != 0))
      return false;
  return true;
}

TEST(Pga3Isa, RunsTheInstructionSetsOfThisProcessor) {
  EXPECT_TRUE(detail::runs(Isa::baseline));
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
  __builtin_cpu_init();
  EXPECT_EQ(detail::runs(Isa::avx2), bool(__builtin_cpu_supports("avx2")));
#else
  EXPECT_FALSE(detail::runs(Isa::avx2));
#endif
  std::printf("pga3 kernels: AVX2 variant %s on this processor\n",
              detail::runs(Isa::avx2) ? "runs" : "does not run (baseline only)");
}

// Each variant, and the dispatched apply_to_points / apply_to_planes, against the header loops for
// 0 … 41 elements (the four-lane loop and every tail), out of place and in place.
TEST(Pga3Isa, BatchVariantsGiveTheLoopBits) {
  std::mt19937 rng(59);
  for (std::size_t n = 0; n <= 41; ++n) {
    const Motor<double> m = random_motor<double>(rng);
    std::vector<double> in[4], want[4];
    for (auto& v : in)
      for (std::size_t i = 0; i < n; ++i) v.push_back(test::Num<double>::random(rng));
    for (auto& v : want) v.assign(n, 0);
    const detail::SandwichMatrix<double> s = detail::sandwich_matrix(m);
    const double u[4] = {1.5, -0.25, 0.75, s.weight};
    detail::transform_points_loop(s.r, in[0].data(), in[1].data(), in[2].data(), want[0].data(),
                                  want[1].data(), want[2].data(), n);
    for (Isa isa : {Isa::baseline, Isa::avx2}) {
      std::vector<double> got[3] = {std::vector<double>(n), std::vector<double>(n),
                                    std::vector<double>(n)};
      detail::transform_points(isa, s.r, in[0].data(), in[1].data(), in[2].data(), got[0].data(),
                               got[1].data(), got[2].data(), n);
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(got[k], want[k])) << n << ' ' << k;
      std::vector<double> place[3] = {in[0], in[1], in[2]};
      detail::transform_points(isa, s.r, place[0].data(), place[1].data(), place[2].data(),
                               place[0].data(), place[1].data(), place[2].data(), n);
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(place[k], want[k])) << n << ' ' << k;
    }
    detail::transform_planes_loop(s.r, u, in[0].data(), in[1].data(), in[2].data(), in[3].data(),
                                  want[0].data(), want[1].data(), want[2].data(), want[3].data(),
                                  n);
    for (Isa isa : {Isa::baseline, Isa::avx2}) {
      std::vector<double> got[4] = {in[0], in[1], in[2], in[3]};  // in place
      detail::transform_planes(isa, s.r, u, got[0].data(), got[1].data(), got[2].data(),
                               got[3].data(), got[0].data(), got[1].data(), got[2].data(),
                               got[3].data(), n);
      for (int k = 0; k < 4; ++k) ASSERT_TRUE(same_bits(got[k], want[k])) << n << ' ' << k;
    }
    // The public batch forms, with the plane offset vector they form themselves.
    std::vector<double> got[4] = {std::vector<double>(n), std::vector<double>(n),
                                  std::vector<double>(n), std::vector<double>(n)};
    apply_to_points(m, in[0], in[1], in[2], got[0], got[1], got[2]);
    detail::transform_points_loop(s.r, in[0].data(), in[1].data(), in[2].data(), want[0].data(),
                                  want[1].data(), want[2].data(), n);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(got[k], want[k])) << n << ' ' << k;
  }
}

// The single-element kernels: baseline = the generic (quaternion-order) formulas bit for bit;
// AVX2 = the lane forms of motor.hpp bit for bit, and for the join the four-lane form, the generic
// values up to the sign of a zero. Half the motors are rotors (zero ideal part), where zero sums
// occur.
TEST(Pga3Isa, SingleElementVariantsGiveTheHeaderBits) {
  std::mt19937 rng(61);
  for (int i = 0; i < 20000; ++i) {
    Motor<double> a = random_motor<double>(rng), b = random_motor<double>(rng);
    Plane<double> v = random_plane<double>(rng);
    const Point<double> x = random_point<double>(rng);
    if (i % 2 == 0) a.e01 = a.e02 = a.e03 = a.e0123 = v.e0 = 0;
    if (i % 4 == 0) b.e01 = b.e02 = b.e03 = b.e0123 = 0;
    ASSERT_TRUE(same_bits(detail::geometric_product(Isa::baseline, a, b),
                          quaternion_order::geometric_product(a, b)))
        << i;
    ASSERT_TRUE(same_bits(detail::apply(Isa::baseline, a, x), quaternion_order::apply(a, x))) << i;
    ASSERT_TRUE(same_bits(detail::apply(Isa::baseline, a, v), quaternion_order::apply(a, v))) << i;
#ifdef PGAMESH_PGA3_SIMD
    if (detail::runs(Isa::avx2)) {
      ASSERT_TRUE(same_bits(detail::geometric_product(Isa::avx2, a, b),
                            detail::geometric_product_lanes(a, b)))
          << i;
      ASSERT_TRUE(same_bits(detail::apply(Isa::avx2, a, x), detail::apply_lanes(a, x))) << i;
      ASSERT_TRUE(same_bits(detail::apply(Isa::avx2, a, v), detail::apply_lanes(a, v))) << i;
    }
#endif
    const Point<double> y = random_point<double>(rng), z = random_point<double>(rng);
    const Plane<double> xyz = join(join(x, y), z);
    ASSERT_TRUE(same_bits(detail::join(Isa::baseline, x, y, z), xyz)) << i;
    ASSERT_TRUE(same_values(detail::join(Isa::avx2, x, y, z), xyz)) << i;
  }
}

}  // namespace
}  // namespace pgamesh::pga3
