// printf into a string: the commands build their whole output first and print it only when
// nothing failed, so a failing command leaves stdout empty (no half a report, no truncated table).
#pragma once

#include <string>

namespace pgamesh::cli {

// Appends the printf-formatted text to `out`, however long.
void append(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));

}  // namespace pgamesh::cli
