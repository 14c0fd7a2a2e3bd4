// The tank tests read golden and shared OBJ meshes with the test support's plain OBJ reader
// (load_obj_file, load_golden_obj), independent of pgamesh's readers; and share two small helpers.
#pragma once

#include <random>

#include "pgamesh/core/vec3.hpp"
#include "support/golden.hpp"
#include "support/golden_mesh.hpp"

namespace pgamesh::test {

// A golden file's [x, y, z].
inline Vec3d json_vec3(const json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

// A direction drawn uniformly on the unit sphere (normalised Gaussian triple).
inline Vec3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3d u{g(rng), g(rng), g(rng)};
  return u / length(u);
}

}  // namespace pgamesh::test
