// PLY reader: ASCII, binary little- and big-endian, any vertex property layout and type, face
// lists of any integer count/index type, skipped elements, and every bad-input case with its
// line:column (ASCII) or byte offset (binary). Binary files are built byte by byte here.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "pgamesh/io/read_mesh.hpp"
#include "support/byte_order.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

using test::put;
using test::read_error;
using test::read_text;

// A square pyramid: 5 vertices, a quad base and 4 triangles (outward).
const Vec3d kApex{0.5, 0.5, 1.25};
const std::vector<Vec3d> kPyramid = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, kApex};
const std::vector<std::vector<int>> kPyramidFaces = {
    {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

void expect_pyramid(const Mesh& m) {
  ASSERT_EQ(m.vertices.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(m.vertices[i], kPyramid[i]) << i;
  ASSERT_EQ(m.face_count(), 5u);
  for (std::size_t f = 0; f < 5; ++f) {
    ASSERT_EQ(m.face_size(f), kPyramidFaces[f].size());
    for (std::size_t k = 0; k < m.face_size(f); ++k)
      EXPECT_EQ(m.face(f)[k], static_cast<std::uint32_t>(kPyramidFaces[f][k]));
  }
  EXPECT_DOUBLE_EQ(test::six_volume(m), 6 * 1.25 / 3);  // base 1 × height 1.25 / 3
}

// Vertex properties: z first, then a uchar colour, y, a list (skipped), x, all doubles; faces with
// a flag before and a colour after the int16-counted uint16 index list; an edge element after.
std::string binary_pyramid(bool big) {
  std::string h =
      std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\ncomment test\nelement vertex 5\nproperty double z\nproperty uchar red\n"
      "property float64 y\nproperty list uint8 float junk\nproperty double x\n"
      "element face 5\nproperty int flags\nproperty list short ushort vertex_indices\n"
      "property uchar red\nelement edge 1\nproperty int a\nproperty int b\nend_header\n";
  for (const Vec3d& v : kPyramid) {
    put<double>(h, v.z, big);
    put<std::uint8_t>(h, 7, big);
    put<double>(h, v.y, big);
    put<std::uint8_t>(h, 2, big);
    put<float>(h, 1.5f, big);
    put<float>(h, 2.5f, big);
    put<double>(h, v.x, big);
  }
  for (const auto& f : kPyramidFaces) {
    put<std::int32_t>(h, -1, big);
    put<std::int16_t>(h, static_cast<std::int16_t>(f.size()), big);
    for (int i : f) put<std::uint16_t>(h, static_cast<std::uint16_t>(i), big);
    put<std::uint8_t>(h, 200, big);
  }
  put<std::int32_t>(h, 0, big);
  put<std::int32_t>(h, 1, big);
  return h;
}

const char* const kAsciiPyramid =
    "ply\r\nformat ascii 1.0\r\ncomment caf\xE9 made by hand\r\nobj_info none\r\n"
    "element vertex 5\r\nproperty float nx\r\nproperty double x\r\nproperty double y\r\n"
    "property double z\r\nelement face 5\r\nproperty list uchar int vertex_index\r\n"
    "property list int float texcoord\r\nend_header\r\n"
    "0 0 0 0\r\n1 1 0 0\r\n2 1 1 0\r\n3 0 1 0\r\n4 0.5 0.5\r\n 1.25\r\n"  // values may wrap
    "4 0 3 2 1 0\r\n3 0 1 4 2 0.5 0.5\r\n3 1 2 4 0\r\n3 2 3 4 0\r\n3 3 0 4 0\r\n";

TEST(ReadPly, AsciiWithExtraPropertiesAndWrappedValues) {
  MeshSource src;
  const Mesh m = read_text(kAsciiPyramid, &src);
  EXPECT_EQ(src.format, MeshFormat::ply_ascii);
  EXPECT_FALSE(src.single_precision);
  expect_pyramid(m);
}

TEST(ReadPly, BinaryLittleEndianAnyLayout) {
  MeshSource src;
  const std::string b = binary_pyramid(false);
  expect_pyramid(read_text(b, &src));
  EXPECT_EQ(src.format, MeshFormat::ply_binary_le);
  ASSERT_EQ(src.warnings.size(), 1u);  // the edge element
  EXPECT_NE(src.warnings[0].find("'edge'"), std::string::npos);
}

TEST(ReadPly, BinaryBigEndianAnyLayout) {
  MeshSource src;
  expect_pyramid(read_text(binary_pyramid(true), &src));
  EXPECT_EQ(src.format, MeshFormat::ply_binary_be);
}

TEST(ReadPly, FloatCoordinatesAreMarkedSinglePrecision) {
  std::string b =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  for (float f : {0.1f, 2.0f, -3.5f}) put<float>(b, f, false);
  MeshSource src;
  const Mesh m = read_text(b, &src);
  EXPECT_TRUE(src.single_precision);
  EXPECT_EQ(m.vertices[0], (Vec3d{double(0.1f), 2.0, -3.5}));
  EXPECT_EQ(m.face_count(), 0u);
}

const std::string kTriHeader =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n";

std::string binary_triangle(std::uint8_t n, std::vector<std::int32_t> idx, float y1 = 0) {
  std::string b = kTriHeader;
  for (float f : {0.f, 0.f, 0.f, 1.f, y1, 0.f, 0.f, 1.f, 0.f}) put<float>(b, f, false);
  put<std::uint8_t>(b, n, false);
  for (std::int32_t i : idx) put<std::int32_t>(b, i, false);
  return b;
}

TEST(ReadPly, BinaryTriangleReadsAndItsFacesAreChecked) {
  const std::size_t data = kTriHeader.size();
  EXPECT_EQ(read_text(binary_triangle(3, {0, 1, 2})).face_count(), 1u);
  EXPECT_BYTE_ERROR(read_error(binary_triangle(2, {0, 1})), data + 36, "face 0 with 2 vertices");
  EXPECT_BYTE_ERROR(read_error(binary_triangle(3, {0, 3, 2})), data + 36 + 1 + 4,
                    "vertex index 3 of face 0 is out of range (3 vertices)");
  EXPECT_BYTE_ERROR(read_error(binary_triangle(3, {0, 1, -1})), data + 36 + 1 + 8,
                    "vertex index -1");
  EXPECT_BYTE_ERROR(read_error(binary_triangle(3, {0, 1})), data + 36,
                    "list length 3 in face 0 runs past the end");
  EXPECT_BYTE_ERROR(
      read_error(binary_triangle(3, {0, 1, 2}, std::numeric_limits<float>::quiet_NaN())),
      data + 12 + 4, "non-finite coordinate (NaN or infinity) in vertex 1");
}

TEST(ReadPly, TruncatedVertexDataNamesBothSizes) {
  std::string b = binary_triangle(3, {0, 1, 2});
  b.resize(kTriHeader.size() + 30);
  EXPECT_BYTE_ERROR(read_error(b), kTriHeader.size(),
                    "3 vertices of 12 bytes need 36 bytes, 30 left");
}

TEST(ReadPly, HugeDeclaredCountsAreRejectedBeforeAllocation) {
  // 4 billion vertices of 12 bytes and 10^18 faces declared in a file of a few hundred bytes.
  std::string b = kTriHeader;
  b.replace(b.find("vertex 3"), 8, "vertex 4000000000");
  for (int i = 0; i < 9; ++i) put<float>(b, 0, false);
  EXPECT_BYTE_ERROR(read_error(b), b.size() - 36, "4000000000 vertices of 12 bytes");
  std::string f = binary_triangle(3, {0, 1, 2});
  f.replace(f.find("face 1"), 6, "face 1000000000000000000");
  EXPECT_BYTE_ERROR(read_error(f), f.size(), "truncated PLY data: face 1 needs 1 bytes, 0 left");
  EXPECT_TEXT_ERROR(
      read_error("ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\n"
                 "property float y\nproperty float z\nend_header\n0 0 0\n"),
      3u, 1u, "vertex count exceeds the 32-bit indices");
  const auto e = read_error(
      "ply\nformat ascii 1.0\nelement vertex 3000000000\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n");
  EXPECT_TEXT_ERROR(e, 9u, 1u, "unexpected end of file in vertex 1");
}

TEST(ReadPly, HugeListLengthIsRejected) {
  std::string b =
      "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  const std::size_t data = b.size();
  put<std::int32_t>(b, 2000000000, true);
  EXPECT_BYTE_ERROR(read_error(b), data, "list length 2000000000 in face 0 runs past the end");
  b.resize(data);
  put<std::int32_t>(b, -5, true);
  EXPECT_BYTE_ERROR(read_error(b), data, "negative list length -5");
}

TEST(ReadPly, ElementWithoutPropertiesAndAHugeCountHoldsNoData) {
  const Mesh m = read_text(
      "ply\nformat binary_little_endian 1.0\nelement nothing 9000000000000000000\nend_header\n");
  EXPECT_EQ(m.face_count(), 0u);
}

TEST(ReadPly, AsciiErrorsHaveLineAndColumn) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(read_text(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").face_count(), 1u);
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"), 11u, 3u,
                    "non-finite coordinate 'nan'");
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), 13u, 7u,
                    "vertex index 3 of face 0 is out of range (3 vertices)");
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), 13u, 1u,
                    "face 0 with 2 vertices");
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n"), 14u, 1u,
                    "after the last declared element");
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 0 0\n0 \xB5 0\n3 0 1 2\n"), 12u, 3u, "byte 0xB5");
  EXPECT_TEXT_ERROR(read_error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1"), 13u, 6u,
                    "unexpected end of file: expected a vertex index");
}

TEST(ReadPly, HeaderErrors) {
  // Found by fuzzing: a format line cut at the end of the file once read one byte past it.
  EXPECT_TEXT_ERROR(read_error("ply\nformat"), 2u, 7u, "unknown PLY encoding, found end of file");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement vertex 0\n"), 4u, 1u,
                    "without 'end_header'");
  EXPECT_TEXT_ERROR(read_error("ply\nformat binary_middle_endian 1.0\nend_header\n"), 2u, 8u,
                    "unknown PLY encoding, found 'binary_middle_endian'");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                               "property float y\nend_header\n0 0\n"),
                    3u, 1u, "vertex element without a 'z' property");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 0\n"
                               "property list uchar float vertex_indices\nend_header\n"),
                    7u, 1u, "'vertex_indices' must be a list of an integer type");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement face 0\n"
                               "property list float int vertex_indices\nend_header\n"),
                    4u, 15u, "list count type must be an integer type");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n"), 4u,
                    10u, "unknown property type 'quad'");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nelement vertex -1\n"), 3u, 16u,
                    "negative element count");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nbogus\nend_header\n"), 3u, 1u,
                    "unknown PLY header line 'bogus'");
  EXPECT_TEXT_ERROR(read_error("ply\nend_header\n"), 1u, 1u, "without a 'format' line");
  EXPECT_TEXT_ERROR(read_error("ply\nformat ascii 1.0\nproperty float x\n"), 3u, 1u,
                    "property before any element");
}

}  // namespace
}  // namespace pgamesh
