// Reading the golden JSON of tests/data/golden (docs/conventions.md §18) and comparing with the
// golden rule: |got − expected| ≤ abs + rel · scale, scale = max |expected| of the group.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pgamesh::test {

using json = nlohmann::json;

// The two JSON parses are compiled once, in golden.cpp: nlohmann's parser is the costliest template
// a test file would otherwise instantiate (seconds per file optimised, tens of seconds under the
// sanitizers), and many test files read JSON.

/// Parses JSON text (e.g. the CLI's --json output); throws json::parse_error when it is not JSON.
json parse_json(const std::string& text);

/// Reads and parses the golden file NAME in tests/data/golden; throws std::runtime_error when it
/// cannot be opened and json::parse_error when it is not JSON.
json load_golden(const std::string& name);

struct Tolerance {
  double rel = 1e-12, abs = 1e-12;
};

inline Tolerance tolerance_of(const json& file, const json& c) {
  Tolerance t;
  if (file.contains("tolerance_default")) {
    t.rel = file["tolerance_default"].value("rel", t.rel);
    t.abs = file["tolerance_default"].value("abs", t.abs);
  }
  if (c.contains("tolerance") && c["tolerance"].is_object()) {
    t.rel = c["tolerance"].value("rel", t.rel);
    t.abs = c["tolerance"].value("abs", t.abs);
  }
  return t;
}

// Compares a group of values (array, matrix flattened, or blade dictionary) as one.
inline ::testing::AssertionResult near_group(const std::vector<double>& got,
                                             const std::vector<double>& expected, Tolerance t) {
  if (got.size() != expected.size())
    return ::testing::AssertionFailure() << "size " << got.size() << " != " << expected.size();
  double scale = 0;
  for (double e : expected) scale = std::max(scale, std::abs(e));
  for (std::size_t i = 0; i < got.size(); ++i) {
    const double err = std::abs(got[i] - expected[i]);
    if (!(err <= t.abs + t.rel * scale))
      return ::testing::AssertionFailure()
             << "component " << i << ": got " << got[i] << ", expected " << expected[i]
             << " (error " << err << ", allowed " << t.abs + t.rel * scale << ")";
  }
  return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult near_scalar(double got, double expected, Tolerance t) {
  return near_group({got}, {expected}, t);
}

// Flattens a JSON number, array or nested array (matrix) into a vector.
inline std::vector<double> flatten(const json& j) {
  std::vector<double> out;
  if (j.is_number()) {
    out.push_back(j.get<double>());
  } else if (j.is_array()) {
    for (const auto& e : j) {
      auto sub = flatten(e);
      out.insert(out.end(), sub.begin(), sub.end());
    }
  }
  return out;
}

// A blade dictionary {"e01": 2.0, ...} as a map (missing keys are zero).
inline std::map<std::string, double> blades(const json& j) {
  std::map<std::string, double> out;
  for (auto it = j.begin(); it != j.end(); ++it) out[it.key()] = it.value().get<double>();
  return out;
}

// The folder of real meshes: tests/data/meshes (always there), merged at configure time with
// ../shared/meshes when that folder exists beside the clone (tests/CMakeLists.txt); empty only
// when the build has none.
inline std::string shared_meshes_dir() {
  const std::filesystem::path p(PGAMESH_SHARED_MESHES_DIR);
  return std::filesystem::is_directory(p) ? p.string() : std::string();
}

// Whether the real mesh `relative` is there: the files under GPL or without a stated licence are
// not shipped in tests/data/meshes and come only with ../shared/meshes.
inline bool has_real_mesh(const std::string& relative) {
  return std::filesystem::exists(std::string(PGAMESH_SHARED_MESHES_DIR) + "/" + relative);
}

}  // namespace pgamesh::test

// Skips the test, visibly, unless every named real mesh is there (has_real_mesh).
#define REQUIRE_REAL_MESHES(...)                        \
  for (const char* required_mesh : {__VA_ARGS__})       \
    if (!::pgamesh::test::has_real_mesh(required_mesh)) \
  GTEST_SKIP() << required_mesh << " is not bundled (its licence): it comes with ../shared/meshes"

// For an extra test of one third-party file that is not bundled (its licence): skipped, and said
// so, unless every named real mesh is there. The property it checks is covered on a lone clone by a
// test of a mesh of our own, which never skips.
#define EXTRA_WITH_REAL_MESHES(...)                                                           \
  for (const char* extra_mesh : {__VA_ARGS__})                                                \
    if (!::pgamesh::test::has_real_mesh(extra_mesh))                                          \
  GTEST_SKIP() << "extra test of " << extra_mesh                                              \
               << " (not bundled, comes with ../shared/meshes); its property is tested on a " \
                  "mesh of our own"

namespace pgamesh::test {}  // namespace pgamesh::test
