// STL readers: ASCII and binary, detection by size arithmetic, every bad-input case with its exact
// position, STL files of our own, and the real files of ../shared/meshes/stl-models (extras).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/stl_binary.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "support/nested_shells.hpp"
#include "support/read_helpers.hpp"
#include "support/stl_bytes.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::binary_stl;
using test::read_error;
using test::read_text;

const char* const kTetra =
    "solid t\n"
    " facet normal 0 0 0\n"
    "  outer loop\n"
    "   vertex 0 0 0\n"
    "   vertex 0 1 0\n"
    "   vertex 1 0 0\n"
    "  endloop\n"
    " endfacet\n"
    " facet normal nan nan nan\n"  // normals are never read
    "  outer loop\n"
    "   vertex 0 0 0\n"
    "   vertex 0 0 1\n"
    "   vertex 0 1 0\n"
    "  endloop\n"
    " endfacet\n"
    " facet normal 0 0 0\n"
    "  outer loop\n"
    "   vertex 0 0 0\n"
    "   vertex 1 0 0\n"
    "   vertex 0 0 1\n"
    "  endloop\n"
    " endfacet\n"
    " facet normal 0 0 0\n"
    "  outer loop\n"
    "   vertex 1 0 0\n"
    "   vertex 0 1 0\n"
    "   vertex 0 0 1\n"
    "  endloop\n"
    " endfacet\n"
    "endsolid t\n";

TEST(ReadStlAscii, TetrahedronKeepsThreeFreshVerticesPerFacet) {
  MeshSource src;
  const Mesh m = read_text(kTetra, &src);
  EXPECT_EQ(src.format, MeshFormat::stl_ascii);
  EXPECT_FALSE(src.single_precision);
  EXPECT_TRUE(src.warnings.empty());
  ASSERT_EQ(m.face_count(), 4u);
  ASSERT_EQ(m.vertices.size(), 12u);
  for (std::uint32_t i = 0; i < 12; ++i) EXPECT_EQ(m.corners[i], i);
  EXPECT_EQ(m.vertices[4], (Vec3d{0, 0, 1}));
  EXPECT_EQ(m.vertices[11], (Vec3d{0, 0, 1}));
  EXPECT_DOUBLE_EQ(test::six_volume(m), 1.0);  // outward unit corner tetrahedron: 6 V = 1
}

TEST(ReadStlAscii, KeywordsAnyCaseCrlfAndSeveralSolids) {
  const std::string text =
      "SOLID a\r\nFACET NORMAL 0 0 1\r\nOUTER LOOP\r\nVERTEX 1.5e0 -2 +3\r\nVERTEX 4 5 6\r\n"
      "VERTEX 7 8 9.25\r\nENDLOOP\r\nENDFACET\r\nENDSOLID a\r\n"
      "solid b\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid b";
  const Mesh m = read_text(text);
  ASSERT_EQ(m.face_count(), 2u);
  EXPECT_EQ(m.vertices[0], (Vec3d{1.5, -2, 3}));
  EXPECT_EQ(m.vertices[2], (Vec3d{7, 8, 9.25}));
  EXPECT_EQ(m.vertices[4], (Vec3d{1, 0, 0}));
}

TEST(ReadStlAscii, DecimalDigitsAreParsedToTheNearestDouble) {
  const Mesh m = read_text(
      "solid\nfacet normal 0 0 0\nouter loop\nvertex 0.1 1e-310 -2.5e+300\n"
      "vertex 0.30000000000000004 3 4\nvertex 1 2 3\nendloop\nendfacet\nendsolid\n");
  EXPECT_EQ(m.vertices[0].x, 0.1);
  EXPECT_EQ(m.vertices[0].y, 1e-310);  // subnormal
  EXPECT_EQ(m.vertices[0].z, -2.5e300);
  EXPECT_EQ(m.vertices[1].x, 0.1 + 0.2);
}

TEST(ReadStlAscii, NonUtf8BytesInTheNameAreIgnored) {
  const Mesh m = read_text(
      "solid caf\xE9 \xFF\xFE\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid caf\xE9\n");
  EXPECT_EQ(m.face_count(), 1u);
}

TEST(ReadStlAscii, NonUtf8ByteInACoordinateIsAnErrorAtItsColumn) {
  const auto e = read_error(
      "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 \xE9 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nendsolid\n");
  EXPECT_TEXT_ERROR(e, 4u, 10u, "byte 0xE9");
}

TEST(ReadStlAscii, QuadFacetIsKeptAsAPolygonWithAWarning) {
  MeshSource src;
  const Mesh m = read_text(
      "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid q\n",
      &src);
  ASSERT_EQ(m.face_count(), 1u);
  EXPECT_EQ(m.face_size(0), 4u);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("mem:2:"), std::string::npos) << src.warnings[0];
}

TEST(ReadStlAscii, FacetWithTwoVerticesIsAnErrorAtTheFacet) {
  const auto e = read_error(
      "solid x\n  facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n"
      "endsolid\n");
  EXPECT_TEXT_ERROR(e, 2u, 3u, "facet with 2 vertices");
}

TEST(ReadStlAscii, NanAndInfinityCoordinatesAreErrorsAtTheNumber) {
  const std::string head = "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 ";
  const std::string tail = " 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n";
  EXPECT_TEXT_ERROR(read_error(head + "nan" + tail), 5u, 10u, "non-finite y coordinate 'nan'");
  EXPECT_TEXT_ERROR(read_error(head + "-inf" + tail), 5u, 10u, "non-finite");
  EXPECT_TEXT_ERROR(read_error(head + "1e999" + tail), 5u, 10u, "out of the range");
  EXPECT_TEXT_ERROR(read_error(head + "1.5x" + tail), 5u, 10u, "malformed y coordinate '1.5x'");
}

TEST(ReadStlAscii, TruncatedInsideAFacetIsAnErrorAtTheEnd) {
  const std::string text = "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0";
  EXPECT_TEXT_ERROR(read_error(text), 5u, 11u, "expected z coordinate, found end of file");
  EXPECT_TEXT_ERROR(read_error("solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n"), 5u, 1u,
                    "expected 'vertex' or 'endloop', found end of file");
}

TEST(ReadStlAscii, MissingEndsolidIsAWarning) {
  MeshSource src;
  const Mesh m = read_text(
      "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\n",
      &src);
  EXPECT_EQ(m.face_count(), 1u);
  ASSERT_EQ(src.warnings.size(), 1u);
  EXPECT_NE(src.warnings[0].find("endsolid"), std::string::npos);
}

TEST(ReadStlAscii, UnexpectedKeywordNamesWhatWasFound) {
  EXPECT_TEXT_ERROR(read_error("solid x\nfacet normal 0 0 0\ninner loop\n"), 3u, 1u,
                    "expected 'outer', found 'inner'");
  EXPECT_TEXT_ERROR(read_error("solid x\n\n   vertex 1 2 3\n"), 3u, 4u,
                    "expected 'facet' or 'endsolid', found 'vertex'");
  EXPECT_TEXT_ERROR(read_error("solid x\nendsolid x\nfacet"), 3u, 1u, "expected 'solid'");
}

TEST(ReadStlAscii, EmptySolidHasNoFaces) {
  const Mesh m = read_text("solid empty\nendsolid empty\n");
  EXPECT_EQ(m.face_count(), 0u);
  EXPECT_TRUE(m.vertices.empty());
}

// ---- binary
// ---------------------------------------------------------------------------------------

const std::vector<std::array<float, 9>> kTris = {
    {0, 0, 0, 0, 1, 0, 1, 0, 0},
    {0.1f, -2.5f, 3e6f, 1, 2, 3, 4, 5, 6},
};

TEST(ReadStlBinary, RecordsBecomeFloat32ExactDoubles) {
  MeshSource src;
  const std::string b = binary_stl(kTris, 2);
  const Mesh m = read_text(b, &src);
  EXPECT_EQ(src.format, MeshFormat::stl_binary);
  EXPECT_TRUE(src.single_precision);
  ASSERT_EQ(m.face_count(), 2u);
  ASSERT_EQ(m.vertices.size(), 6u);
  EXPECT_EQ(m.vertices[1], (Vec3d{0, 1, 0}));
  EXPECT_EQ(m.vertices[3], (Vec3d{double(0.1f), -2.5, 3e6}));
  EXPECT_EQ(m.vertices[5], (Vec3d{4, 5, 6}));
  EXPECT_EQ(m.face(1)[0], 3u);
}

TEST(ReadStlBinary, HeaderStartingWithSolidIsStillBinary) {
  const std::string b = binary_stl(kTris, 2, "solid looks like ascii");
  EXPECT_EQ(detect_format({b.data(), b.size()}), MeshFormat::stl_binary);
  MeshSource src;
  EXPECT_EQ(read_text(b, &src).face_count(), 2u);
  EXPECT_EQ(src.format, MeshFormat::stl_binary);
}

TEST(ReadStlBinary, ViewAndTriangleGiveTheRecords) {
  const std::string b = binary_stl(kTris, 2);
  const auto view = binary_stl_view({b.data(), b.size()}, "mem");
  ASSERT_TRUE(view);
  EXPECT_EQ(view->count, 2u);
  Vec3d v[3];
  stl_triangle(view->records + 50, v);
  EXPECT_EQ(v[0], (Vec3d{double(0.1f), -2.5, 3e6}));
  EXPECT_EQ(v[2], (Vec3d{4, 5, 6}));
  EXPECT_FALSE(binary_stl_view({kTetra, std::strlen(kTetra)}, "mem"));
  const std::string obj = "v 0 0 0\n";
  EXPECT_FALSE(binary_stl_view({obj.data(), obj.size()}, "mem"));
}

TEST(ReadStlBinary, ZeroTrianglesIsAnEmptyMesh) {
  const std::string b = binary_stl({}, 0);
  EXPECT_EQ(b.size(), 84u);
  EXPECT_EQ(read_text(b).face_count(), 0u);
}

TEST(ReadStlBinary, TruncatedInsideARecordReportsBothNumbers) {
  std::string b = binary_stl(kTris, 2);
  b.resize(b.size() - 7);
  const auto e = read_error(b);
  EXPECT_BYTE_ERROR(e, 80u, "declares 2 triangles (84 + 50 x 2 = 184 bytes)");
  EXPECT_TRUE(test::mentions(e, "file has 177 bytes (1 whole triangles and 43 bytes more)"));
}

TEST(ReadStlBinary, CountDisagreeingWithWholeRecordsIsAnError) {
  EXPECT_BYTE_ERROR(read_error(binary_stl(kTris, 3)), 80u,
                    "declares 3 triangles (84 + 50 x 3 = 234 bytes) but the file has 184 bytes "
                    "(2 whole triangles)");
  EXPECT_BYTE_ERROR(read_error(binary_stl(kTris, 1)), 80u, "declares 1 triangles");
}

TEST(ReadStlBinary, HugeDeclaredCountIsRejectedBeforeAnyAllocation) {
  // 4294967295 triangles would be 214 GB; the 184-byte file proves otherwise.
  EXPECT_BYTE_ERROR(read_error(binary_stl(kTris, 0xFFFFFFFFu)), 80u, "declares 4294967295");
}

TEST(ReadStlBinary, ShorterThanTheHeaderIsTruncated) {
  std::string b = binary_stl({}, 0);
  b.resize(40);
  EXPECT_BYTE_ERROR(read_error(b), 40u, "shorter than the 84-byte header");
}

TEST(ReadStlBinary, NanAndInfinityAreErrorsAtTheirByte) {
  auto tris = kTris;
  tris[1][4] = std::numeric_limits<float>::quiet_NaN();  // triangle 2, vertex 2, y
  EXPECT_BYTE_ERROR(read_error(binary_stl(tris, 2)), 84u + 50 + 12 + 12 + 4,
                    "triangle 2, vertex 2");
  tris = kTris;
  tris[0][8] = -std::numeric_limits<float>::infinity();
  const std::string b = binary_stl(tris, 2);
  EXPECT_BYTE_ERROR(read_error(b), 84u + 12 + 24 + 8, "non-finite");
  const auto view = binary_stl_view({b.data(), b.size()}, "mem");
  ASSERT_TRUE(view);
  EXPECT_THROW(check_binary_stl_finite(*view, "mem"), InputError);
}

TEST(ReadStlBinary, ForcedStlStillDecidesAsciiOrBinaryBySize) {
  const std::string b = binary_stl(kTris, 2, "solid");
  EXPECT_EQ(read_text(b, nullptr, MeshFormat::stl_ascii).face_count(), 2u);
  EXPECT_EQ(read_text(kTetra, nullptr, MeshFormat::stl_binary).face_count(), 4u);
  EXPECT_TEXT_ERROR(read_error("v 0 0 0\n", MeshFormat::stl_binary), 1u, 1u, "expected 'solid'");
}

// ---- the real files of ../shared/meshes ------------------------------------------------------
// Extras: stl-models has no stated licence and OpenSCAD's file is GPL, so neither is bundled; each
// runs only when the file is there. Their properties on input of our own: the quad facet, the
// binary header starting with "solid", the wrong declared count (above), the tetrahedron of volume
// 1 (TopologyOwnMeshes, MassStl), and the two tests just below.

TEST(ReadStlOwn, EmptyFileIsAnError) {
  const test::TempFile file(".stl", "");
  try {
    read_mesh(file.path());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_BYTE_ERROR(e, 0u, "empty file");
  }
}

TEST(ReadStlOwn, TorusAsciiAndBinaryAgreeToSevenDigits) {
  // A torus of our own (radii 2 and 1, 24 × 12 quads fanned to 576 triangles), written as ASCII STL
  // with 7 significant digits and as binary STL.
  const Mesh torus = test::torus_mesh(2, 1, 24, 12, Vec3d{0, 0, 0}, true);
  const std::vector<char> bytes = test::binary_stl_bytes(torus);
  const test::TempFile ascii_file(".stl", test::ascii_stl_text(torus));
  const test::TempFile binary_file(".stl", {bytes.data(), bytes.size()});
  MeshSource sa, sb;
  const Mesh a = read_mesh(ascii_file.path(), &sa);
  const Mesh b = read_mesh(binary_file.path(), &sb);
  EXPECT_EQ(sa.format, MeshFormat::stl_ascii);
  EXPECT_EQ(sb.format, MeshFormat::stl_binary);
  ASSERT_EQ(a.face_count(), 576u);
  ASSERT_EQ(b.face_count(), 576u);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  // 7 significant digits: relative rounding ≤ 5e-7, plus float32's 6e-8.
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(a.vertices[i][k], b.vertices[i][k], 6e-7 * std::abs(b.vertices[i][k]))
          << "vertex " << i << " axis " << k;
}

TEST(ReadStlReal, GearwheelAsciiAndBinaryAgreeToSevenDigits) {
  SHARED_MESH_EXTRA(ascii_path, "stl-models/gearwheel.ascii.stl");
  SHARED_MESH_EXTRA(binary_path, "stl-models/gearwheel.bin.stl");
  MeshSource sa, sb;
  const Mesh a = read_mesh(ascii_path, &sa);
  const Mesh b = read_mesh(binary_path, &sb);
  EXPECT_EQ(sa.format, MeshFormat::stl_ascii);
  EXPECT_EQ(sb.format, MeshFormat::stl_binary);
  ASSERT_EQ(a.face_count(), 2444u);
  ASSERT_EQ(b.face_count(), 2444u);
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  // The ASCII file prints 7 significant digits (%e): relative rounding ≤ 5e-7, plus float32's 6e-8.
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(a.vertices[i][k], b.vertices[i][k], 6e-7 * std::abs(b.vertices[i][k]))
          << "vertex " << i << " axis " << k;
}

TEST(ReadStlReal, WrongHeaderReadsAsBinary) {
  SHARED_MESH_EXTRA(path, "stl-models/wrongHeader.bin.stl");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::stl_binary);
  EXPECT_EQ(m.face_count(), 12u);
  EXPECT_EQ(m.vertices.size(), 36u);
}

TEST(ReadStlReal, TetrahedronIrregularHasVolumeOne) {
  SHARED_MESH_EXTRA(path, "stl-models/tetrahedronIrregular.bin.stl");
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_DOUBLE_EQ(test::six_volume(m) / 6, 1.0);  // vertices (0,0,0) (3,0,0) (0,2,0) (0,0,1)
}

TEST(ReadStlReal, IncorrectFaceCounterIsAnErrorWithBothNumbers) {
  SHARED_MESH_EXTRA(path, "stl-models/incorrectFaceCounter.bin.stl");
  try {
    read_mesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_BYTE_ERROR(e, 80u, "declares 66 triangles");
    EXPECT_TRUE(test::mentions(e, "file has 284 bytes (4 whole triangles)")) << e.what();
    EXPECT_EQ(e.file(), path);
  }
}

TEST(ReadStlReal, QuadAsciiHasThreeTrianglesAndOneQuad) {
  SHARED_MESH_EXTRA(path, "stl-models/quad.ascii.stl");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  ASSERT_EQ(m.face_count(), 4u);
  EXPECT_EQ(m.face_size(0), 4u);
  EXPECT_EQ(m.face_size(1), 3u);
  EXPECT_EQ(m.vertices.size(), 13u);
  EXPECT_EQ(src.warnings.size(), 1u);
}

TEST(ReadStlReal, EmptyFileIsAnError) {
  SHARED_MESH_EXTRA(path, "stl-models/empty.stl");
  try {
    read_mesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_BYTE_ERROR(e, 0u, "empty file");
  }
}

TEST(ReadStlReal, BunnyBinaryAndBackToBackAscii) {
  SHARED_MESH_EXTRA(bunny, "npm/bunny.stl");
  SHARED_MESH_EXTRA(b2b, "openscad-testing-data/issue1580-back-to-back.stl");
  EXPECT_EQ(read_mesh(bunny).face_count(), 3674u);
  EXPECT_EQ(read_mesh(b2b).face_count(), 10u);
}

}  // namespace
}  // namespace pgamesh
