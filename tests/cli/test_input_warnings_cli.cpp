// The warnings about the input that every command gives alike (the front door's
// Analysis::warnings, in props, check and fuel): float32 coordinates far from the origin, and
// polygon faces that are not planar — whose area is then the one face area of every command.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"

namespace pgamesh::test {
namespace {

// A box of side 1/64 at x = 2^14, where float32 spacing is 2^-10: 6% of the part.
std::string far_float32_box() {
  const Mesh box = transformed(box_mesh(1.0 / 64, 1.0 / 64, 1.0 / 64), [](Vec3d v) {
    return v + Vec3d{16384, 0, 0};
  });
  return write_mesh_bytes(box, MeshFormat::stl_binary);
}

constexpr const char* warning = "float32 coordinates reach";

TEST(Float32WarningCli, EveryCommandWarnsInItsText) {
  const TempFile file(".stl", far_float32_box());
  const std::string path = " \"" + file.path() + "\"";
  for (const std::string& args : {"props" + path, "check" + path, "fuel" + path + " --fraction 0.5",
                                  "fuel" + path + " --table 2 --csv", "props" + path + " --urdf"}) {
    SCOPED_TRACE(args);
    const CliRun r = run_cli(args);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE((r.out + r.err).find(warning), std::string::npos) << r.out << r.err;
  }
}

TEST(Float32WarningCli, EveryCommandWarnsInItsJson) {
  const TempFile file(".stl", far_float32_box());
  const std::string path = " \"" + file.path() + "\" --json";
  for (const std::string& args :
       {"props" + path, "check" + path, "fuel" + path + " --level 0.005"}) {
    SCOPED_TRACE(args);
    const CliRun r = run_cli(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const json j = parse_json(r.out);
    ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
    EXPECT_EQ(j["warnings"][0].get<std::string>().rfind(warning, 0), 0u) << j["warnings"];
  }
}

// A closed UV sphere whose vertices are moved in and out at random: its quads are bent by up to a
// few per cent of their size.
Mesh lumpy_sphere() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.9, 1.1);
  Mesh m = uv_sphere(1, 8, 12);
  for (Vec3d& v : m.vertices) v = u(rng) * v;
  return m;
}

TEST(NonplanarFacesCli, EveryCommandWarnsAndMeasuresOneArea) {
  const Mesh lumpy = lumpy_sphere();
  for (MeshFormat format : {MeshFormat::obj, MeshFormat::ply_binary_le}) {
    const std::string ext = format == MeshFormat::obj ? ".obj" : ".ply";
    const TempFile file(ext, write_mesh_bytes(lumpy, format));
    SCOPED_TRACE(ext);
    const std::string path = " \"" + file.path() + "\" --json";
    double area = 0;
    for (const std::string& args : {"props" + path, "props" + path + " --no-topology",
                                    "check" + path, "fuel" + path + " --fraction 1"}) {
      SCOPED_TRACE(args);
      const CliRun r = run_cli(args);
      ASSERT_EQ(r.status, 0) << r.err;
      const json j = parse_json(r.out);
      ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"];
      const std::string w = j["warnings"][0].get<std::string>();
      // 8 × 12 faces, of which the 2 × 12 at the poles are triangles.
      EXPECT_EQ(w.rfind("72 polygon faces are not planar", 0), 0u) << w;
      // The full tank's wetted wall is the whole surface: the same signed fan area as props.
      const double a =
          j.contains("wetted_area") ? j["wetted_area"].get<double>() : j["area"].get<double>();
      if (area == 0) area = a;
      EXPECT_NEAR(a, area, 1e-13 * area);
    }
    // The fan triangles' areas, summed here: every quad of this sphere is convex enough that no
    // fan triangle folds.
    double fan = 0;
    for (std::size_t f = 0; f < lumpy.face_count(); ++f) {
      const std::uint32_t* c = lumpy.face(f);
      for (std::size_t i = 1; i + 1 < lumpy.face_size(f); ++i)
        fan += length(cross(lumpy.vertices[c[i]] - lumpy.vertices[c[0]],
                            lumpy.vertices[c[i + 1]] - lumpy.vertices[c[0]])) /
               2;
    }
    EXPECT_NEAR(area, fan, 1e-13 * fan);
  }
}

}  // namespace
}  // namespace pgamesh::test
