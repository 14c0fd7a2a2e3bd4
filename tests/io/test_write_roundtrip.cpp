// Writers and readers together: one mesh written in every format reads back to identical
// vertices (bit-exact doubles in text formats and float64 PLY; float32-rounded for binary STL and
// float PLY) and identical faces (STL: the fan of each polygon).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "io/stl_binary.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/read_helpers.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

// Coordinates chosen to break lossy printing: repeating binary fractions, 17-digit values,
// subnormals, huge and tiny magnitudes, negative zero.
Mesh awkward_mesh() {
  Mesh m;
  m.vertices = {{0.1, 1.0 / 3.0, -2.0 / 7.0},
                {1e-300, 4.9406564584124654e-324, -0.0},
                {123456789.12345678, -1e300, 0.30000000000000004},
                {std::nextafter(1.0, 2.0), 6.02214076e23, -1.7976931348623157e308},
                {2.5, -3.75, 1e-5},
                {-0.5, 7.0, 1.0 / 9.0}};
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3, 4});
  m.add_face({5, 4, 3, 2, 1});
  return m;
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Not inlined: GCC 12.2 -O2 vectorises (double)(float)x for neighbouring lanes into x (wrong code).
[[gnu::noinline]] double float_rounded(double x) {
  return static_cast<float>(x);
}

Vec3d to_float(const Vec3d& v) {
  return {float_rounded(v.x), float_rounded(v.y), float_rounded(v.z)};
}

void expect_same_vertices(const std::vector<Vec3d>& got, const std::vector<Vec3d>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(same_bits(got[i][k], want[i][k]))
          << "vertex " << i << " axis " << k << ": " << got[i][k] << " vs " << want[i][k];
}

void expect_same_faces(const Mesh& got, const Mesh& want) {
  EXPECT_EQ(got.corners, want.corners);
  EXPECT_EQ(got.face_offsets, want.face_offsets);
}

// The triangle fan STL holds for `m`, with three fresh vertices per triangle.
Mesh fan(const Mesh& m, bool single) {
  Mesh out;
  for (std::size_t f = 0; f < m.face_count(); ++f)
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      const auto n = static_cast<std::uint32_t>(out.vertices.size());
      for (std::uint32_t c : {m.face(f)[0], m.face(f)[k], m.face(f)[k + 1]})
        out.vertices.push_back(single ? to_float(m.vertices[c]) : m.vertices[c]);
      out.add_face({n, n + 1, n + 2});
    }
  return out;
}

Mesh round_trip(const Mesh& m, MeshFormat f, MeshSource* src, WriteOptions o = {}) {
  const std::string bytes = write_mesh_bytes(m, f, o);
  return read_mesh_bytes({bytes.data(), bytes.size()}, "roundtrip", src);  // detected, not forced
}

class RoundTrip : public ::testing::TestWithParam<MeshFormat> {};

TEST_P(RoundTrip, PolygonFormatsKeepVerticesBitExactAndFaces) {
  const Mesh m = awkward_mesh();
  MeshSource src;
  const Mesh r = round_trip(m, GetParam(), &src);
  EXPECT_EQ(src.format, GetParam());
  EXPECT_TRUE(src.warnings.empty());
  expect_same_vertices(r.vertices, m.vertices);
  expect_same_faces(r, m);
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip,
                         ::testing::Values(MeshFormat::obj, MeshFormat::off, MeshFormat::ply_ascii,
                                           MeshFormat::ply_binary_le, MeshFormat::ply_binary_be));

TEST(RoundTripPly, FloatPropertiesRoundToFloat32) {
  const Mesh m = awkward_mesh();
  for (MeshFormat f :
       {MeshFormat::ply_ascii, MeshFormat::ply_binary_le, MeshFormat::ply_binary_be}) {
    Mesh finite = m;
    finite.vertices[2].y = -1e30;  // float32 range
    finite.vertices[3].y = 6.02214076e23;
    finite.vertices[3].z = -3e38;
    MeshSource src;
    const Mesh r = round_trip(finite, f, &src, WriteOptions{.single_precision = true});
    EXPECT_TRUE(src.single_precision);
    std::vector<Vec3d> want;
    for (const Vec3d& v : finite.vertices) want.push_back(to_float(v));
    expect_same_vertices(r.vertices, want);
    expect_same_faces(r, finite);
  }
}

TEST(RoundTripStl, AsciiIsTheFanWithBitExactDoubles) {
  const Mesh m = awkward_mesh();
  MeshSource src;
  const Mesh r = round_trip(m, MeshFormat::stl_ascii, &src);
  EXPECT_EQ(src.format, MeshFormat::stl_ascii);
  const Mesh want = fan(m, false);
  EXPECT_EQ(r.face_count(), 1u + 2u + 3u);
  expect_same_vertices(r.vertices, want.vertices);
  expect_same_faces(r, want);
}

TEST(RoundTripStl, BinaryIsTheFanRoundedToFloat32) {
  Mesh m = awkward_mesh();
  m.vertices[2].y = -1e30;
  m.vertices[3].z = 3e38;
  MeshSource src;
  const std::string bytes = write_mesh_bytes(m, MeshFormat::stl_binary);
  EXPECT_EQ(bytes.size(), 84u + 50u * 6);
  const Mesh r = read_mesh_bytes({bytes.data(), bytes.size()}, "roundtrip", &src);
  EXPECT_EQ(src.format, MeshFormat::stl_binary);
  const Mesh want = fan(m, true);
  expect_same_vertices(r.vertices, want.vertices);
  expect_same_faces(r, want);
}

TEST(RoundTripStl, BinaryHeaderNeverStartsWithSolid) {
  const std::string bytes =
      write_mesh_bytes(awkward_mesh(), MeshFormat::stl_binary, WriteOptions{.solid_name = "solid"});
  EXPECT_NE(bytes.rfind("solid", 0), 0u);
}

TEST(RoundTripStl, FanKeepsTheSignedVolumeOfAConcavePolygonPrism) {
  // An L-shaped prism whose caps are concave hexagons: 6 V = 6 × area 3 × height 1.
  Mesh m;
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (double z : {0.0, 1.0})
    for (const auto& p : xy) m.vertices.push_back({p[0], p[1], z});
  m.add_face({5, 4, 3, 2, 1, 0});  // bottom, seen from below: counter-clockwise
  m.add_face({6, 7, 8, 9, 10, 11});
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    m.add_face({i, j, j + 6, i + 6});
  }
  EXPECT_DOUBLE_EQ(test::six_volume(m), 18.0);
  MeshSource src;
  EXPECT_DOUBLE_EQ(test::six_volume(round_trip(m, MeshFormat::stl_ascii, &src)), 18.0);
  EXPECT_DOUBLE_EQ(test::six_volume(round_trip(m, MeshFormat::stl_binary, &src)), 18.0);
}

TEST(RoundTripReal, ShuttleThroughEveryFormat) {
  SHARED_MESH_OR_SKIP(path, "mayavi2/shuttle.obj");
  const Mesh m = read_mesh(path);
  for (MeshFormat f : {MeshFormat::obj, MeshFormat::off, MeshFormat::ply_ascii,
                       MeshFormat::ply_binary_le, MeshFormat::ply_binary_be}) {
    MeshSource src;
    const Mesh r = round_trip(m, f, &src);
    expect_same_vertices(r.vertices, m.vertices);
    expect_same_faces(r, m);
  }
}

TEST(WriteMesh, ToAFileAndBack) {
  const test::TempFile file(".ply");  // written by write_mesh, removed with `file`
  const std::string& path = file.path();
  const Mesh m = awkward_mesh();
  write_mesh(m, path, MeshFormat::ply_binary_le);
  MeshSource src;
  const Mesh r = read_mesh(path, &src);
  EXPECT_EQ(src.path, path);
  expect_same_vertices(r.vertices, m.vertices);
  EXPECT_THROW(write_mesh(m, "/nonexistent/dir/x.obj", MeshFormat::obj), std::runtime_error);
}

TEST(WriteMesh, RejectsBadIndicesAndNoFormat) {
  Mesh m = awkward_mesh();
  EXPECT_THROW(write_mesh_bytes(m, MeshFormat::unknown), std::invalid_argument);
  m.add_face({0, 1, 99});
  EXPECT_THROW(write_mesh_bytes(m, MeshFormat::obj), std::invalid_argument);
}

TEST(WriteMesh, LargeFacesUseAWideCountType) {
  Mesh m;
  std::vector<std::uint32_t> ring;
  for (std::uint32_t i = 0; i < 300; ++i) {
    const double t = 2 * M_PI * i / 300;
    m.vertices.push_back({std::cos(t), std::sin(t), 0});
    m.corners.push_back(i);
  }
  m.face_offsets.push_back(300);
  for (MeshFormat f :
       {MeshFormat::ply_ascii, MeshFormat::ply_binary_le, MeshFormat::obj, MeshFormat::off}) {
    MeshSource src;
    const Mesh r = round_trip(m, f, &src);
    ASSERT_EQ(r.face_count(), 1u);
    EXPECT_EQ(r.face_size(0), 300u);
  }
}

}  // namespace
}  // namespace pgamesh
