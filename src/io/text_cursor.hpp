// Internal: a cursor over the bytes of a text mesh format (STL ASCII, OBJ, PLY, OFF). Numbers are
// parsed in place with std::from_chars (no iostreams, no copies); line:column is computed only when
// an error is reported, so the hot loop pays nothing for positions.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "pgamesh/core/input_error.hpp"

namespace pgamesh::detail {

// Line and column (1-based) of `at` within the text starting at `begin`.
InputPosition text_position(const char* begin, const char* at);

// A binary position: byte offset only.
inline InputPosition byte_position(std::uint64_t offset) {
  return InputPosition{0, 0, offset, false};
}

// What the input holds at `at`, for messages: 'token', "end of line", "end of file", or
// "byte 0xE9" for a byte that is not printable ASCII (a non-UTF-8 or binary byte in a text format).
std::string describe_at(const char* at, const char* end);

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
inline bool is_space(char c) {
  return is_blank(c) || c == '\n';
}

// The value of a plain decimal ([-]digits[.digits][e[+-]digits]) starting at p, bit-identical to
// std::from_chars; returns the end of the number, or nullptr when it is not such a decimal or
// needs more than the fast path (then from_chars decides).
const char* simple_decimal(const char* p, const char* end, double& out);

// ASCII case-insensitive equality, for keywords such as "facet" / "FACET".
bool same_word(std::string_view a, std::string_view b);

class TextCursor {
 public:
  TextCursor(std::span<const char> bytes, const std::string& name)
      : begin(bytes.data()), p(bytes.data()), end(bytes.data() + bytes.size()), name(name) {}

  // Throws InputError at `at` (file:line:column).
  [[noreturn]] void fail(const char* at, const std::string& problem) const;

  bool at_end() const { return p == end; }
  // True at the end of the current line (call after skip_blanks).
  bool at_eol() const { return p == end || *p == '\n'; }
  // Skips spaces, tabs and carriage returns, staying on the line.
  void skip_blanks() {
    while (p != end && is_blank(*p)) ++p;
  }
  // Skips all whitespace including newlines.
  void skip_space() {
    while (p != end && is_space(*p)) ++p;
  }
  // Moves past the next newline (or to the end).
  void skip_line();
  // The next run of non-whitespace bytes on this line (empty at the end of a line).
  std::string_view word();

  // A decimal number (optional sign, fraction, exponent; also "nan"/"inf" which callers reject)
  // ending at whitespace, the end, or `delimiter`. `what` names it in errors.
  double number(const char* what, char delimiter = 0);
  // A number that must be finite: NaN/Inf coordinates are an error with their position.
  double coordinate(const char* what);
  // A signed decimal integer ending at whitespace, the end, or `delimiter`.
  std::int64_t integer(const char* what, char delimiter = 0);

  const char* begin;
  const char* p;
  const char* end;
  const std::string& name;
};

}  // namespace pgamesh::detail
