// A file in the temporary folder that lives exactly as long as the object naming it, so that a test
// leaves nothing behind however it ends (a failing ASSERT_* returns from the test early).
#pragma once

#include <string>
#include <string_view>

namespace pgamesh::test {

// A path in the temporary folder unique to the running test, process and object, removed (with
// whatever a program wrote there) when the object goes out of scope.
//
// The name is `pgamesh_<suite>_<test>_<pid>_<n><suffix>`: ctest runs the cases of a test file in
// parallel processes, so names carry the test and the process id; `n` counts the objects made in
// this process, so two of one test with the same suffix differ too. Hold a TempFile before running
// anything that writes to its path (a CLI's --output), so that the output is removed as well.
class TempFile {
 public:
  // Only a path: nothing is there (a file left at it by an earlier process with the same id is
  // removed), for code under test to create.
  explicit TempFile(std::string_view suffix);
  // A file holding exactly `bytes` (binary); throws std::runtime_error when it cannot be written.
  TempFile(std::string_view suffix, std::string_view bytes);
  // Removes the file, if any; never throws (a failed removal is ignored).
  ~TempFile();

  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  // The file's absolute path.
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace pgamesh::test
