// The real OBJ, PLY and OFF files of ../shared/meshes (see its README): face and vertex counts,
// polygon sizes, and the signed volume's sign where the README states the orientation. The GPL
// files (conway-tI.obj, mushroom.off) are not bundled: their tests are extras, run only when the
// file is there, and files of our own written here check the same on a lone clone.
#include <gtest/gtest.h>

#include <map>

#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"
#include "support/temp_file.hpp"

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

TEST(ReadOwnMeshes, ObjPrismsKeepPentagonsAndHexagons) {
  // Our own OBJ: prisms of height 1 over the convex pentagon (0,0) (2,0) (3,2) (1,3) (−1,2) (area 8
  // by the shoelace formula) and the hexagon (2,0) (1,2) (−1,2) (−2,0) (−1,−2) (1,−2) (area 12, at
  // z 2..3), both counter-clockwise seen from +z: volume 8 + 12 = 20, six times it 120.
  const test::TempFile obj(".obj",
                           "v 0 0 0\nv 2 0 0\nv 3 2 0\nv 1 3 0\nv -1 2 0\n"
                           "v 0 0 1\nv 2 0 1\nv 3 2 1\nv 1 3 1\nv -1 2 1\n"
                           "f 5 4 3 2 1\nf 6 7 8 9 10\n"
                           "f 1 2 7 6\nf 2 3 8 7\nf 3 4 9 8\nf 4 5 10 9\nf 5 1 6 10\n"
                           "v 2 0 2\nv 1 2 2\nv -1 2 2\nv -2 0 2\nv -1 -2 2\nv 1 -2 2\n"
                           "v 2 0 3\nv 1 2 3\nv -1 2 3\nv -2 0 3\nv -1 -2 3\nv 1 -2 3\n"
                           "f 16 15 14 13 12 11\nf 17 18 19 20 21 22\n"
                           "f 11 12 18 17\nf 12 13 19 18\nf 13 14 20 19\n"
                           "f 14 15 21 20\nf 15 16 22 21\nf 16 11 17 22\n");
  const Mesh m = read_mesh(obj.path());
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{4, 11}, {5, 2}, {6, 2}}));
  EXPECT_EQ(m.vertices.size(), 22u);
  EXPECT_EQ(test::six_volume(m), 120.0);  // integer coordinates: exact
}

TEST(ReadOwnMeshes, OffTrianglesAndQuadInward) {
  // Our own OFF: the square pyramid over [0,2]² at z = 0 with apex (1,1,3), every face wound
  // clockwise seen from outside: volume −(4·3/3) = −4, six times it −24.
  const test::TempFile off(".off",
                           "OFF\n5 5 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n1 1 3\n"
                           "4 0 1 2 3\n3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n");
  MeshSource src;
  const Mesh m = read_mesh(off.path(), &src);
  EXPECT_EQ(src.format, MeshFormat::off);
  EXPECT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{3, 4}, {4, 1}}));
  EXPECT_EQ(test::six_volume(m), -24.0);
}

TEST(ReadRealMeshes, ConwayTruncatedIcosahedronObjHasPentagonsAndHexagons) {
  SHARED_MESH_EXTRA(path, "npm/conway-tI.obj");
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
  SHARED_MESH_EXTRA(path, "geomview/mushroom.off");
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  EXPECT_EQ(src.format, MeshFormat::off);
  EXPECT_EQ(m.vertices.size(), 226u);
  EXPECT_EQ(polygon_sizes(m), (std::map<std::size_t, std::size_t>{{3, 32}, {4, 208}}));
  EXPECT_LT(test::six_volume(m), 0);  // README: inward-oriented
}

}  // namespace
}  // namespace pgamesh
