// `pgamesh props FILE` reads a mapped file, giving its pages back as the readers and the fused STL
// passes consume them, and frees a triangle mesh once welded; `pgamesh props - < FILE` reads the
// same bytes from a pipe into a buffer of its own, where nothing is released. Both must print the
// same report, field for field, and the same errors — on files of several MiB, so that pages are
// released before the data that decides the figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

using pgamesh::test::CliRun;
using pgamesh::test::json;
using pgamesh::test::parse_json;
using pgamesh::test::run_cli;
using pgamesh::test::TempFile;

namespace {

// The report of the mapped file and of the same bytes through a pipe, with `flags`: equal but for
// the file name. The search for intersecting faces runs on the welded mesh, after every page is
// released; it has its own tests (test_self_intersections_cli.cpp), and is left out here.
void expect_same_props(const std::string& bytes, const std::string& flags) {
  SCOPED_TRACE(flags);
  const TempFile file(".mesh", bytes);
  const std::string& path = file.path();
  const std::string options = " --json --no-self-intersections " + flags;
  const CliRun mapped = run_cli("props \"" + path + "\"" + options);
  const CliRun piped = run_cli("props -" + options, path);
  ASSERT_EQ(mapped.status, 0) << mapped.err;
  ASSERT_EQ(piped.status, 0) << piped.err;
  json a = parse_json(mapped.out), b = parse_json(piped.out);
  EXPECT_EQ(a["file"], path);
  EXPECT_EQ(b["file"], "-");
  a.erase("file");
  b.erase("file");
  EXPECT_EQ(a, b);  // every number printed with %.17g: equal bit for bit
  // Warnings may name the file; none are expected for these meshes.
  EXPECT_TRUE(a["warnings"].empty()) << a["warnings"];
}

pgamesh::Mesh big_triangles() {
  return pgamesh::test::triangulated(pgamesh::test::uv_sphere(1.5, 200, 400));
}

TEST(PropsRelease, TextFormatsWithAndWithoutTopology) {
  const pgamesh::Mesh tri = big_triangles();
  for (pgamesh::MeshFormat f :
       {pgamesh::MeshFormat::obj, pgamesh::MeshFormat::ply_ascii, pgamesh::MeshFormat::stl_ascii}) {
    SCOPED_TRACE(pgamesh::format_name(f));
    // ASCII STL spends ~250 bytes a facet: a coarser sphere gives it the same few MiB.
    const std::string bytes = pgamesh::write_mesh_bytes(
        f == pgamesh::MeshFormat::stl_ascii
            ? pgamesh::test::triangulated(pgamesh::test::uv_sphere(1.5, 100, 150))
            : tri,
        f);
    ASSERT_GT(bytes.size(), std::size_t{6} << 20);
    expect_same_props(bytes, "");
    expect_same_props(bytes, "--no-topology");
  }
}

TEST(PropsRelease, BinaryFormatsAndToleranceWeld) {
  const pgamesh::Mesh tri = big_triangles();
  pgamesh::WriteOptions single;
  single.single_precision = true;
  for (pgamesh::MeshFormat f :
       {pgamesh::MeshFormat::ply_binary_le, pgamesh::MeshFormat::ply_binary_be,
        pgamesh::MeshFormat::stl_binary}) {
    SCOPED_TRACE(pgamesh::format_name(f));
    const std::string bytes = pgamesh::write_mesh_bytes(tri, f, single);
    expect_same_props(bytes, "");
    expect_same_props(bytes, "--no-topology");
  }
  expect_same_props(pgamesh::write_mesh_bytes(tri, pgamesh::MeshFormat::ply_binary_le),
                    "--weld-tolerance 1e-9");
}

TEST(PropsRelease, PolygonsNegativeIndicesAndUnweldedTriangles) {
  // Quads and pole triangles (the polygon layout of the topology pass), then relative indices.
  std::string obj =
      pgamesh::write_mesh_bytes(pgamesh::test::uv_sphere(1.5, 220, 440), pgamesh::MeshFormat::obj);
  obj += "v 0 0 9\nv 1 0 9\nv 0 1 9\nf -3 -1 -2\n";
  expect_same_props(obj, "");
  expect_same_props(obj, "--no-topology");
  // STL facets weld 6 : 1, and an OBJ of the same unshared triangles.
  std::string unshared_obj;
  const pgamesh::Mesh tri = big_triangles();
  pgamesh::Mesh unshared;
  for (std::uint32_t c : tri.corners) {
    unshared.vertices.push_back(tri.vertices[c]);
    unshared.corners.push_back(static_cast<std::uint32_t>(unshared.corners.size()));
    if (unshared.corners.size() % 3 == 0)
      unshared.face_offsets.push_back(static_cast<std::uint32_t>(unshared.corners.size()));
  }
  expect_same_props(pgamesh::write_mesh_bytes(unshared, pgamesh::MeshFormat::obj), "");
}

TEST(PropsRelease, ErrorsKeepTheirPositions) {
  const std::string obj = pgamesh::write_mesh_bytes(big_triangles(), pgamesh::MeshFormat::obj);
  const std::string bad = obj + "f 1 2 0\n";
  const TempFile file(".obj", bad);
  const std::string& path = file.path();
  for (const char* flags : {"", "--no-topology"}) {
    const CliRun mapped = run_cli(std::string("props \"") + path + "\" " + flags);
    const CliRun piped = run_cli(std::string("props - ") + flags, path);
    EXPECT_EQ(mapped.status, 1);
    EXPECT_EQ(piped.status, 1);
    const std::size_t at = mapped.err.find(path);
    ASSERT_NE(at, std::string::npos) << mapped.err;
    EXPECT_EQ(mapped.err.substr(0, at) + "-" + mapped.err.substr(at + path.size()), piped.err);
    // The zero index sits on the last line, after the released pages.
    const auto lines = std::count(bad.begin(), bad.end(), '\n');
    std::string where = ":";  // built in steps: GCC 12 misreads ":" + to_string(...) (-Wrestrict)
    where += std::to_string(lines);
    where += ":7:";
    EXPECT_NE(mapped.err.find(where), std::string::npos) << mapped.err;
  }
}

// Without topology a PLY's faces are summed as they are parsed, never stored: the whole report
// must be the one of the same mesh read into a Mesh first (an OBJ of the same doubles), and an
// error late in a mapped file the careful reader's, byte offset included.
TEST(PropsRelease, PlyWithoutAFaceListReportsAsTheMeshPath) {
  const pgamesh::Mesh mesh = pgamesh::test::uv_sphere(1.5, 200, 400);  // quads and triangles
  auto report = [](const std::string& bytes, const std::string& what) {
    const TempFile file(what, bytes);
    const CliRun r = run_cli("props \"" + file.path() + "\" --json --no-topology");
    EXPECT_EQ(r.status, 0) << r.err;
    json j = parse_json(r.out);
    j.erase("file");
    j.erase("format");
    return j;
  };
  const json expected = report(pgamesh::write_mesh_bytes(mesh, pgamesh::MeshFormat::obj), ".obj");
  EXPECT_EQ(expected["faces"], mesh.face_count());
  for (pgamesh::MeshFormat f : {pgamesh::MeshFormat::ply_ascii, pgamesh::MeshFormat::ply_binary_le,
                                pgamesh::MeshFormat::ply_binary_be}) {
    SCOPED_TRACE(pgamesh::format_name(f));
    EXPECT_EQ(report(pgamesh::write_mesh_bytes(mesh, f), ".ply"), expected);
  }

  // A vertex index out of range in the last face, after pages already given back.
  std::string bad = pgamesh::write_mesh_bytes(mesh, pgamesh::MeshFormat::ply_binary_le);
  bad[bad.size() - 2] = 0x7f;  // the last index's high byte
  const TempFile file(".ply", bad);
  const std::string& path = file.path();
  std::string expected_error;
  try {
    pgamesh::read_mesh_bytes({bad.data(), bad.size()}, path);
  } catch (const pgamesh::InputError& e) {
    expected_error = std::string("pgamesh props: ") + e.what() + "\n";
  }
  ASSERT_NE(expected_error.find("out of range"), std::string::npos) << expected_error;
  const CliRun mapped = run_cli("props \"" + path + "\" --no-topology");
  EXPECT_EQ(mapped.status, 1);
  EXPECT_EQ(mapped.err, expected_error);
}

}  // namespace
