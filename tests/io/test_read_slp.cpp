// SLP (Pro/ENGINEER render files): ASCII STL's grammar with 'color' lines and vertex normals. An
// SLP reads to exactly the facets of the same text written as ASCII STL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "support/read_helpers.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

// The corner tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), outward, as `facet` blocks; `slp`
// adds the colour and vertex-normal lines of a Pro/ENGINEER render file.
std::string slp_tetrahedron(bool slp) {
  const char* const facets[4][3] = {{"0 0 0", "0 1 0", "1 0 0"},
                                    {"0 0 0", "0 0 1", "0 1 0"},
                                    {"0 0 0", "1 0 0", "0 0 1"},
                                    {"1 0 0", "0 1 0", "0 0 1"}};
  std::string s = "solid PRT0001\n";
  if (slp) s += "  color 0.500 0.500 0.500\n";
  for (int f = 0; f < 4; ++f) {
    if (slp && f == 2) s += "  color 1 0 0\n";
    s += slp ? "  facet\n" : "  facet normal 0 0 0\n";
    if (slp)
      for (int k = 0; k < 3; ++k) s += "    normal 0.577 0.577 0.577\n";
    s += "    outer loop\n";
    for (int k = 0; k < 3; ++k) s += std::string("      vertex ") + facets[f][k] + "\n";
    if (slp && f == 3) s += "      color 0 1 0\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid PRT0001\n";
}

TEST(ReadSlp, ColourLinesAndVertexNormalsReadAsTheSameFacetsAsStl) {
  MeshSource slp_source, stl_source;
  const Mesh slp = test::read_text(slp_tetrahedron(true), &slp_source);
  const Mesh stl = test::read_text(slp_tetrahedron(false), &stl_source);
  EXPECT_EQ(slp_source.format, MeshFormat::slp);
  EXPECT_EQ(stl_source.format, MeshFormat::stl_ascii);
  EXPECT_EQ(slp.vertices, stl.vertices);
  EXPECT_EQ(slp.corners, stl.corners);
  EXPECT_EQ(slp.face_count(), 4u);
  EXPECT_DOUBLE_EQ(mass_properties(slp).volume, 1.0 / 6.0);
}

TEST(ReadSlp, TheSlpExtensionNamesAnStlLikeFile) {
  const test::TempFile file(".slp", slp_tetrahedron(false));
  MeshSource source;
  read_mesh(file.path(), &source);
  EXPECT_EQ(source.format, MeshFormat::slp);
  EXPECT_EQ(format_for_extension("part.SLP"), MeshFormat::slp);
  AnalysisOptions streamed;  // the summing path of props --no-topology names it so too
  streamed.topology = false;
  const Analysis fast = analyze_file(file.path(), streamed);
  EXPECT_EQ(fast.format, MeshFormat::slp);
  EXPECT_DOUBLE_EQ(fast.mass.volume, 1.0 / 6.0);
  const test::TempFile coloured(".slp", slp_tetrahedron(true));
  EXPECT_DOUBLE_EQ(analyze_file(coloured.path()).mass.volume, 1.0 / 6.0);
}

TEST(ReadSlp, EndSolidInTwoWordsClosesTheSolid) {
  std::string two_words = slp_tetrahedron(true);
  two_words.replace(two_words.rfind("endsolid"), 8, "end  solid");
  MeshSource source;
  const Mesh slp = test::read_text(two_words + "solid second\nEnd Solid second\n", &source);
  EXPECT_EQ(source.format, MeshFormat::slp);
  EXPECT_EQ(slp.face_count(), 4u);
  EXPECT_DOUBLE_EQ(mass_properties(slp).volume, 1.0 / 6.0);
  EXPECT_TRUE(source.warnings.empty());
  const test::TempFile file(".slp", two_words);  // the summing path of props --no-topology too
  AnalysisOptions streamed;
  streamed.topology = false;
  EXPECT_DOUBLE_EQ(analyze_file(file.path(), streamed).mass.volume, 1.0 / 6.0);
  // 'end' followed by anything else is not a solid's end.
  const std::string end_facet = two_words.substr(0, two_words.rfind("end  solid")) + "end facet\n";
  const auto line =
      static_cast<std::uint64_t>(std::count(end_facet.begin(), end_facet.end(), '\n'));
  EXPECT_TEXT_ERROR(test::read_error(end_facet), line, 1u, "expected 'facet' or 'endsolid'");
}

TEST(ReadSlp, AColourLineOutsideASolidIsAnError) {
  const std::string solid = slp_tetrahedron(true);
  const auto line = static_cast<std::uint64_t>(std::count(solid.begin(), solid.end(), '\n')) + 1;
  EXPECT_TEXT_ERROR(test::read_error(solid + "color 1 1 1\n"), line, 1u, "expected 'solid'");
}

}  // namespace
}  // namespace pgamesh
