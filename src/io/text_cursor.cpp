#include "io/text_cursor.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace pgamesh::detail {

InputPosition text_position(const char* begin, const char* at) {
  InputPosition pos;
  pos.has_line = true;
  pos.byte_offset = static_cast<std::uint64_t>(at - begin);
  pos.line = 1;
  const char* line_start = begin;
  for (const char* q = begin; q != at; ++q) {
    if (*q == '\n') {
      ++pos.line;
      line_start = q + 1;
    }
  }
  pos.column = static_cast<std::uint64_t>(at - line_start) + 1;
  return pos;
}

std::string describe_at(const char* at, const char* end) {
  if (at == end) return "end of file";
  if (*at == '\n' || *at == '\r') return "end of line";
  const auto u = static_cast<unsigned char>(*at);
  if (u < 0x20 || u >= 0x7f) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "byte 0x%02X (not ASCII text)", u);
    return buf;
  }
  std::string s = "'";
  const char* q = at;
  while (q != end && !is_space(*q) && q - at < 24) {
    const auto c = static_cast<unsigned char>(*q);
    if (c < 0x20 || c >= 0x7f) break;
    s += *q++;
  }
  if (q != end && !is_space(*q) && q - at >= 24) s += "...";
  return s + "'";
}

bool same_word(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  if (a == b) return true;  // the usual lower-case keyword
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

void TextCursor::fail(const char* at, const std::string& problem) const {
  throw InputError(name, text_position(begin, at), problem);
}

void TextCursor::skip_line() {
  const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  p = nl ? static_cast<const char*>(nl) + 1 : end;
}

std::string_view TextCursor::word() {
  skip_blanks();
  const char* s = p;
  while (p != end && !is_space(*p)) ++p;
  return {s, static_cast<std::size_t>(p - s)};
}

namespace {

// When the 8 bytes at p are all decimal digits, their value (SWAR: two bytes, then four, then
// eight are combined by three multiplications instead of eight dependent ones).
bool eight_digits(const char* p, std::uint64_t& value) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
  // Every byte 0x30-0x39: high nibble 3, and adding 6 does not carry out of the low nibble.
  if ((v & 0xF0F0F0F0F0F0F0F0) != 0x3030303030303030 ||
      ((v + 0x0606060606060606) & 0xF0F0F0F0F0F0F0F0) != 0x3030303030303030)
    return false;
  v -= 0x3030303030303030;
  v = v * 10 + (v >> 8);  // pairs: byte 2k holds digits 2k, 2k+1 as a number 0-99
  v = (((v & 0x000000FF000000FF) * (100 + (1000000ULL << 32))) +
       (((v >> 16) & 0x000000FF000000FF) * (1 + (10000ULL << 32)))) >>
      32;
  value = static_cast<std::uint32_t>(v);
  return true;
}

bool ends_token(const char* q, const char* end, char delimiter) {
  return q == end || is_space(*q) || (delimiter && *q == delimiter);
}
}  // namespace

// Clinger's fast path for the plain decimals mesh files are made of: with at most 19 digits, a
// mantissa m <= 2^53 and a power of ten 10^e with |e| <= 22 are both exact doubles, so m * 10^e
// (or m / 10^-e) is one correctly rounded operation — bit-identical to std::from_chars. Anything
// else (longer mantissas, larger exponents, nan, inf) returns nullptr and goes to from_chars.
const char* simple_decimal(const char* p, const char* end, double& out) {
  static constexpr double pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const char* q = p;
  const bool negative = q != end && *q == '-';
  if (negative) ++q;
  std::uint64_t m = 0;
  int digits = 0, fraction = 0;
  auto digit = [&](const char* c) { return c != end && static_cast<unsigned>(*c - '0') < 10; };
  for (; digit(q); ++q, ++digits) m = m * 10 + static_cast<unsigned>(*q - '0');
  if (q != end && *q == '.') {
    ++q;
    // Fractions are usually 6-9 digits long: take eight at a time where the bytes allow.
    for (std::uint64_t eight; end - q >= 8 && eight_digits(q, eight);
         q += 8, digits += 8, fraction += 8)
      m = m * 100000000 + eight;
    for (; digit(q); ++q, ++digits, ++fraction) m = m * 10 + static_cast<unsigned>(*q - '0');
  }
  if (digits == 0 || digits > 19) return nullptr;
  int e = 0;
  if (q != end && (*q == 'e' || *q == 'E')) {
    const char* r = q + 1;
    const bool eneg = r != end && *r == '-';
    if (r != end && (*r == '-' || *r == '+')) ++r;
    int edigits = 0;
    for (; digit(r); ++r)
      if (++edigits > 4)
        return nullptr;
      else
        e = e * 10 + (*r - '0');
    if (edigits) {  // "1e" is "1" followed by a stray 'e', as for from_chars
      q = r;
      if (eneg) e = -e;
    } else {
      e = 0;
    }
  }
  e -= fraction;
  if (m > (std::uint64_t{1} << 53) || e < -22 || e > 22) return nullptr;
  const double v = e < 0 ? static_cast<double>(m) / pow10[-e] : static_cast<double>(m) * pow10[e];
  out = negative ? -v : v;
  return q;
}

double TextCursor::number(const char* what, char delimiter) {
  skip_blanks();
  const char* s = p;
  if (s != end && *s == '+' && s + 1 != end && *(s + 1) != '-') ++s;  // from_chars has no '+'
  double v = 0;
  if (const char* q = simple_decimal(s, end, v)) {
    if (!ends_token(q, end, delimiter))
      fail(p, std::string("malformed ") + what + " " + describe_at(p, end));
    p = q;
    return v;
  }
  const auto r = std::from_chars(s, end, v);
  if (r.ec == std::errc::invalid_argument)
    fail(p, std::string("expected ") + what + ", found " + describe_at(p, end));
  if (!ends_token(r.ptr, end, delimiter))
    fail(p, std::string("malformed ") + what + " " + describe_at(p, end));
  if (r.ec == std::errc::result_out_of_range)
    fail(p, std::string(what) + " " + describe_at(p, end) + " is out of the range of a double");
  p = r.ptr;
  return v;
}

double TextCursor::coordinate(const char* what) {
  skip_blanks();
  const char* s = p;
  const double v = number(what);
  if (!std::isfinite(v)) fail(s, std::string("non-finite ") + what + " " + describe_at(s, end));
  return v;
}

std::int64_t TextCursor::integer(const char* what, char delimiter) {
  skip_blanks();
  const char* s = p;
  if (s != end && *s == '+' && s + 1 != end && *(s + 1) != '-') ++s;
  std::int64_t v = 0;
  const auto r = std::from_chars(s, end, v);
  if (r.ec == std::errc::invalid_argument)
    fail(p, std::string("expected ") + what + ", found " + describe_at(p, end));
  if (!ends_token(r.ptr, end, delimiter))
    fail(p, std::string("malformed ") + what + " " + describe_at(p, end));
  if (r.ec == std::errc::result_out_of_range)
    fail(p, std::string(what) + " " + describe_at(p, end) + " is out of range");
  p = r.ptr;
  return v;
}

}  // namespace pgamesh::detail
