// `pgamesh props` on a 3MF file: the unit the file states printed with the figures, and each build
// item reported alone beside the whole (text and JSON, docs/json.md "unit" and "parts").
#include <gtest/gtest.h>

#include <string>

#include "pgamesh/io/write_mesh.hpp"
#include "support/cli_run.hpp"
#include "support/golden.hpp"
#include "support/solids.hpp"
#include "support/temp_file.hpp"
#include "support/threemf_package.hpp"

namespace pgamesh::test {
namespace {

// Boxes 1×2×3 ("a") and 2×2×2 ("b", moved by 10 along x), in inches.
std::string two_boxes_in_inches() {
  return threemf_package(threemf_model(
      threemf_box(1, 1, 2, 3, "a") + threemf_box(2, 2, 2, 2, "b"),
      "<item objectid=\"1\"/>\n<item objectid=\"2\" transform=\"1 0 0 0 1 0 0 0 1 10 0 0\"/>\n",
      "unit=\"inch\""));
}

TEST(Props3mfCli, TextGivesTheUnitAndEachBuildItem) {
  const TempFile file(".3mf", two_boxes_in_inches());
  const CliRun r = run_cli("props \"" + file.path() + "\"");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* expected :
       {"unit              in", "volume            14 in^3", "area              46 in^2",
        "parts             2", "1 'a': 12 faces, area 22 in^2, volume 6 in^3",
        "2 'b': 12 faces, area 24 in^2, volume 8 in^3", "centre of mass 11 1 1 in"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
}

TEST(Props3mfCli, JsonAddsUnitAndPartsKeepingTheOtherKeys) {
  const TempFile file(".3mf", two_boxes_in_inches());
  const CliRun r = run_cli("props \"" + file.path() + "\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse_json(r.out);
  EXPECT_EQ(j["unit"], "in");
  EXPECT_EQ(j["format"], "3mf");
  EXPECT_DOUBLE_EQ(j["volume"].get<double>(), 14.0);
  EXPECT_EQ(j["closed"], true);
  ASSERT_EQ(j["parts"].size(), 2u);
  EXPECT_EQ(j["parts"][0]["name"], "a");
  EXPECT_DOUBLE_EQ(j["parts"][0]["volume"].get<double>(), 6.0);
  EXPECT_EQ(j["parts"][1]["first_face"], 12);
  EXPECT_DOUBLE_EQ(j["parts"][1]["volume"].get<double>(), 8.0);
  EXPECT_DOUBLE_EQ(j["parts"][1]["center_of_mass"][0].get<double>(), 11.0);
  EXPECT_EQ(j["parts"][1]["closed"], true);
  EXPECT_EQ(j["parts"][1]["components"], 1);
}

TEST(Props3mfCli, FilesWithoutAUnitAreUnitlessAndHaveNoParts) {
  const TempFile file(".obj", write_mesh_bytes(box_mesh(1, 2, 3), MeshFormat::obj));
  const CliRun text = run_cli("props \"" + file.path() + "\"");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("\nunit              unitless"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("^3"), std::string::npos) << text.out;
  const json j = parse_json(run_cli("props \"" + file.path() + "\" --json").out);
  EXPECT_EQ(j["unit"], "unitless");
  EXPECT_TRUE(j["parts"].empty());
}

}  // namespace
}  // namespace pgamesh::test
