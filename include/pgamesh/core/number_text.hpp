// Numbers as text, one rule for the whole project: what a command-line argument, a query parameter
// or a message accepts and prints. Parsing is std::from_chars (independent of the C locale, the
// whole text or nothing); printing is %.17g, which reads back to the same bits.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace pgamesh {

// The finite number that is the whole of `text` (a leading '+' allowed), or nullopt.
inline std::optional<double> parse_number(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc{} || stop != end || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// The whole of `text` as a non-negative integer, or nullopt.
inline std::optional<unsigned long long> parse_count(std::string_view text) {
  unsigned long long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc{} || stop != end) return std::nullopt;
  return value;
}

// `x` with 17 significant digits (%.17g): the text reads back to the same double.
inline std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace pgamesh
