// Reading a mapped file while giving its pages back to the kernel (read_mesh, and read_mesh_bytes
// with release_pages): the mesh, the source fields and every error message must be those of
// reading the same bytes from memory. The files are several MiB so that the readers release pages
// (in 4 MiB steps) before they reach the data that is compared or the error that is reported.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "io/readers.hpp"
#include "io/stl_binary.hpp"
#include "mesh/mass/stl_ascii_sums.hpp"
#include "mesh/mass/stl_mass_properties.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/same_topology.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh {
namespace {

using test::expect_same_mass;
using test::TempFile;

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vec3d)),
            0);
  EXPECT_EQ(a.corners, b.corners);
  EXPECT_EQ(a.face_offsets, b.face_offsets);
}

void expect_same_source(const MeshSource& a, const MeshSource& b) {
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.single_precision, b.single_precision);
  EXPECT_EQ(a.groups, b.groups);
  EXPECT_EQ(a.warnings, b.warnings);
}

// The file read through its mapping with pages released, against its bytes read from memory;
// returns the mesh.
Mesh expect_same_reading(const std::string& stem, const std::string& bytes) {
  const TempFile file("_" + stem + ".mesh", bytes);
  MeshSource from_file, from_memory;
  const Mesh a = read_mesh(file.path(), &from_file);
  const Mesh b = read_mesh_bytes({bytes.data(), bytes.size()}, file.path(), &from_memory);
  expect_same_mesh(a, b);
  expect_same_source(from_file, from_memory);
  // The same through a mapping the test holds.
  const MappedFile mapped = MappedFile::open(file.path());
  EXPECT_TRUE(mapped.mapped());
  MeshSource explicit_source;
  const Mesh c = read_mesh(mapped, &explicit_source);
  expect_same_mesh(c, b);
  expect_same_source(explicit_source, from_memory);
  // The mapping still reads back the released bytes.
  EXPECT_EQ(std::memcmp(mapped.bytes().data(), bytes.data(), bytes.size()), 0);
  return a;
}

// The error message of reading `bytes` from a released mapping, which must equal the one from
// memory (file:line:column or byte offset, and the problem).
void expect_same_error(const std::string& stem, const std::string& bytes) {
  const TempFile file("_" + stem + ".mesh", bytes);
  std::string from_file, from_memory;
  try {
    read_mesh(file.path());
  } catch (const InputError& e) {
    from_file = e.what();
  }
  try {
    read_mesh_bytes({bytes.data(), bytes.size()}, file.path());
  } catch (const InputError& e) {
    from_memory = e.what();
  }
  EXPECT_FALSE(from_memory.empty());
  EXPECT_EQ(from_file, from_memory);
}

// A UV sphere of quads and triangle fans at the poles: about 10 MiB as OBJ.
Mesh big_polygon_mesh() {
  return test::uv_sphere(1.5, 300, 600);
}

TEST(ReadReleasePages, ObjWithPolygonsAndNegativeIndicesReadsAsFromMemory) {
  std::string text = write_mesh_bytes(big_polygon_mesh(), MeshFormat::obj);
  ASSERT_GT(text.size(), std::size_t{9} << 20);
  // A group, a quad and a triangle with relative (negative) indices after the released pages.
  text += "g tail\nv 0 0 9\nv 1 0 9\nv 1 1 9\nv 0 1 9\nf -4 -3 -2 -1\nf -4 -3 -2\n";
  const Mesh m = expect_same_reading("release_obj", text);
  const std::size_t n = m.vertices.size();
  ASSERT_GE(m.face_count(), 2u);
  EXPECT_EQ(m.face_size(m.face_count() - 2), 4u);
  EXPECT_EQ(m.face(m.face_count() - 1)[0], n - 4);
}

TEST(ReadReleasePages, ObjErrorsAfterReleasedPagesKeepTheirPositions) {
  const std::string text = write_mesh_bytes(big_polygon_mesh(), MeshFormat::obj);
  expect_same_error("release_obj_bad_number", text + "v 0 0 x\n");
  expect_same_error("release_obj_zero_index", text + "f 1 0 2\n");
  expect_same_error("release_obj_back_too_far", text + "f -1 -2 -999999999\n");
  // A forward index checked only at the end, reported at its own (released) position.
  const std::string forward = "f 1 2 999999999\n" + text;
  expect_same_error("release_obj_forward_index", forward);
  // A byte that is not ASCII, late in the file.
  expect_same_error("release_obj_bad_byte", text + "\xE9\n");
}

TEST(ReadReleasePages, PlyAsciiAndBinaryReadAsFromMemory) {
  const Mesh m = big_polygon_mesh();
  for (MeshFormat f : {MeshFormat::ply_ascii, MeshFormat::ply_binary_le, MeshFormat::ply_binary_be})
    for (bool single : {false, true}) {
      SCOPED_TRACE(std::string(format_name(f)) + (single ? " float" : " double"));
      WriteOptions w;
      w.single_precision = single;
      const std::string bytes = write_mesh_bytes(m, f, w);
      ASSERT_GT(bytes.size(), std::size_t{4} << 20);
      expect_same_reading("release_ply", bytes);
    }
}

TEST(ReadReleasePages, PlyErrorsAfterReleasedPagesKeepTheirPositions) {
  const Mesh m = big_polygon_mesh();
  const std::string ascii = write_mesh_bytes(m, MeshFormat::ply_ascii);
  // The last face's last index made out of range; then the file cut inside the last face.
  const std::size_t last_space = ascii.find_last_of(' ');
  expect_same_error("release_ply_index", ascii.substr(0, last_space) + " 99999999\n");
  expect_same_error("release_ply_ascii_cut", ascii.substr(0, last_space));
  const std::string le = write_mesh_bytes(m, MeshFormat::ply_binary_le);
  expect_same_error("release_ply_le_cut", le.substr(0, le.size() - 3));
  const std::string be = write_mesh_bytes(m, MeshFormat::ply_binary_be);
  expect_same_error("release_ply_be_cut", be.substr(0, be.size() - 3));
}

TEST(ReadReleasePages, StlAsciiAndOffReadAsFromMemory) {
  const Mesh tri = test::triangulated(test::uv_sphere(1.5, 100, 150));
  const std::string stl = write_mesh_bytes(tri, MeshFormat::stl_ascii);
  ASSERT_GT(stl.size(), std::size_t{5} << 20);
  expect_same_reading("release_stl_ascii", stl);
  expect_same_error("release_stl_ascii_bad", stl.substr(0, stl.rfind("endsolid")) + "facet x\n");
  const std::string off = write_mesh_bytes(big_polygon_mesh(), MeshFormat::off);
  // Data after the declared faces: a warning naming its (released) line.
  MeshSource source;
  read_mesh_bytes({off.data(), off.size()}, "mem", &source);
  EXPECT_TRUE(source.warnings.empty());
  expect_same_reading("release_off", off + "3 0 1 2\n");
  expect_same_error("release_off_bad", off.substr(0, off.find_last_of(' ')) + " 99999999\n");
  const std::string bin = write_mesh_bytes(tri, MeshFormat::stl_binary);
  expect_same_reading("release_stl_binary", bin);
}

TEST(ReadReleasePages, StreamedStlPassesReleaseAndSumTheSame) {
  const Mesh tri = test::triangulated(test::uv_sphere(1.5, 100, 150));
  const std::string ascii = write_mesh_bytes(tri, MeshFormat::stl_ascii);
  // The summing consumer of ASCII STL releases each piece once parsed: the same figures and
  // source as from memory, the mesh read's (a polygon facet at the end) up to rounding, and the
  // same error (after released pages) as the reader's.
  const std::size_t end = ascii.rfind("endsolid");
  const std::string quad = ascii.substr(0, end) +
                           "facet normal 0 0 1\nouter loop\nvertex 0 0 5\nvertex 1 0 5\n"
                           "vertex 1 1 5\nvertex 0 1 5\nendloop\nendfacet\n" +
                           ascii.substr(end);
  for (const std::string& text : {ascii, quad}) {
    const TempFile file("_release_summed_ascii.mesh", text);
    const MappedFile mapped = MappedFile::open(file.path());
    MeshSource released_source, kept_source, read_source;
    const MassProperties released =
        ascii_stl_mass_properties(mapped.bytes(), "f", released_source, {}, true);
    const MassProperties kept =
        ascii_stl_mass_properties({text.data(), text.size()}, "f", kept_source, {});
    expect_same_mass(released, kept);
    expect_same_source(released_source, kept_source);
    const Mesh m =
        detail::read_mesh_bytes(mapped.bytes(), "f", &read_source, MeshFormat::unknown, true);
    // The mesh read up to the last bits, about the same point (the quad leaves the surface open,
    // whose volume depends on it): the sums run about a sampled reference point, piece by piece
    // (stl_ascii_sums.hpp).
    const MassProperties read = mesh_mass_properties_from_sums(
        mesh_boundary_sums(m, released.reference_point), released.reference_point, m.vertices,
        m.face_count(), released.triangles, {}, false);
    EXPECT_NEAR(released.volume, read.volume, 1e-13 * read.volume);
    EXPECT_NEAR(released.area, read.area, 1e-13 * read.area);
    EXPECT_EQ(released.vertices, read.vertices);
    EXPECT_EQ(released.faces, read.faces);
    EXPECT_EQ(released.warnings, read.warnings);
    expect_same_source(released_source, read_source);
    EXPECT_EQ(released.faces, tri.face_count() + (text == quad ? 1 : 0));
    EXPECT_EQ(std::memcmp(mapped.bytes().data(), text.data(), text.size()), 0);
  }
  {
    const std::string bad = ascii.substr(0, end) + "facet x\n";
    const TempFile file("_release_summed_ascii_bad.mesh", bad);
    const MappedFile mapped = MappedFile::open(file.path());
    std::string summed_error, read_error;
    try {
      MeshSource source;
      ascii_stl_mass_properties(mapped.bytes(), "f", source, {}, true);
    } catch (const InputError& e) {
      summed_error = e.what();
    }
    try {
      read_mesh_bytes({bad.data(), bad.size()}, "f");
    } catch (const InputError& e) {
      read_error = e.what();
    }
    EXPECT_FALSE(read_error.empty());
    EXPECT_EQ(summed_error, read_error);
  }
  const std::string binary = write_mesh_bytes(tri, MeshFormat::stl_binary);
  const TempFile file("_release_streamed_binary.mesh", binary);
  const MappedFile mapped = MappedFile::open(file.path());
  const auto view = binary_stl_view(mapped.bytes(), "f");
  const auto memory_view = binary_stl_view({binary.data(), binary.size()}, "f");
  ASSERT_TRUE(view && memory_view);
  expect_same_mass(binary_stl_mass_properties(*view, "f", {}, true),
                   binary_stl_mass_properties(*memory_view, "f", {}));
}

}  // namespace
}  // namespace pgamesh
