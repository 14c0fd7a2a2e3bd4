// The large-array allocator of the weld and the topology pass (src/mesh/huge_pages.hpp,
// uninitialized_array.hpp): blocks of half a huge page or more start on a 2 MiB boundary, smaller
// ones are std::allocator's, and the arrays keep their contents through growth and copies.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/uninitialized_array.hpp"

namespace {

using pgamesh::detail::huge_page_bytes;
using pgamesh::detail::HugeVector;

std::uintptr_t address(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p);
}

TEST(HugePages, LargeBlocksStartOnAHugePageBoundary) {
  for (std::size_t bytes : {huge_page_bytes / 2, huge_page_bytes, 3 * huge_page_bytes + 12}) {
    HugeVector<std::uint32_t> v(bytes / 4, 7u);
    EXPECT_EQ(address(v.data()) % huge_page_bytes, 0u) << bytes << " bytes";
    EXPECT_EQ(v.front(), 7u);
    EXPECT_EQ(v.back(), 7u);
  }
}

TEST(HugePages, SmallBlocksAreOrdinary) {
  HugeVector<std::uint64_t> v(1000);
  std::iota(v.begin(), v.end(), std::uint64_t{0});
  EXPECT_EQ(v[999], 999u);
  // Below half a huge page the block is std::allocator's, with no huge-page alignment asked for:
  // of a few such blocks, at least one does not start on a 2 MiB boundary.
  HugeVector<char> a(100), b(100), c(100);
  EXPECT_FALSE(address(a.data()) % huge_page_bytes == 0 &&
               address(b.data()) % huge_page_bytes == 0 &&
               address(c.data()) % huge_page_bytes == 0);
}

TEST(HugePages, GrowthAcrossTheThresholdKeepsTheContents) {
  HugeVector<std::uint32_t> v;
  for (std::uint32_t i = 0; i < 1'000'000; ++i) v.push_back(i * 3);  // 4 MB: crosses it
  EXPECT_EQ(address(v.data()) % huge_page_bytes, 0u);
  for (std::uint32_t i = 0; i < 1'000'000; i += 9973) ASSERT_EQ(v[i], i * 3);
  const HugeVector<std::uint32_t> copy = v;
  EXPECT_EQ(copy, v);
  v.clear();
  v.shrink_to_fit();
  EXPECT_EQ(v.capacity(), 0u);
}

TEST(HugePages, UninitializedArraysAreWritableThroughout) {
  const std::size_t n = 3 * huge_page_bytes / 4 + 5;
  auto a = pgamesh::detail::uninitialized_array<std::uint32_t>(n);
  EXPECT_EQ(address(a.get()) % huge_page_bytes, 0u);
  for (std::size_t i = 0; i < n; ++i) a[i] = static_cast<std::uint32_t>(i);
  EXPECT_EQ(a[n - 1], n - 1);
  auto small = pgamesh::detail::uninitialized_array<std::uint32_t>(3);
  small[2] = 5;
  EXPECT_EQ(small[2], 5u);
  a = std::move(small);  // the large block freed by its own deleter
  EXPECT_EQ(a[2], 5u);
}

}  // namespace
