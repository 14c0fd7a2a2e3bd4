// MappedFile: the bytes of regular files, empty files, errors for missing paths and directories.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "pgamesh/input_error.hpp"
#include "pgamesh/mesh/mapped_file.hpp"

namespace pgamesh {
namespace {

std::string temp_path(const std::string& leaf) {
  return (std::filesystem::temp_directory_path() /
          ("pgamesh_mf_" + std::to_string(::getpid()) + "_" + leaf))
      .string();
}

TEST(MappedFile, MapsTheBytesOfARegularFile) {
  const std::string path = temp_path("a.bin");
  const std::string content("ab\0cd\xff", 6);
  std::ofstream(path, std::ios::binary) << content;
  MappedFile f = MappedFile::open(path);
  EXPECT_EQ(std::string(f.bytes().data(), f.bytes().size()), content);
  MappedFile g = std::move(f);  // move-only; the mapping travels
  EXPECT_TRUE(f.bytes().empty());
  EXPECT_EQ(std::string(g.bytes().data(), g.bytes().size()), content);
  EXPECT_EQ(g.path(), path);
  std::filesystem::remove(path);
}

TEST(MappedFile, EmptyFileIsAnEmptySpan) {
  const std::string path = temp_path("empty");
  std::ofstream(path).close();
  EXPECT_TRUE(MappedFile::open(path).bytes().empty());
  std::filesystem::remove(path);
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
  const std::string path = temp_path("fifo");
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
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace pgamesh
