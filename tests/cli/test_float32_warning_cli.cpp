// Every command that reads a float32 file far from the origin warns that its coordinates carry
// float32 rounding: the front door's warning (Analysis::warnings), in props, check and fuel alike.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace pgamesh::test
