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

// Why a text is not a number, for readers that say so (3MF): not a decimal number as a whole,
// beyond double's range, or infinite / NaN.
enum class NumberFault { none, malformed, out_of_range, non_finite };

// Reads the whole of `text` (a leading '+' allowed) into `value`: NumberFault::none when it is a
// finite number, else why not.
inline NumberFault read_number(std::string_view text, double& value) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || stop != end) return NumberFault::malformed;
  if (ec == std::errc::result_out_of_range) return NumberFault::out_of_range;
  if (ec != std::errc{}) return NumberFault::malformed;
  return std::isfinite(value) ? NumberFault::none : NumberFault::non_finite;
}

// The words for a fault, as error messages print them.
inline const char* describe(NumberFault f) {
  switch (f) {
    case NumberFault::malformed:
      return "malformed number";
    case NumberFault::out_of_range:
      return "number out of double range";
    case NumberFault::non_finite:
      return "non-finite number (inf or nan)";
    case NumberFault::none:
      break;
  }
  return "number";
}

// The finite number that is the whole of `text` (a leading '+' allowed), or nullopt.
inline std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  if (read_number(text, value) != NumberFault::none) return std::nullopt;
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
