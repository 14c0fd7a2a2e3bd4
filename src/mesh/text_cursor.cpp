#include "text_cursor.hpp"

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
bool ends_token(const char* q, const char* end, char delimiter) {
  return q == end || is_space(*q) || (delimiter && *q == delimiter);
}
}  // namespace

double TextCursor::number(const char* what, char delimiter) {
  skip_blanks();
  const char* s = p;
  if (s != end && *s == '+' && s + 1 != end && *(s + 1) != '-') ++s;  // from_chars has no '+'
  double v = 0;
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
