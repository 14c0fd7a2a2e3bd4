// The streamed binary STL path: same figures as reading the mesh first, thread-count independent,
// errors with byte offsets for non-finite coordinates, the float32 far-from-origin warning.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "mesh/mass/stl_mass_properties.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "support/golden.hpp"
#include "support/read_helpers.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "support/stl_bytes.hpp"
#include "support/temp_file.hpp"

using namespace pgamesh;
using namespace pgamesh::test;

namespace {

MassProperties streamed(const std::vector<char>& bytes, unsigned threads = 0) {
  const auto view = binary_stl_view(bytes, "test.stl");
  EXPECT_TRUE(view.has_value());
  MassOptions opt;
  opt.threads = threads;
  return binary_stl_mass_properties(*view, "test.stl", opt);
}

// The closed form of the tetrahedron (0,0,0), (a,0,0), (0,b,0), (0,0,c) with a, b, c = 3, 2, 1:
// V = abc/6 = 1, c = (a/4, b/4, c/4) = (3/4, 1/2, 1/4); about the origin ∫x² = a³bc/60 = 27·2/60,
// ∫xy = a²b²c/120 = 36/120, and the others alike.
void expect_corner_tetrahedron(const MassProperties& p) {
  EXPECT_DOUBLE_EQ(p.volume, 1);
  EXPECT_DOUBLE_EQ(p.center_of_mass.x, 0.75);
  EXPECT_DOUBLE_EQ(p.center_of_mass.y, 0.5);
  EXPECT_DOUBLE_EQ(p.center_of_mass.z, 0.25);
  const double xx = 27.0 * 2 / 60, yy = 3 * 8.0 / 60, zz = 3 * 2.0 / 60;
  const double xy = 9 * 4.0 / 120, yz = 3 * 4.0 / 120, zx = 9 * 2.0 / 120;
  EXPECT_NEAR(p.inertia_origin[0][0], yy + zz, 1e-15);
  EXPECT_NEAR(p.inertia_origin[1][1], xx + zz, 1e-15);
  EXPECT_NEAR(p.inertia_origin[2][2], xx + yy, 1e-15);
  EXPECT_NEAR(p.inertia_origin[0][1], -xy, 1e-15);
  EXPECT_NEAR(p.inertia_origin[1][2], -yz, 1e-15);
  EXPECT_NEAR(p.inertia_origin[0][2], -zx, 1e-15);
}

}  // namespace

TEST(MassStl, StreamedEqualsReadMesh) {
  // Fewer triangles than the reference sample: both paths accumulate about the same point in the
  // same order, so they agree to the last bit.
  const Mesh m = uv_sphere(2, 10, 16);
  const std::vector<char> bytes = binary_stl_bytes(m);
  const MassProperties s = streamed(bytes);
  MeshSource source;
  const Mesh read = read_mesh_bytes(bytes, "test.stl", &source);
  const MassProperties r = mass_properties(read, {}, &source);
  EXPECT_EQ(s.triangles, r.triangles);
  EXPECT_EQ(s.vertices, r.vertices);
  EXPECT_EQ(s.volume, r.volume);
  EXPECT_EQ(s.area, r.area);
  EXPECT_EQ(s.center_of_mass, r.center_of_mass);
  EXPECT_EQ(s.inertia_com, r.inertia_com);
  EXPECT_GT(s.volume, 0);
}

TEST(MassStl, LargeStreamIsThreadIndependentAndMatchesMesh) {
  const Mesh m = uv_sphere(1, 120, 240);  // 57k triangles: many chunks, sampled reference point
  const std::vector<char> bytes = binary_stl_bytes(m);
  const MassProperties a = streamed(bytes, 1), b = streamed(bytes, 2), c = streamed(bytes, 5);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.volume, c.volume);
  EXPECT_EQ(a.inertia_com, b.inertia_com);
  EXPECT_EQ(a.inertia_com, c.inertia_com);
  MeshSource source;
  const MassProperties r = mass_properties(read_mesh_bytes(bytes, "t.stl", &source), {}, &source);
  EXPECT_NEAR(a.volume, r.volume, 1e-14 * r.volume);
  EXPECT_NEAR(a.inertia_com[0][0], r.inertia_com[0][0], 1e-14 * r.inertia_com[0][0]);
  EXPECT_NEAR(length(a.center_of_mass - r.center_of_mass), 0, 1e-15);
}

TEST(MassStl, NonFiniteCoordinateNamesItsByte) {
  std::vector<char> bytes = binary_stl_bytes(box_mesh(1, 2, 3));
  // Triangle 5 (0-based 4), vertex 2, y: byte 84 + 50·4 + 12 + 12 + 4.
  const std::size_t offset = 84 + 50 * 4 + 12 + 12 + 4;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(bytes.data() + offset, &nan, 4);
  const auto view = binary_stl_view(bytes, "nan.stl");
  ASSERT_TRUE(view);
  try {
    binary_stl_mass_properties(*view, "nan.stl");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().byte_offset, offset);
    EXPECT_NE(std::string(e.what()).find("nan.stl"), std::string::npos);
  }
}

TEST(MassStl, FarFromOriginFloat32Warns) {
  const Mesh near = box_mesh(1, 1, 1);
  EXPECT_TRUE(streamed(binary_stl_bytes(near)).warnings.empty());
  // At 1e4 float32 spacing is ~1e-3, 1e-3 of the part size: warned.
  const Mesh far = transformed(near, [](Vec3d v) { return v + Vec3d{1e4, 0, 0}; });
  const MassProperties p = streamed(binary_stl_bytes(far));
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("float32"), std::string::npos);
  // The same box is still measured exactly: its coordinates are representable.
  EXPECT_DOUBLE_EQ(p.volume, 1);
  EXPECT_DOUBLE_EQ(p.center_of_mass.x, 1e4 + 0.5);
}

TEST(MassStl, OwnCornerTetrahedronHasVolumeOne) {
  // Our own binary STL of the tetrahedron (0,0,0), (3,0,0), (0,2,0), (0,0,1), integer coordinates,
  // exact in float32.
  const std::vector<char> bytes =
      binary_stl_bytes(tetrahedron_mesh({0, 0, 0}, {3, 0, 0}, {0, 2, 0}, {0, 0, 1}));
  const TempFile file(".stl", {bytes.data(), bytes.size()});
  const MappedFile mapped = MappedFile::open(file.path());
  const auto view = binary_stl_view(mapped.bytes(), file.path());
  ASSERT_TRUE(view);
  const MassProperties p = binary_stl_mass_properties(*view, file.path());
  expect_corner_tetrahedron(p);
}

TEST(MassStl, IrregularTetrahedronHasVolumeOne) {
  // Extra: the same tetrahedron in the stl-models file (no licence stated, not bundled).
  EXTRA_WITH_REAL_MESHES("stl-models/tetrahedronIrregular.bin.stl");
  const std::string dir = shared_meshes_dir();
  const MappedFile file = MappedFile::open(dir + "/stl-models/tetrahedronIrregular.bin.stl");
  const auto view = binary_stl_view(file.bytes(), "tetrahedronIrregular.bin.stl");
  ASSERT_TRUE(view);
  const MassProperties p = binary_stl_mass_properties(*view, "tetrahedronIrregular.bin.stl");
  expect_corner_tetrahedron(p);
}

namespace {

// A binary STL written to a temporary file and mapped, viewed with its records read from the file
// (BinaryStlView::file) in blocks.
struct StlFile {
  explicit StlFile(const std::vector<char>& bytes)
      : file(".stl", {bytes.data(), bytes.size()}),
        mapped(MappedFile::open(file.path())),
        view(binary_stl_view(mapped.bytes(), file.path()).value()) {
    view.file = mapped.descriptor();
  }
  TempFile file;
  MappedFile mapped;
  BinaryStlView view;
};

// The InputError that the mass properties of `stl` must raise; a test failure otherwise.
InputError mass_error(const StlFile& stl) {
  try {
    binary_stl_mass_properties(stl.view, stl.file.path());
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", {}, "");
}

}  // namespace

// A view whose records are read from its file (BinaryStlView::file) in blocks: the same bits as
// the view of the bytes in memory, on one thread or two.
TEST(MassStl, ReadingTheFileEqualsReadingMemory) {
  Mesh m = uv_sphere(1, 120, 240);         // 57k triangles: 14 blocks of records, 4 chunks
  m.corners.resize(m.corners.size() - 9);  // three triangles fewer: a count that is no
  m.face_offsets.resize(m.face_offsets.size() - 3);  // multiple of the four lanes
  const std::vector<char> bytes = binary_stl_bytes(m);
  const StlFile stl(bytes);
  ASSERT_GE(stl.view.file, 0);
  for (unsigned threads : {1u, 2u}) {
    MassOptions opt;
    opt.threads = threads;
    expect_same_mass(binary_stl_mass_properties(stl.view, stl.file.path(), opt, true),
                     streamed(bytes, threads));
  }
}

TEST(MassStl, ReadingTheFileNamesTheNonFiniteByte) {
  std::vector<char> bytes = binary_stl_bytes(uv_sphere(1, 40, 80));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::size_t at = 84 + 50 * 5000 + 12 + 12 * 2 + 4;  // triangle 5001, vertex 3, y
  std::memcpy(bytes.data() + at, &nan, 4);
  EXPECT_BYTE_ERROR(mass_error(StlFile(bytes)), at, "triangle 5001, vertex 3");
}

TEST(MassStl, AFileShortenedWhileReadIsAnErrorAtItsEnd) {
  const std::vector<char> bytes = binary_stl_bytes(uv_sphere(1, 40, 80));
  const StlFile stl(bytes);
  const std::size_t kept = 84 + 50 * 1000 + 7;
  ASSERT_EQ(::truncate(stl.file.path().c_str(), static_cast<off_t>(kept)), 0);
  EXPECT_BYTE_ERROR(mass_error(stl), kept, "shortened");
}
