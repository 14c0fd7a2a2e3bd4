#include "text_append.hpp"

#include <cstdarg>
#include <cstdio>

namespace pgamesh::cli {

void append(std::string& out, const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0) {
    const std::size_t at = out.size();
    out.resize(at + static_cast<std::size_t>(n) + 1);
    std::vsnprintf(out.data() + at, static_cast<std::size_t>(n) + 1, format, again);
    out.resize(at + static_cast<std::size_t>(n));  // drop vsnprintf's terminating NUL
  }
  va_end(again);
}

}  // namespace pgamesh::cli
