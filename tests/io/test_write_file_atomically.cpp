// write_file_atomically: the whole new file or the old one, never a truncated one, and nothing
// left beside it when it fails.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "pgamesh/io/write_file.hpp"
#include "support/file_bytes.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

std::size_t files_in(const std::string& folder) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(folder)) ++n;
  return n;
}

TEST(WriteFileAtomically, CreatesThenReplacesLeavingNoTemporary) {
  const TempFile folder("_atomic");
  std::filesystem::create_directory(folder.path());
  const std::string path = folder.path() + "/mesh.obj";
  write_file_atomically(path, "first");
  EXPECT_EQ(file_bytes(path), "first");
  const std::string big(3 << 20, 'x');  // several writes' worth
  write_file_atomically(path, big);
  EXPECT_EQ(file_bytes(path), big);
  write_file_atomically(path, "");
  EXPECT_EQ(file_bytes(path), "");
  EXPECT_EQ(files_in(folder.path()), 1u);
  std::filesystem::remove_all(folder.path());
}

TEST(WriteFileAtomically, FailureNamesThePathAndKeepsWhatWasThere) {
  const TempFile folder("_atomic_fail");
  std::filesystem::create_directory(folder.path());
  const std::string missing = folder.path() + "/no/such/folder/out.obj";
  try {
    write_file_atomically(missing, "bytes");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  // A folder where the file should go: the rename fails, the folder stays, no temporary remains.
  const std::string in_the_way = folder.path() + "/out.obj";
  std::filesystem::create_directory(in_the_way);
  EXPECT_THROW(write_file_atomically(in_the_way, "bytes"), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(in_the_way));
  EXPECT_EQ(files_in(folder.path()), 1u);
  std::filesystem::remove_all(folder.path());
}

}  // namespace
}  // namespace pgamesh::test
