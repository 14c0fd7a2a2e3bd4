// A whole file's bytes, for tests that compare what a program wrote or read a mesh as given.
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace pgamesh::test {

// The bytes of the file at `path` (binary), or an empty string when it cannot be opened.
inline std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace pgamesh::test
