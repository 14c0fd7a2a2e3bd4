// OBJ reader: polygons of any size (concave too), index forms, negative and forward indices,
// optional w/colour, counted groups, and every bad-input case with its line:column.
#include <gtest/gtest.h>

#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

using test::read_error;
using test::read_text;

TEST(ReadObj, TrianglesQuadsAndConcaveNgonsStayPolygons) {
  // An L-shaped (concave) hexagon, a quad and a triangle.
  MeshSource src;
  const Mesh m = read_text(
      "# comment\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
      "f 1 2 3 4 5 6\nf 1 2 3 4\nf 1 2 3\n",
      &src);
  EXPECT_EQ(src.format, MeshFormat::obj);
  EXPECT_FALSE(src.single_precision);
  ASSERT_EQ(m.face_count(), 3u);
  EXPECT_EQ(m.face_size(0), 6u);
  EXPECT_EQ(m.face_size(1), 4u);
  EXPECT_EQ(m.face_size(2), 3u);
  EXPECT_EQ(m.face(0)[5], 5u);
  EXPECT_EQ(m.vertices[4], (Vec3d{1, 2, 0}));
}

TEST(ReadObj, IndexFormsWithTextureAndNormalReferences) {
  const Mesh m = read_text(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
      "f 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\n");
  ASSERT_EQ(m.face_count(), 3u);
  for (std::size_t f = 0; f < 3; ++f)
    for (std::uint32_t k = 0; k < 3; ++k) EXPECT_EQ(m.face(f)[k], k);
}

TEST(ReadObj, NegativeIndicesCountBackFromTheLatestVertex) {
  const Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\nf -4 -1 -2\n");
  ASSERT_EQ(m.face_count(), 2u);
  EXPECT_EQ(m.face(0)[0], 0u);
  EXPECT_EQ(m.face(0)[2], 2u);
  EXPECT_EQ(m.face(1)[0], 0u);
  EXPECT_EQ(m.face(1)[1], 3u);
  EXPECT_EQ(m.face(1)[2], 2u);
}

TEST(ReadObj, ForwardReferencesResolveAgainstTheFinalVertexCount) {
  const Mesh m = read_text("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(m.face_count(), 1u);
}

TEST(ReadObj, WeightAndColourAreReadAndIgnored) {
  const Mesh m = read_text("v 1 2 3 1.0\nv 4 5 6 0.5 0.25 0.125\nv 7 8 9 1 0.5 0.25 0.125\n");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[1], (Vec3d{4, 5, 6}));
  EXPECT_EQ(m.vertices[2], (Vec3d{7, 8, 9}));
  EXPECT_TEXT_ERROR(read_error("v 1 2 3 4 5 6 7 8\n"), 1u, 17u, "too many values");
}

TEST(ReadObj, GroupsAndObjectsAreCountedOtherStatementsSkipped) {
  MeshSource src;
  const Mesh m = read_text(
      "mtllib a.mtl\no body\ng left\nusemtl red\ns 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\ng\n"
      "s off\nf 1 2 3\n",
      &src);
  EXPECT_EQ(m.face_count(), 1u);
  EXPECT_EQ(src.groups, 3u);
  EXPECT_TRUE(src.warnings.empty());
}

TEST(ReadObj, LinesPointsAndCurvesAreSkippedWithOneWarning) {
  MeshSource src;
  const Mesh m = read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 3\ncstype bezier\nf 1 2 3\n", &src);
  EXPECT_EQ(m.face_count(), 1u);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("mem:4: 3 statement(s)"), std::string::npos) << src.warnings[0];
}

TEST(ReadObj, CrlfAndTabsAndMissingFinalNewline) {
  const Mesh m = read_text("v\t0 0 0\r\nv 1\t0 0\r\nv 0 1 0\r\nf 1 2 3");
  EXPECT_EQ(m.face_count(), 1u);
  EXPECT_EQ(m.vertices[1], (Vec3d{1, 0, 0}));
}

TEST(ReadObj, IndexZeroIsAnError) {
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 3\n"), 4u, 5u, "vertex index 0");
}

TEST(ReadObj, OutOfRangeIndexIsAnErrorAtItsPosition) {
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\nf 1 9 2\n"), 6u, 5u,
                    "vertex index 9 is out of range (the file has 3 vertices)");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n"), 4u, 7u,
                    "relative vertex index -4 reaches before the first vertex (3 vertices so far)");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nf 1 1 99999999999999999999\n"), 2u, 7u,
                    "vertex index '99999999999999999999' is out of range");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nf 1 1 -9223372036854775808\n"), 2u, 7u,
                    "reaches before the first vertex");
}

TEST(ReadObj, FacesWithFewerThanThreeVerticesAreErrors) {
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nv 1 0 0\n  f 1 2\n"), 3u, 3u, "face with 2 vertices");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nf\n"), 2u, 1u, "face with 0 vertices");
}

TEST(ReadObj, NanInfinityAndBadNumbersAreErrors) {
  EXPECT_TEXT_ERROR(read_error("v 0 NaN 0\n"), 1u, 5u, "non-finite y coordinate 'NaN'");
  EXPECT_TEXT_ERROR(read_error("v 0 0 infinity\n"), 1u, 7u, "non-finite z coordinate");
  EXPECT_TEXT_ERROR(read_error("v 0 0\n"), 1u, 6u, "expected z coordinate, found end of line");
  EXPECT_TEXT_ERROR(read_error("v 0 0x1 0\n"), 1u, 5u, "malformed y coordinate '0x1'");
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nf 1 2a 3\n"), 2u, 5u, "malformed vertex index '2a'");
}

TEST(ReadObj, NonUtf8BytesAreFineInCommentsAndNamesButNotInNumbers) {
  MeshSource src;
  const Mesh m = read_text("# caf\xE9\ng gr\xFC\xDF\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", &src);
  EXPECT_EQ(m.face_count(), 1u);
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nv 1 \xC3\xA9 0\n"), 2u, 5u, "byte 0xC3");
}

TEST(ReadObj, UnknownStatementIsAnError) {
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\nvertex 1 2 3\n", MeshFormat::obj), 2u, 1u,
                    "unknown OBJ statement 'vertex'");
}

TEST(ReadObj, AVertexWithoutFacesIsAnEmptyMeshWithVertices) {
  const Mesh m = read_text("v 1 2 3\n");
  EXPECT_EQ(m.face_count(), 0u);
  EXPECT_EQ(m.vertices.size(), 1u);
}

}  // namespace
}  // namespace pgamesh
