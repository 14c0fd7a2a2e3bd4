// The summing consumer of the ASCII STL grammar (`props --no-topology`) against the Mesh it reads:
// for every text, on any thread count and any cut into pieces, ascii_stl_mass_properties() is
// mass_properties() of read_mesh_bytes() about the same reference point up to rounding (bit for bit
// for a text of one piece whose sample meets every vertex line), the same bits on any thread count,
// with the same counts and source fields — or both throw the same InputError (message and
// position). The cases cover the repairs (polygons, a missing endsolid, several solids, letter
// case, CRLF, a byte order mark), the errors, and troubles in a later piece of a large file.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mesh/mass/stl_ascii_sums.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/geometry/reference_point.hpp"
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

// The figures of `mesh` accumulated about `reference`, as mass_properties() accumulates them about
// its own reference point.
MassProperties mass_about(const Mesh& mesh, Vec3d reference, const MeshSource& source) {
  std::uint64_t triangles = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) triangles += mesh.face_size(f) - 2;
  return mesh_mass_properties_from_sums(mesh_boundary_sums(mesh, reference, 1), reference,
                                        mesh.vertices, mesh.face_count(), triangles, {},
                                        source.single_precision);
}

// a and b equal up to the rounding of sums of many terms: relative to each quantity's scale.
void expect_near_mass(const MassProperties& a, const MassProperties& b) {
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.warnings, b.warnings);
  const double tol = 1e-12;
  EXPECT_NEAR(a.area, b.area, tol * std::abs(b.area));
  EXPECT_NEAR(a.volume, b.volume, tol * std::abs(b.volume));
  EXPECT_NEAR(a.gap_area, b.gap_area, tol * (std::abs(b.area) + 1e-300));
  const double size = std::cbrt(std::abs(b.volume)) + 1e-300;
  if (std::isfinite(b.center_of_mass.x)) {
    EXPECT_NEAR(length(a.center_of_mass - b.center_of_mass), 0,
                tol * (size + length(b.center_of_mass)));
    double scale = 0;
    for (const auto& row : b.inertia_com)
      for (double v : row) scale = std::max(scale, std::abs(v));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(a.inertia_com[i][j], b.inertia_com[i][j], tol * scale);
  } else {
    EXPECT_FALSE(std::isfinite(a.center_of_mass.x));
  }
}

TEST_P(StlAsciiSums, EqualMassPropertiesOfTheReadMesh) {
  const std::string text = GetParam().text();
  const std::span<const char> bytes{text.data(), text.size()};
  MeshSource read_source;
  std::optional<Mesh> read;
  std::optional<InputError> read_error;
  try {
    read = read_mesh_bytes(bytes, "mem.stl", &read_source, MeshFormat::stl_ascii);
    EXPECT_EQ(read_source.format, MeshFormat::stl_ascii);
  } catch (const InputError& e) {
    read_error = e;
  }
  // The default pieces, and pieces of a few facets (every file then has several).
  for (const std::size_t piece_bytes : {detail::stl_ascii_piece_bytes, std::size_t{300}}) {
    std::optional<MassProperties> first;  // on one thread
    for (const unsigned threads : {1u, 2u, 5u}) {
      SCOPED_TRACE("piece bytes " + std::to_string(piece_bytes) + ", threads " +
                   std::to_string(threads));
      MassOptions options;
      options.threads = threads;
      MeshSource source;
      try {
        const MassProperties summed =
            ascii_stl_mass_properties(bytes, "mem.stl", source, options, false, piece_bytes);
        ASSERT_TRUE(read) << "the reader rejects it: " << read_error->what();
        EXPECT_EQ(source.format, read_source.format);
        EXPECT_EQ(source.warnings, read_source.warnings);
        expect_near_mass(summed, mass_about(*read, summed.reference_point, read_source));
        if (first)
          test::expect_same_mass(summed, *first);
        else
          first = summed;
        // One piece, and a sample that met every vertex: the mesh's own figures, bit for bit.
        if (text.size() <= piece_bytes && summed.reference_point == reference_point(*read))
          test::expect_same_mass(summed, mass_properties(*read, {}, &read_source));
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
}

// The sampled reference point lies in the box of the mesh and near its centre: for a sphere far
// from the origin, within a hundredth of its radius of the centre (the samples reach every band).
TEST(StlAsciiSums, SampledReferenceIsNearTheCentre) {
  const Vec3d centre{1e6, -1e6, 1e6};
  const std::string text =
      ascii_stl(test::transformed(uv_sphere(1.25, 40, 80), [&](Vec3d p) { return p + centre; }));
  MeshSource source;
  const MassProperties p = ascii_stl_mass_properties({text.data(), text.size()}, "mem.stl", source);
  EXPECT_LT(length(p.reference_point - centre), 0.0125);
  // A vertex line that is not one (a name holding the word) is no sample.
  const std::string named = "solid vertex 1e300 0 0\n" + tetra_facets + "endsolid\n";
  const Box3 box = detail::stl_ascii_sampled_box({named.data(), named.size()}, "mem.stl", false);
  EXPECT_EQ(box.max_abs(), 1);
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
