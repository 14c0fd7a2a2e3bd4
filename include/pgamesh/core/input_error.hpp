// The one error type for bad input: every reader and every command reports the file, the position
// (line and column for text, byte offset for binary) and the problem, and never crashes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace pgamesh {

struct InputPosition {
  std::uint64_t line = 0;         // 1-based line for text input; 0 when not applicable
  std::uint64_t column = 0;       // 1-based column; 0 when not applicable
  std::uint64_t byte_offset = 0;  // offset of the offending byte from the start of the file
  bool has_line = false;
};

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, InputPosition where, const std::string& problem)
      : std::runtime_error(format(file, where, problem)), file_(std::move(file)), where_(where) {}

  const std::string& file() const { return file_; }
  const InputPosition& where() const { return where_; }

  // "FILE:LINE:COL: problem" for text, "FILE: byte OFFSET: problem" for binary input.
  static std::string format(const std::string& file, InputPosition where,
                            const std::string& problem) {
    // Appended piece by piece: GCC 12's -Wrestrict misfires on `"literal" + std::string&&`.
    std::string s = file;
    if (where.has_line) {
      s += ':';
      s += std::to_string(where.line);
      if (where.column) {
        s += ':';
        s += std::to_string(where.column);
      }
    } else {
      s += ": byte ";
      s += std::to_string(where.byte_offset);
    }
    s += ": ";
    s += problem;
    return s;
  }

 private:
  std::string file_;
  InputPosition where_;
};

}  // namespace pgamesh
