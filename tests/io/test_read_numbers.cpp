// Number parsing of the text readers: the fast decimal path must give exactly the double that
// std::from_chars gives (the correctly rounded value), for every shape of decimal mesh files use.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdio>
#include <random>
#include <string>

#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

std::string random_decimal(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> len(1, 21), digit(0, 9), coin(0, 3), ex(-40, 40);
  std::string s;
  if (coin(rng) == 0) s += '-';
  const int n = len(rng);
  const int point = coin(rng) == 0 ? -1 : std::uniform_int_distribution<int>(0, n)(rng);
  for (int i = 0; i < n; ++i) {
    if (i == point) s += '.';
    s += static_cast<char>('0' + digit(rng));
  }
  if (point == n) s += ".0";
  if (coin(rng) != 0) {
    s += coin(rng) == 0 ? 'E' : 'e';
    const int e = ex(rng);
    if (e >= 0 && coin(rng) == 0) s += '+';
    s += std::to_string(e);
  }
  return s;
}

TEST(ReadNumbers, EveryDecimalShapeMatchesFromChars) {
  std::mt19937_64 rng(12345);
  std::vector<std::string> numbers;
  for (int i = 0; i < 30000; ++i) numbers.push_back(random_decimal(rng));
  // Exact halfway and boundary cases of the fast path.
  for (const char* s : {"9007199254740993", "9007199254740992e22", "9007199254740992e-22", "1e22",
                        "1e23", "1e-22", "1e-23", "0.1", "-0", "-0.0e5", "4.9406564584124654e-324",
                        "2.2250738585072011e-308", "1.7976931348623157e308", "123456789012345678.9",
                        "0.30000000000000004", "5.", "0000000000000000000001", "1e0000", "1e+4",
                        // Fractions read eight digits at a time, around the 19-digit limit.
                        "0.12345678", "-0.123456789", "3.9999473112345678", "12345678901.12345678",
                        "1.123456789012345678", "1.1234567890123456789", "0.00000000",
                        "9.99999999e-3", "99999999999.99999999", "0.9999999999999999999"})
    numbers.push_back(s);
  std::string obj;
  for (std::size_t i = 0; i + 2 < numbers.size(); i += 3)
    obj += "v " + numbers[i] + " " + numbers[i + 1] + " " + numbers[i + 2] + "\n";
  const Mesh m = test::read_text(obj);
  ASSERT_EQ(m.vertices.size(), numbers.size() / 3);
  for (std::size_t i = 0; i < m.vertices.size() * 3; ++i) {
    const std::string& s = numbers[i];
    double want = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), want);
    ASSERT_EQ(r.ptr, s.data() + s.size()) << s;
    const double got = m.vertices[i / 3][static_cast<int>(i % 3)];
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
        << s << ": " << got << " vs " << want;
  }
}

}  // namespace
}  // namespace pgamesh
