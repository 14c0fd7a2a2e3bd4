// Each reader round-trips the same mesh to identical results: the bundled bunny (float32
// coordinates, so binary STL and float PLY are lossless too) written in every format and read
// back gives bit-identical mass properties.
#include <gtest/gtest.h>

#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"

using namespace pgamesh;

TEST(MassRoundTrip, EveryFormatGivesIdenticalResults) {
  const Mesh bunny = read_mesh(std::string(PGAMESH_BUNDLED_MESHES_DIR) + "/bunny.stl");
  ASSERT_EQ(bunny.face_count(), 3674u);
  const MassProperties ref = mass_properties(bunny);
  ASSERT_GT(ref.volume, 0);
  for (MeshFormat f :
       {MeshFormat::stl_ascii, MeshFormat::stl_binary, MeshFormat::obj, MeshFormat::ply_ascii,
        MeshFormat::ply_binary_le, MeshFormat::ply_binary_be, MeshFormat::off}) {
    for (bool single : {false, true}) {
      SCOPED_TRACE(std::string(format_name(f)) + (single ? " float32" : ""));
      WriteOptions opt;
      opt.single_precision = single;
      const std::string bytes = write_mesh_bytes(bunny, f, opt);
      MeshSource source;
      const Mesh back = read_mesh_bytes(bytes, "roundtrip", &source);
      EXPECT_EQ(source.format, f);
      const MassProperties p = mass_properties(back, {}, &source);
      EXPECT_EQ(p.triangles, ref.triangles);
      EXPECT_EQ(p.volume, ref.volume);
      EXPECT_EQ(p.area, ref.area);
      EXPECT_EQ(p.center_of_mass, ref.center_of_mass);
      EXPECT_EQ(p.inertia_com, ref.inertia_com);
      EXPECT_EQ(p.principal.moments, ref.principal.moments);
    }
  }
}
