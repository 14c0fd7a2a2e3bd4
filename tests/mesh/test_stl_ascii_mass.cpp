// The summing consumer of the ASCII STL grammar (`props --no-topology`) against the Mesh it reads:
// for every text, on any thread count and any cut into pieces, ascii_stl_mass_properties() is
// mass_properties() of read_mesh_bytes() bit for bit, with the same source fields — or both throw
// the same InputError (message and position). The cases cover the repairs (polygons, a missing
// endsolid, several solids, letter case, CRLF, a byte order mark), the errors, and troubles in a
// later piece of a large file.
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mass/stl_ascii_sums.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "pgamesh/mesh/mass/mass_properties.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"

namespace pgamesh {
namespace {

using test::triangulated;
using test::uv_sphere;

std::string ascii_stl(const Mesh& m) {
  return write_mesh_bytes(triangulated(m), MeshFormat::stl_ascii);
}

// A sphere written as ASCII STL, larger than several pieces.
const std::string& large_sphere() {
  static const std::string text = ascii_stl(uv_sphere(2.5, 60, 120));
  return text;
}

const std::string tetra_facets =
    "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n"
    " endloop\nendfacet\n"
    "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n"
    "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n"
    " endloop\nendfacet\n"
    "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n"
    " endloop\nendfacet\n";

const std::string quad_facet =
    "facet normal 0 0 1\n outer loop\n  vertex 0 0 5\n  vertex 1 0 5\n  vertex 1 1 5\n"
    "  vertex 0 1 5\n endloop\nendfacet\n";

// `text` with `insert` put in front of the first 'facet' line at or after `fraction` of it.
std::string inserted(std::string text, double fraction, const std::string& insert) {
  const auto at = text.find("\nfacet", static_cast<std::size_t>(fraction * text.size()));
  return text.insert(at + 1, insert);
}

// `text` with the first vertex line at or after `fraction` of it replaced by `line`.
std::string replaced_vertex(std::string text, double fraction, const std::string& line) {
  const auto at = text.find("vertex ", static_cast<std::size_t>(fraction * text.size()));
  return text.replace(at, text.find('\n', at) - at, line);
}

struct Case {
  const char* name;
  std::function<std::string()> text;
};

const Case stl_ascii_cases[] = {
    {"SmallSphere", [] { return ascii_stl(uv_sphere(1.5, 10, 16)); }},
    {"Box", [] { return ascii_stl(test::box_mesh(2, 3, 5)); }},
    {"LargeSphere", [] { return large_sphere(); }},
    {"FarFromOrigin",
     [] {
       return ascii_stl(test::transformed(uv_sphere(1.25, 40, 80), [](Vec3d p) {
         return p + Vec3d{1e6, -1e6, 1e6};
       }));
     }},
    {"AnyCaseCrlfSeveralSolids",
     [] {
       return "SOLID a\r\n" + tetra_facets +
              "ENDSOLID a\r\nsolid b\r\n"
              "FACET NORMAL 0 0 0\r\n OUTER LOOP\r\n  VERTEX 5 5 5\r\n  VERTEX 6 5 5\r\n"
              "  VERTEX 5 6 5\r\n ENDLOOP\r\nENDFACET\r\nendsolid b\r\n";
     }},
    {"ByteOrderMark", [] { return "\xEF\xBB\xBFsolid t\n" + tetra_facets + "endsolid t\n"; }},
    {"MissingEndsolid", [] { return "solid t\n" + tetra_facets; }},
    {"MissingEndsolidLarge",
     [] { return large_sphere().substr(0, large_sphere().rfind("endsolid")); }},
    {"Polygons",
     [] { return "solid t\n" + quad_facet + tetra_facets + quad_facet + "endsolid\n"; }},
    {"PolygonInALaterPiece", [] { return inserted(large_sphere(), 0.6, quad_facet); }},
    {"SolidsSplitAcrossPieces",
     [] {
       std::string text = large_sphere();
       for (double f = 0.1; f < 0.95; f += 0.13) text = inserted(text, f, "endsolid p\nsolid p\n");
       return text;
     }},
    {"EmptySolid", [] { return std::string("solid t\nendsolid t\n"); }},
    {"MissingEndsolidOneLongLine",
     [] {
       std::string text = "solid x";
       while (text.size() < 3 * detail::stl_ascii_piece_bytes) text += " facet vertex 1 2 3";
       return text;
     }},
    {"NaN", [] { return "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 nan\n"; }},
    {"TruncatedInAFacet",
     [] { return "solid t\n" + tetra_facets + "facet normal 0 0 1\n outer loop\n  vertex 0 0\n"; }},
    {"FacetOutsideASolid",
     [] { return "solid t\n" + tetra_facets + "endsolid t\n" + tetra_facets; }},
    {"StrayVertex", [] { return "solid t\n" + tetra_facets + "  vertex 1 2 3\n"; }},
    {"MisspeltKeyword",
     [] { return "solid t\n" + tetra_facets.substr(0, tetra_facets.size() - 9) + "endfacetx\n"; }},
    {"OutOfRange", [] { return std::string("solid t\nfacet\n outer loop\n  vertex 0 0 1e999\n"); }},
    {"FourNumbers", [] { return std::string("solid t\nfacet\n outer loop\n  vertex 0 0 1 2\n"); }},
    {"TwoVertices",
     [] {
       return std::string(
           "solid t\nfacet\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n endloop\n"
           "endfacet\nendsolid\n");
     }},
    {"NotStl", [] { return std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }},
    {"NaNInTheLastPiece", [] { return replaced_vertex(large_sphere(), 0.99, "vertex 1 nan 2"); }},
    {"ErrorInAMiddlePiece", [] { return replaced_vertex(large_sphere(), 0.5, "vertex 1 2"); }},
    {"FacetAfterEndsolidInAMiddlePiece",
     [] { return inserted(large_sphere(), 0.5, "endsolid p\n"); }},
};

class StlAsciiSums : public ::testing::TestWithParam<Case> {};

TEST_P(StlAsciiSums, EqualMassPropertiesOfTheReadMeshBitForBit) {
  const std::string text = GetParam().text();
  const std::span<const char> bytes{text.data(), text.size()};
  MeshSource read_source;
  std::optional<MassProperties> read_mass;
  std::optional<InputError> read_error;
  try {
    const Mesh m = read_mesh_bytes(bytes, "mem.stl", &read_source, MeshFormat::stl_ascii);
    EXPECT_EQ(read_source.format, MeshFormat::stl_ascii);
    read_mass = mass_properties(m, {}, &read_source);
  } catch (const InputError& e) {
    read_error = e;
  }
  // The default pieces, and pieces of a few facets (every file then has several).
  for (const std::size_t piece_bytes : {detail::stl_ascii_piece_bytes, std::size_t{300}})
    for (const unsigned threads : {1u, 2u, 5u}) {
      SCOPED_TRACE("piece bytes " + std::to_string(piece_bytes) + ", threads " +
                   std::to_string(threads));
      MassOptions options;
      options.threads = threads;
      MeshSource source;
      try {
        const MassProperties summed =
            ascii_stl_mass_properties(bytes, "mem.stl", source, options, false, piece_bytes);
        ASSERT_TRUE(read_mass) << "the reader rejects it: " << read_error->what();
        test::expect_same_mass(summed, *read_mass);
        EXPECT_EQ(source.format, read_source.format);
        EXPECT_EQ(source.warnings, read_source.warnings);
      } catch (const InputError& e) {
        ASSERT_TRUE(read_error) << "only the summing consumer rejects it: " << e.what();
        EXPECT_STREQ(e.what(), read_error->what());
        EXPECT_EQ(e.file(), read_error->file());
        EXPECT_EQ(e.where().has_line, read_error->where().has_line);
        EXPECT_EQ(e.where().line, read_error->where().line);
        EXPECT_EQ(e.where().column, read_error->where().column);
        EXPECT_EQ(e.where().byte_offset, read_error->where().byte_offset);
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Texts, StlAsciiSums, ::testing::ValuesIn(stl_ascii_cases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

// The cases above reach what they are meant to: repairs are made, errors raised, and the large
// texts are cut into several pieces.
TEST(StlAsciiSums, CasesReachTheirPaths) {
  EXPECT_GT(large_sphere().size(), 4 * detail::stl_ascii_piece_bytes);
  auto warnings = [](const std::string& text) {
    MeshSource source;
    ascii_stl_mass_properties({text.data(), text.size()}, "mem.stl", source);
    return source.warnings.size();
  };
  for (const Case& c : stl_ascii_cases) {
    const std::string name = c.name;
    const std::string text = c.text();
    const bool error = name == "NaN" || name == "TruncatedInAFacet" ||
                       name == "FacetOutsideASolid" || name == "StrayVertex" ||
                       name == "MisspeltKeyword" || name == "OutOfRange" || name == "FourNumbers" ||
                       name == "TwoVertices" || name == "NotStl" || name == "NaNInTheLastPiece" ||
                       name == "ErrorInAMiddlePiece" || name == "FacetAfterEndsolidInAMiddlePiece";
    if (error) {
      EXPECT_THROW(warnings(text), InputError) << name;
    } else {
      const std::size_t expected =
          name.starts_with("Missing") || name.starts_with("Polygon") ? 1u : 0u;
      EXPECT_EQ(warnings(text), expected) << name;
    }
  }
}

}  // namespace
}  // namespace pgamesh
