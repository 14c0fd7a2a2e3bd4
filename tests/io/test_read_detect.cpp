// Content-based format detection, --format names, and the errors shared by every format: empty
// files, whitespace-only files, unrecognised content.
#include <gtest/gtest.h>

#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

MeshFormat detect(std::string_view s) {
  return detect_format({s.data(), s.size()});
}

TEST(DetectFormat, TextFormatsByTheirFirstStatement) {
  EXPECT_EQ(detect("solid x\nfacet normal 0 0 0\n"), MeshFormat::stl_ascii);
  EXPECT_EQ(detect("  \n\xEF\xBB\xBFSOLID\n"), MeshFormat::unknown);  // BOM only at the start
  EXPECT_EQ(detect("\xEF\xBB\xBFsolid x\n"), MeshFormat::stl_ascii);
  EXPECT_EQ(detect("# made by hand\n\nv 0 0 0\n"), MeshFormat::obj);
  EXPECT_EQ(detect("mtllib x.mtl\n"), MeshFormat::obj);
  EXPECT_EQ(detect("o thing\n"), MeshFormat::obj);
  EXPECT_EQ(detect("ply\nformat ascii 1.0\n"), MeshFormat::ply_ascii);
  EXPECT_EQ(detect("ply\r\nformat binary_little_endian 1.0\r\n"), MeshFormat::ply_binary_le);
  EXPECT_EQ(detect("ply\nformat binary_big_endian 1.0\n"), MeshFormat::ply_binary_be);
  EXPECT_EQ(detect("OFF\n"), MeshFormat::off);
  EXPECT_EQ(detect("# c\nSTCNOFF\n"), MeshFormat::off);
  EXPECT_EQ(detect("hello world\n"), MeshFormat::unknown);
  EXPECT_EQ(detect(""), MeshFormat::unknown);
}

TEST(DetectFormat, BinaryBySizeArithmeticNotByTheFirstWord) {
  EXPECT_EQ(detect(test::binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}, 1, "solid x")),
            MeshFormat::stl_binary);
  EXPECT_EQ(detect(test::binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}, 1, "v 0 0 0")),
            MeshFormat::stl_binary);
  // Not matching the size and holding binary bytes: still STL, so its reader explains why.
  EXPECT_EQ(detect(test::binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}, 7, "x")),
            MeshFormat::stl_binary);
}

TEST(DetectFormat, FormatNamesForTheFormatOption) {
  EXPECT_EQ(format_from_name("STL"), MeshFormat::stl_binary);
  EXPECT_EQ(format_from_name("stl-ascii"), MeshFormat::stl_ascii);
  EXPECT_EQ(format_from_name("obj"), MeshFormat::obj);
  EXPECT_EQ(format_from_name("ply"), MeshFormat::ply_ascii);
  EXPECT_EQ(format_from_name("ply-le"), MeshFormat::ply_binary_le);
  EXPECT_EQ(format_from_name("ply-binary-big-endian"), MeshFormat::ply_binary_be);
  EXPECT_EQ(format_from_name("off"), MeshFormat::off);
  EXPECT_EQ(format_from_name("auto"), MeshFormat::unknown);
  EXPECT_EQ(format_from_name("3ds"), MeshFormat::unknown);
  // Every printed name reads back to its format.
  for (MeshFormat f :
       {MeshFormat::stl_ascii, MeshFormat::stl_binary, MeshFormat::obj, MeshFormat::ply_ascii,
        MeshFormat::ply_binary_le, MeshFormat::ply_binary_be, MeshFormat::off})
    EXPECT_EQ(format_from_name(format_name(f)), f) << format_name(f);
}

TEST(ReadMesh, EmptyAndBlankFilesAreErrors) {
  EXPECT_BYTE_ERROR(test::read_error(""), 0u, "empty file");
  EXPECT_BYTE_ERROR(test::read_error(" \n\t\r\n"), 0u, "empty file");
  EXPECT_BYTE_ERROR(test::read_error("", MeshFormat::obj), 0u, "empty file");
}

TEST(ReadMesh, UnrecognisedTextIsAnError) {
  EXPECT_TEXT_ERROR(test::read_error("hello world\n"), 1u, 1u, "unrecognised mesh format");
}

TEST(ReadMesh, ShortBinaryGarbageIsATruncatedStl) {
  EXPECT_BYTE_ERROR(test::read_error(std::string("\x00\x01\x02", 3)), 3u,
                    "shorter than the 84-byte header");
}

TEST(ReadMesh, MissingFileNamesThePath) {
  try {
    read_mesh("/nonexistent/part.stl");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/part.stl");
  }
}

TEST(ReadMesh, SourceIsResetAndFilled) {
  MeshSource src;
  src.warnings.push_back("stale");
  src.groups = 9;
  test::read_text("g a\nv 0 0 0\n", &src);
  EXPECT_EQ(src.path, "mem");
  EXPECT_EQ(src.format, MeshFormat::obj);
  EXPECT_EQ(src.groups, 1u);
  EXPECT_TRUE(src.warnings.empty());
}

}  // namespace
}  // namespace pgamesh
