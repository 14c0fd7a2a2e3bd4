// TempFile (tests/support/temp_file.hpp): its name, its bytes, and that the file is gone when the
// object is, whoever wrote it and however the scope was left.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "support/file_bytes.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

TEST(TempFile, HoldsTheGivenBytesUntilItGoesOutOfScope) {
  const std::string bytes("a\0b\r\n\xff", 6);  // binary: a NUL and a CR LF kept as they are
  std::string path;
  {
    const TempFile file(".bin", bytes);
    path = file.path();
    EXPECT_EQ(file_bytes(path), bytes);
    EXPECT_EQ(std::filesystem::file_size(path), 6u);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  {
    const TempFile empty(".empty", "");
    path = empty.path();
    EXPECT_TRUE(std::filesystem::is_regular_file(path));
    EXPECT_EQ(std::filesystem::file_size(path), 0u);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(TempFile, NameCarriesTestProcessAndSuffixAndIsUnique) {
  const TempFile a(".obj"), b(".obj");
  const std::filesystem::path p(a.path());
  EXPECT_TRUE(std::filesystem::equivalent(p.parent_path(), std::filesystem::temp_directory_path()))
      << a.path();
  const std::string leaf = p.filename().string();
  const std::string prefix = "pgamesh_TempFile_NameCarriesTestProcessAndSuffixAndIsUnique_" +
                             std::to_string(::getpid()) + "_";
  EXPECT_EQ(leaf.rfind(prefix, 0), 0u) << leaf;
  EXPECT_EQ(p.extension(), ".obj");
  EXPECT_NE(a.path(), b.path());
}

TEST(TempFile, PathOnlyLeavesNothingThereAndRemovesWhatOthersWrote) {
  std::string path;
  {
    const TempFile out(".out");
    path = out.path();
    EXPECT_FALSE(std::filesystem::exists(path));  // nothing is created
    std::ofstream(path) << "written by the code under test\n";
    ASSERT_TRUE(std::filesystem::exists(path));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  // A path-only object whose file never appeared: the destructor does not throw.
  EXPECT_NO_THROW({ const TempFile never(".never"); });
}

TEST(TempFile, RemovedWhenTheScopeIsLeftByAnException) {
  std::string path;
  try {
    const TempFile file(".txt", "x");
    path = file.path();
    throw std::runtime_error("leaving early");
  } catch (const std::runtime_error&) {
  }
  ASSERT_FALSE(path.empty());
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(TempFile, UnwritableFileThrows) {
  // A name longer than a file name may be (NAME_MAX is 255 on Linux): the file cannot be made.
  EXPECT_THROW(TempFile(std::string(300, 'x'), "bytes"), std::runtime_error);
}

// Parameterised tests have '/' in their suite and test names; the file stays in the folder.
class TempFileParameterised : public ::testing::TestWithParam<int> {};

TEST_P(TempFileParameterised, SlashesInTheTestNameAreReplaced) {
  const TempFile file(".txt", std::to_string(GetParam()));
  const std::filesystem::path p(file.path());
  EXPECT_TRUE(std::filesystem::equivalent(p.parent_path(), std::filesystem::temp_directory_path()))
      << file.path();
  EXPECT_EQ(p.filename().string().rfind(
                "pgamesh_Values_TempFileParameterised_SlashesInTheTestNameAreReplaced_0_", 0),
            0u)
      << file.path();
  EXPECT_EQ(file_bytes(file.path()), "7");
}

INSTANTIATE_TEST_SUITE_P(Values, TempFileParameterised, ::testing::Values(7));

}  // namespace
}  // namespace pgamesh::test
