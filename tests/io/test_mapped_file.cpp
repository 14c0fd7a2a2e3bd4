// MappedFile: the bytes of regular files, empty files, errors for missing paths and directories.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>
#include <thread>

#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::TempFile;

TEST(MappedFile, MapsTheBytesOfARegularFile) {
  const std::string content("ab\0cd\xff", 6);
  const TempFile file(".bin", content);
  const std::string& path = file.path();
  MappedFile f = MappedFile::open(path);
  EXPECT_EQ(std::string(f.bytes().data(), f.bytes().size()), content);
  MappedFile g = std::move(f);  // move-only; the mapping travels
  EXPECT_TRUE(f.bytes().empty());
  EXPECT_EQ(std::string(g.bytes().data(), g.bytes().size()), content);
  EXPECT_EQ(g.path(), path);
}

TEST(MappedFile, EmptyFileIsAnEmptySpan) {
  const TempFile empty("_empty", "");
  const std::string& path = empty.path();
  EXPECT_TRUE(MappedFile::open(path).bytes().empty());
}

TEST(MappedFile, MissingFileAndDirectoryAreInputErrors) {
  try {
    MappedFile::open("/nonexistent/pgamesh/x.stl");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/pgamesh/x.stl");
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
  try {
    MappedFile::open(std::filesystem::temp_directory_path().string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

TEST(MappedFile, PipeIsReadIntoMemory) {
  const TempFile fifo("_fifo");  // the path, for mkfifo to make
  const std::string& path = fifo.path();
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::FILE* writer = nullptr;
  std::thread t([&] {
    writer = std::fopen(path.c_str(), "w");
    std::fputs("solid x\nendsolid x\n", writer);
    std::fclose(writer);
  });
  MappedFile f = MappedFile::open(path);
  t.join();
  EXPECT_EQ(std::string(f.bytes().data(), f.bytes().size()), "solid x\nendsolid x\n");
}

}  // namespace
}  // namespace pgamesh
