// The real OBJ, PLY and OFF files of ../shared/meshes (see its README): face and vertex counts,
// polygon sizes, and the signed volume's sign where the README states the orientation.
#include <gtest/gtest.h>

#include <map>

#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"

namespace pgamesh {
namespace {

std::map<std::size_t, std::size_t> polygon_sizes(const Mesh& m) {
  std::map<std::size_t, std::size_t> sizes;
  for (std::size_t f = 0; f < m.face_count(); ++f) ++sizes[m.face_size(f)];
  return sizes;
}

TEST(ReadRealMeshes, ShuttleObjHasTrianglesAndQuads) {
  SHARED_MESH_OR_SKIP(path, "mayavi2/shuttle.obj");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::obj);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{3, 170}, {4, 223}}));
  EXPECT_GE(src.groups, 1u);
}

TEST(ReadRealMeshes, ConwayTruncatedIcosahedronObjHasPentagonsAndHexagons) {
  SHARED_MESH_OR_SKIP(path, "npm/conway-tI.obj");
  const Mesh m = read_mesh(path);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{5, 12}, {6, 20}}));
  EXPECT_EQ(m.vertices.size(), 60u);
  EXPECT_GT(test::six_volume(m), 0);
}

TEST(ReadRealMeshes, BunnyObjMatchesBunnyStl) {
  SHARED_MESH_OR_SKIP(obj, "npm/bunny.obj");
  SHARED_MESH_OR_SKIP(stl, "npm/bunny.stl");
  const Mesh a = read_mesh(obj), b = read_mesh(stl);
  ASSERT_EQ(a.face_count(), 3674u);
  ASSERT_EQ(b.face_count(), 3674u);
  // Same triangles in the same order: the STL is the OBJ rounded to float32.
  for (std::size_t f = 0; f < a.face_count(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3d p = a.vertices[a.face(f)[k]], q = b.vertices[b.face(f)[k]];
      for (int i = 0; i < 3; ++i) ASSERT_EQ(static_cast<float>(p[i]), q[i]) << f << " " << k;
    }
}

TEST(ReadRealMeshes, TeapotObj) {
  SHARED_MESH_OR_SKIP(path, "npm/teapot.obj");
  EXPECT_EQ(polygon_sizes(read_mesh(path)), (std::map<std::size_t, std::size_t>{{3, 992}}));
}

TEST(ReadRealMeshes, CubeBinaryPlyIsTheUnitCube) {
  SHARED_MESH_OR_SKIP(path, "assimp-testmodels/cube_binary.ply");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::ply_binary_le);
  EXPECT_TRUE(src.single_precision);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{3, 12}}));
  EXPECT_DOUBLE_EQ(std::abs(test::six_volume(m)), 6.0);  // unit cube, closed
}

TEST(ReadRealMeshes, DodecahedronPlyHasTwelveInwardPentagons) {
  SHARED_MESH_OR_SKIP(path, "octave-matgeom/dodecahedron.ply");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::ply_ascii);
  EXPECT_EQ(m.vertices.size(), 20u);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{5, 12}}));
  EXPECT_LT(test::six_volume(m), 0);  // README: inward-oriented
}

TEST(ReadRealMeshes, MushroomOffHasTrianglesAndQuadsInward) {
  SHARED_MESH_OR_SKIP(path, "geomview/mushroom.off");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::off);
  EXPECT_EQ(m.vertices.size(), 226u);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{3, 32}, {4, 208}}));
  EXPECT_LT(test::six_volume(m), 0);  // README: inward-oriented
}

}  // namespace
}  // namespace pgamesh
