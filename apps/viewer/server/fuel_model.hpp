// A mesh made ready for fuel queries, built once per stored mesh on first use: the library's tank
// (triangles, reference point, whole-tank sums) and its hierarchy of accumulated sums, or the
// reason the mesh cannot be gauged (open, inside out, empty).
#pragma once

#include <memory>
#include <string>

#include "mesh_store.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/tank.hpp"

namespace pgamesh::viewer {

struct FuelModel {
  tank::Tank tank;
  std::unique_ptr<tank::FuelIndex> index;  // refers to `tank`: the model is never copied
  std::string problem;                     // non-empty: not a gaugeable tank, and why
};

/// The fuel model of a stored mesh, built on first use and shared afterwards (thread-safe).
std::shared_ptr<const FuelModel> fuel_model(const StoredMesh& stored);

}  // namespace pgamesh::viewer
