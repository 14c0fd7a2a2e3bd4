// Real meshes nobody on this project wrote (../shared/meshes, read in place): closed meshes give
// positive volumes that agree across formats and with exact rational arithmetic; inward meshes
// give negative volumes, reported as such. A test of a file that is not bundled (its licence) is an
// extra, run only with ../shared/meshes; a mesh of our own, built in code, covers its property on a
// lone clone.
#include <gtest/gtest.h>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "support/golden.hpp"
#include "support/nested_shells.hpp"
#include "support/solids.hpp"
#include "support/stl_bytes.hpp"
#include "support/temp_file.hpp"

#ifdef PGAMESH_HAVE_GMP
#include "support/exact_mass.hpp"
#endif

using namespace pgamesh;
using pgamesh::test::max_abs;

namespace {

struct Loaded {
  Mesh mesh;
  MeshSource source;
  MassProperties props;
};

Loaded load_path(const std::string& path) {
  Loaded l;
  l.mesh = read_mesh(path, &l.source);
  l.props = mass_properties(l.mesh, {}, &l.source);
  return l;
}

Loaded load(const std::string& relative) {
  return load_path(pgamesh::test::shared_meshes_dir() + "/" + relative);
}

#define REQUIRE_SHARED_MESHES() \
  if (pgamesh::test::shared_meshes_dir().empty()) GTEST_SKIP() << "../shared/meshes not found"

void expect_exact([[maybe_unused]] const Loaded& l) {
#ifdef PGAMESH_HAVE_GMP
  const auto x = pgamesh::test::exact_summary(l.mesh);
  EXPECT_NEAR(l.props.volume, x.volume, 1e-12 * std::abs(x.volume));
  const double size = bounding_box(l.mesh.vertices).diagonal();
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(l.props.center_of_mass[i], x.center_of_mass[i], 1e-12 * size);
  const double scale = max_abs(x.inertia_com);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(l.props.inertia_com[i][j], x.inertia_com[i][j], 1e-12 * scale);
#endif
}

}  // namespace

TEST(MassRealMeshes, GearwheelAsciiAndBinaryAgree) {
  EXTRA_WITH_REAL_MESHES("stl-models/gearwheel.ascii.stl", "stl-models/gearwheel.bin.stl");
  const Loaded a = load("stl-models/gearwheel.ascii.stl"), b = load("stl-models/gearwheel.bin.stl");
  EXPECT_EQ(a.props.triangles, 2444u);
  EXPECT_GT(a.props.volume, 0);
  // The ASCII text and the float32 records hold nearly the same numbers.
  EXPECT_NEAR(a.props.volume, b.props.volume, 1e-6 * a.props.volume);
  EXPECT_NEAR(length(a.props.center_of_mass - b.props.center_of_mass), 0,
              1e-6 * bounding_box(a.mesh.vertices).diagonal());
  EXPECT_LT(a.props.gap_area, 1e-9 * a.props.area);
  expect_exact(a);
  expect_exact(b);
}

TEST(MassOwnMeshes, TorusAsciiAndBinaryStlAgree) {
  // Our own genus-1 solid, in place of the gear wheel: a torus (radii 2 and 1) of 24 × 12 quads,
  // fanned into 576 triangles, written as ASCII STL (7 significant digits) and binary (float32).
  const Mesh torus = pgamesh::test::torus_mesh(2, 1, 24, 12, Vec3d{0, 0, 0}, true);
  const std::string text = pgamesh::test::ascii_stl_text(torus);
  const std::vector<char> bytes = pgamesh::test::binary_stl_bytes(torus);
  const pgamesh::test::TempFile ascii_file(".stl", text);
  const pgamesh::test::TempFile binary_file(".stl", {bytes.data(), bytes.size()});
  const Loaded a = load_path(ascii_file.path()), b = load_path(binary_file.path());
  EXPECT_EQ(a.source.format, MeshFormat::stl_ascii);
  EXPECT_EQ(b.source.format, MeshFormat::stl_binary);
  EXPECT_EQ(a.props.triangles, 576u);
  EXPECT_EQ(b.props.triangles, 576u);
  EXPECT_GT(a.props.volume, 0);
  // Both round the same doubles, to 5e-7 and 6e-8 relative: the figures agree to ~1e-6.
  EXPECT_NEAR(a.props.volume, b.props.volume, 1e-6 * a.props.volume);
  EXPECT_NEAR(length(a.props.center_of_mass - b.props.center_of_mass), 0,
              1e-6 * bounding_box(a.mesh.vertices).diagonal());
  EXPECT_LT(a.props.gap_area, 1e-9 * a.props.area);
  expect_exact(a);
  expect_exact(b);
}

TEST(MassOwnMeshes, InsideOutTorusReportsNegativeVolume) {
  // Our own inward closed mesh, in place of the mushroom: the torus above with every quad facing
  // in, beside the bundled inward dodecahedron.
  Loaded own;
  own.mesh = pgamesh::test::torus_mesh(2, 1, 24, 12, Vec3d{0, 0, 0}, false);
  own.props = mass_properties(own.mesh, {}, &own.source);
  const Loaded dodecahedron = load("octave-matgeom/dodecahedron.ply");
  for (const Loaded* l : {static_cast<const Loaded*>(&own), &dodecahedron}) {
    EXPECT_LT(l->props.volume, 0);  // not abs()'d
    EXPECT_LT(l->props.mass, 0);
    // The centre of mass is still that of the solid; the inertia comes out negated.
    EXPECT_LT(l->props.inertia_com[0][0], 0);
    expect_exact(*l);
  }
  // The torus is symmetric about the origin: its centre of mass is there.
  EXPECT_NEAR(length(own.props.center_of_mass), 0, 1e-12);
}

TEST(MassRealMeshes, BunnyStlAndObjAgree) {
  REQUIRE_SHARED_MESHES();
  const Loaded s = load("npm/bunny.stl"), o = load("npm/bunny.obj");
  EXPECT_EQ(s.props.triangles, 3674u);
  EXPECT_EQ(o.props.triangles, 3674u);
  EXPECT_GT(o.props.volume, 0);
  // OBJ holds float64 text, the STL its float32 rounding: relative agreement ~1e-6.
  EXPECT_NEAR(s.props.volume, o.props.volume, 1e-5 * o.props.volume);
  EXPECT_NEAR(s.props.principal.moments[2], o.props.principal.moments[2],
              1e-5 * o.props.principal.moments[2]);
  EXPECT_LT(o.props.gap_area, 1e-12 * o.props.area);
  expect_exact(s);
  expect_exact(o);
}

TEST(MassRealMeshes, ShuttleWithQuadsIsASolid) {
  REQUIRE_SHARED_MESHES();
  const Loaded l = load("mayavi2/shuttle.obj");
  EXPECT_EQ(l.props.faces, 170u + 223u);
  EXPECT_EQ(l.props.triangles, 170u + 2 * 223u);
  EXPECT_GT(l.props.volume, 0);
  expect_exact(l);
}

TEST(MassRealMeshes, BinaryPlyUnitCube) {
  REQUIRE_SHARED_MESHES();
  const Loaded l = load("assimp-testmodels/cube_binary.ply");
  EXPECT_NEAR(std::abs(l.props.volume), 1, 1e-6);
  EXPECT_NEAR(l.props.area, 6, 1e-6);
}

TEST(MassRealMeshes, InwardMeshesReportNegativeVolume) {
  EXTRA_WITH_REAL_MESHES("geomview/mushroom.off");
  for (const char* name : {"geomview/mushroom.off", "octave-matgeom/dodecahedron.ply"}) {
    SCOPED_TRACE(name);
    const Loaded l = load(name);
    EXPECT_LT(l.props.volume, 0);  // not abs()'d
    EXPECT_LT(l.props.mass, 0);
    // The centre of mass is still that of the solid; the inertia comes out negated.
    EXPECT_LT(l.props.inertia_com[0][0], 0);
    expect_exact(l);
  }
}

TEST(MassRealMeshes, DodecahedronPentagonsMatchTheClosedForm) {
  REQUIRE_SHARED_MESHES();
  const Loaded l = load("octave-matgeom/dodecahedron.ply");
  // Regular dodecahedron of edge a: V = (15 + 7√5)/4 a³.
  const auto& v = l.mesh.vertices;
  double edge = 1e300;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) edge = std::min(edge, length(v[i] - v[j]));
  const double expected = (15 + 7 * std::sqrt(5.0)) / 4 * edge * edge * edge;
  EXPECT_NEAR(-l.props.volume, expected, 1e-5 * expected);
}
