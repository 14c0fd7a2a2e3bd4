#include "support/temp_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace pgamesh::test {

namespace {

// `pgamesh_<suite>_<test>_<pid>_<n><suffix>` in the temporary folder. Parameterised tests have
// '/' in their names ("Prefix/Suite", "Case/0"): replaced, the name stays one file in the folder.
std::string unique_temp_path(std::string_view suffix) {
  static std::atomic<unsigned> made{0};
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string leaf = std::string("pgamesh_") + (test ? test->test_suite_name() : "") + "_" +
                     (test ? test->name() : "") + "_" + std::to_string(::getpid()) + "_" +
                     std::to_string(made++);
  leaf += suffix;
  std::replace(leaf.begin(), leaf.end(), '/', '_');
  return (std::filesystem::temp_directory_path() / leaf).string();
}

// Removes `path` if something is there, without throwing.
void remove_quietly(const std::string& path) noexcept {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

}  // namespace

TempFile::TempFile(std::string_view suffix) : path_(unique_temp_path(suffix)) {
  remove_quietly(path_);
}

TempFile::TempFile(std::string_view suffix, std::string_view bytes)
    : path_(unique_temp_path(suffix)) {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    remove_quietly(path_);  // the destructor of an object never made does not run
    throw std::runtime_error("cannot write the temporary file " + path_);
  }
}

TempFile::~TempFile() {
  remove_quietly(path_);
}

}  // namespace pgamesh::test
