// OFF reader: header variants, comments, colours, n-gons, and every bad-input case with its
// line:column.
#include <gtest/gtest.h>

#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

using test::read_error;
using test::read_text;

TEST(ReadOff, PolygonsCommentsAndColours) {
  MeshSource src;
  const Mesh m = read_text(
      "# a comment first\nCOFF\n# counts\n5 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n2 1 0\n"
      "1 2 0 0.5 0.5 0.5 1\n0 1 0\n\n5 0 1 2 3 4 255 0 0\n3 0 1 3 # trailing comment\n",
      &src);
  EXPECT_EQ(src.format, MeshFormat::off);
  ASSERT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(m.vertices[2], (Vec3d{2, 1, 0}));
  ASSERT_EQ(m.face_count(), 2u);
  EXPECT_EQ(m.face_size(0), 5u);
  EXPECT_EQ(m.face(0)[4], 4u);
  EXPECT_EQ(m.face(1)[2], 3u);
  EXPECT_TRUE(src.warnings.empty());
}

TEST(ReadOff, CountsOnTheKeywordLineAndNoEdgeCount) {
  const Mesh m = read_text("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(m.face_count(), 1u);
  EXPECT_EQ(read_text("NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n").face_count(),
            1u);
}

TEST(ReadOff, DataAfterTheDeclaredFacesIsAWarning) {
  MeshSource src;
  read_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", &src);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("mem:7: data after the declared 1 faces"), std::string::npos)
      << src.warnings[0];
}

TEST(ReadOff, BadFacesAreErrorsAtTheirPosition) {
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_TEXT_ERROR(read_error(head + "  2 0 1\n"), 6u, 3u, "face with 2 vertices");
  EXPECT_TEXT_ERROR(read_error(head + "3 0 1 3\n"), 6u, 7u,
                    "vertex index 3 is out of range (3 vertices)");
  EXPECT_TEXT_ERROR(read_error(head + "3 0 -1 2\n"), 6u, 5u, "vertex index -1 is out of range");
  EXPECT_TEXT_ERROR(read_error(head + "4 0 1 2\n"), 6u, 8u, "face line ends after 3 of its 4");
  EXPECT_TEXT_ERROR(read_error(head), 6u, 1u, "unexpected end of file: 0 of 1 faces read");
  EXPECT_TEXT_ERROR(read_error(head + "99999999999999999999 0 1 2\n"), 6u, 1u, "out of range");
}

TEST(ReadOff, BadVerticesAreErrors) {
  EXPECT_TEXT_ERROR(read_error("OFF\n3 0 0\n0 0 0\n1 inf 0\n0 1 0\n"), 4u, 3u,
                    "non-finite y coordinate 'inf'");
  EXPECT_TEXT_ERROR(read_error("OFF\n3 0 0\n0 0 0\n1 0\n0 1 0\n"), 4u, 4u,
                    "expected z coordinate, found end of line");
  EXPECT_TEXT_ERROR(read_error("OFF\n3 0 0\n0 0 0\n"), 4u, 1u, "1 of 3 vertices read");
  EXPECT_TEXT_ERROR(read_error("OFF\n1 0 0\n\xFF 0 0\n"), 3u, 1u, "byte 0xFF");
}

TEST(ReadOff, HugeDeclaredCountsFailAtTheEndOfTheData) {
  EXPECT_TEXT_ERROR(read_error("OFF\n5000000000 1 0\n0 0 0\n"), 2u, 1u,
                    "vertex count 5000000000 exceeds the 32-bit indices");
  EXPECT_TEXT_ERROR(read_error("OFF\n3000000000 1 0\n0 0 0\n"), 4u, 1u,
                    "1 of 3000000000 vertices read");
  EXPECT_TEXT_ERROR(read_error("OFF\n3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), 7u, 1u,
                    "1 of 1000000000000 faces read");
}

TEST(ReadOff, HeaderErrors) {
  EXPECT_TEXT_ERROR(read_error("4OFF\n1 0 0\n0 0 0 0\n"), 1u, 1u, "only 3-D OFF");
  EXPECT_TEXT_ERROR(read_error("OFF BINARY\n"), 1u, 5u, "binary OFF is not supported");
  EXPECT_TEXT_ERROR(read_error("OFF\n-3 1 0\n"), 2u, 1u, "negative vertex count");
  EXPECT_TEXT_ERROR(read_error("OFF\n3 x 0\n"), 2u, 3u, "expected face count, found 'x'");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\n", MeshFormat::off), 1u, 1u,
                    "expected an OFF header keyword, found 'v'");
}

}  // namespace
}  // namespace pgamesh
