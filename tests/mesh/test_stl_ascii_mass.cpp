// The fused ASCII STL path: the same figures as reading the mesh first (bit for bit on a small
// file, to 1e-12 on a large one, whose sums are added in another order), independent of the thread
// count, held to exact rational arithmetic and closed forms, and declining (nullopt) for everything
// the careful reader must see: polygons, syntax errors, NaN, empty solids — also when the trouble
// is in a later piece.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "pgamesh/mesh/mass/stl_ascii_mass_properties.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#ifdef PGAMESH_HAVE_GMP
#include "support/exact_mass.hpp"
#endif

using namespace pgamesh;
using namespace pgamesh::test;

namespace {

std::optional<MassProperties> fused(const std::string& text, unsigned threads = 0) {
  MassOptions o;
  o.threads = threads;
  return ascii_stl_mass_properties({text.data(), text.size()}, "mem.stl", o);
}

MassProperties careful(const std::string& text) {
  MeshSource source;
  const Mesh m = read_mesh_bytes({text.data(), text.size()}, "mem.stl", &source);
  return mass_properties(m, {}, &source);
}

std::string ascii_stl(const Mesh& m) {
  return write_mesh_bytes(triangulated(m), MeshFormat::stl_ascii);
}

// A sphere written as ASCII STL, larger than several pieces.
const std::string& large_sphere_text() {
  static const std::string text = ascii_stl(uv_sphere(2.5, 60, 120));
  return text;
}

const char* const tetra_facets =
    "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n"
    " endloop\nendfacet\n"
    "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n"
    "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n"
    " endloop\nendfacet\n"
    "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n";

}  // namespace

TEST(StlAsciiMass, SmallFileEqualsReadMeshBitForBit) {
  // One piece, every vertex in the reference box: the same point and the same order of sums.
  const std::string text = ascii_stl(uv_sphere(1.5, 10, 16));
  const auto f = fused(text);
  ASSERT_TRUE(f);
  test::expect_same_mass(*f, careful(text));
  EXPECT_GT(f->volume, 0);
  EXPECT_TRUE(f->warnings.empty());
}

TEST(StlAsciiMass, BoxMatchesClosedForms) {
  // [0,2]×[0,3]×[0,5]: V = 30, centre (1, 1.5, 2.5), I_xx = m (b² + c²) / 12.
  const auto f = fused(ascii_stl(box_mesh(2, 3, 5)));
  ASSERT_TRUE(f);
  EXPECT_EQ(f->triangles, 12u);
  EXPECT_EQ(f->vertices, 36u);
  EXPECT_NEAR(f->volume, 30, 1e-13);
  EXPECT_NEAR(f->area, 2 * (6 + 10 + 15), 1e-13);
  EXPECT_NEAR(length(f->center_of_mass - Vec3d{1, 1.5, 2.5}), 0, 1e-14);
  EXPECT_NEAR(f->inertia_com[0][0], 30 * (9 + 25) / 12.0, 1e-12);
  EXPECT_NEAR(f->inertia_com[1][1], 30 * (4 + 25) / 12.0, 1e-12);
  EXPECT_NEAR(f->inertia_com[2][2], 30 * (4 + 9) / 12.0, 1e-12);
  EXPECT_NEAR(f->inertia_com[0][1], 0, 1e-12);
  EXPECT_NEAR(f->gap_area, 0, 1e-13);
}

TEST(StlAsciiMass, LargeFileIsThreadIndependentAndMatchesReadMesh) {
  const std::string& text = large_sphere_text();
  ASSERT_GT(text.size(), 4 * stl_ascii_piece_bytes);
  const auto a = fused(text, 1), b = fused(text, 2), c = fused(text, 5);
  ASSERT_TRUE(a && b && c);
  test::expect_same_mass(*a, *b);
  test::expect_same_mass(*a, *c);
  const MassProperties r = careful(text);
  EXPECT_EQ(a->triangles, r.triangles);
  EXPECT_NEAR(a->volume, r.volume, 1e-12 * r.volume);
  EXPECT_NEAR(a->area, r.area, 1e-12 * r.area);
  EXPECT_NEAR(length(a->center_of_mass - r.center_of_mass), 0, 1e-13);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(a->inertia_com[i][j], r.inertia_com[i][j], 1e-12 * r.inertia_com[0][0]);
  // The sampled reference point lies inside the sphere's box.
  EXPECT_LT(length(a->reference_point), 2.5);
}

#ifdef PGAMESH_HAVE_GMP
TEST(StlAsciiMass, FarFromOriginAgreesWithExactRationals) {
  // Text round trips are bit-exact, so the exact sums of the mesh's own doubles are the reference.
  const Mesh m = triangulated(transformed(uv_sphere(1.25, 40, 80), [](Vec3d p) {
    return p + Vec3d{1e6, -1e6, 1e6};
  }));
  const std::string text = write_mesh_bytes(m, MeshFormat::stl_ascii);
  ASSERT_GT(text.size(), stl_ascii_piece_bytes);
  const auto f = fused(text);
  ASSERT_TRUE(f);
  const ExactSummary e = exact_summary(m);
  EXPECT_NEAR(f->volume, e.volume, 1e-12 * e.volume);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f->center_of_mass[i], e.center_of_mass[i], 1e-12 * 1.25);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(f->inertia_com[i][j], e.inertia_com[i][j], 1e-12 * e.inertia_com[0][0]);
}
#endif

TEST(StlAsciiMass, AnyCaseCrlfAndSeveralSolidsAsTheReader) {
  const std::string text =
      std::string("SOLID a\r\n") + tetra_facets + "ENDSOLID a\r\nsolid b\r\n" +
      "FACET NORMAL 0 0 0\r\n OUTER LOOP\r\n  VERTEX 5 5 5\r\n  VERTEX 6 5 5\r\n"
      "  VERTEX 5 6 5\r\n ENDLOOP\r\nENDFACET\r\nendsolid b\r\n";
  const auto f = fused(text);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->triangles, 5u);
  EXPECT_DOUBLE_EQ(f->volume, careful(text).volume);
  EXPECT_NEAR(f->area, careful(text).area, 1e-15);
  EXPECT_TRUE(f->warnings.empty());
}

TEST(StlAsciiMass, MissingEndsolidIsTheReadersWarning) {
  const std::string text = std::string("solid t\n") + tetra_facets;
  const auto f = fused(text);
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->volume, 1.0 / 6, 1e-16);
  MeshSource source;
  read_mesh_bytes({text.data(), text.size()}, "mem.stl", &source);
  ASSERT_EQ(f->warnings.size(), 1u);
  ASSERT_EQ(source.warnings.size(), 1u);
  EXPECT_EQ(f->warnings[0], source.warnings[0]);
}

TEST(StlAsciiMass, DeclinesWhatTheCarefulReaderMustSee) {
  const std::string head = "solid t\n";
  const std::string facet = tetra_facets;
  const std::string quad =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 1 1 0\n"
      "  vertex 0 1 0\n endloop\nendfacet\n";
  for (const std::string& text : {
           head + facet + quad + "endsolid t\n",                              // a polygon
           head + "facet normal 0 0 1\n outer loop\n  vertex 0 0 nan\n",      // NaN
           head + facet + "facet normal 0 0 1\n outer loop\n  vertex 0 0\n",  // truncated
           head + facet + "endsolid t\n" + facet,                     // facet outside a solid
           head + facet + "  vertex 1 2 3\n",                         // stray vertex
           head + facet.substr(0, facet.size() - 9) + "endfacetx\n",  // misspelt keyword
           head + "facet\n outer loop\n  vertex 0 0 1e999\n",         // out of range
           head + "facet\n outer loop\n  vertex 0 0 1 2\n",           // four numbers
           head + "endsolid t\n",                                     // no facets
           std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),       // not STL
           std::string(""),
           // A control byte in the first KiB: read_mesh_bytes takes it for a broken binary STL.
           head + "facet normal \x03\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n"
                  "  vertex 0 1 0\n endloop\nendfacet\nendsolid t\n",
       })
    EXPECT_FALSE(fused(text)) << text;
}

TEST(StlAsciiMass, DeclinesALargeFileWithoutNewlines) {
  // Several pieces' worth of one line: sampling and piece boundaries scan it once each.
  std::string text = "solid x";
  while (text.size() < 4 * stl_ascii_piece_bytes) text += " facet vertex 1 2 3";
  EXPECT_FALSE(fused(text));
  text += "\nendsolid x\n";
  EXPECT_FALSE(fused(text));
}

TEST(StlAsciiMass, DeclinesTroubleInALaterPiece) {
  const std::string& good = large_sphere_text();
  ASSERT_TRUE(fused(good));
  // A NaN in the last facet, and a quad in the middle: both many pieces after the first.
  std::string nan_text = good;
  const auto last = nan_text.rfind("vertex ") + 7;
  nan_text.replace(last, nan_text.find(' ', last) - last, "nan");
  EXPECT_FALSE(fused(nan_text));
  std::string quad_text = good;
  const auto mid = quad_text.find(" endloop", quad_text.size() / 2);
  quad_text.insert(mid, "  vertex 0 0 0\n");
  EXPECT_FALSE(fused(quad_text));
  EXPECT_TRUE(read_mesh_bytes({quad_text.data(), quad_text.size()}, "q.stl").face_count() > 0);
}

TEST(StlAsciiMass, SolidsSplitAcrossPiecesStillSum) {
  // endsolid / solid pairs between facets anywhere in a large file: the pieces agree on the state.
  const std::string& good = large_sphere_text();
  std::string text = good;
  for (std::size_t at = text.size() / 7; at < text.size() - 1000; at += text.size() / 7) {
    const auto facet = text.find("\nfacet", at);
    text.insert(facet + 1, "endsolid part\nsolid part\n");
  }
  const auto a = fused(text);
  ASSERT_TRUE(a);
  const MassProperties r = careful(text);
  EXPECT_EQ(a->triangles, r.triangles);
  EXPECT_NEAR(a->volume, r.volume, 1e-12 * r.volume);
  EXPECT_NEAR(a->area, r.area, 1e-12 * r.area);
  EXPECT_TRUE(a->warnings.empty());
}
