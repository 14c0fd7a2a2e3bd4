#include "fuel_model.hpp"

#include <cstdio>
#include <stdexcept>

#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh::viewer {

namespace {

std::shared_ptr<const FuelModel> build(const StoredMesh& stored) {
  auto model = std::make_shared<FuelModel>();
  // The tank of `pgamesh fuel --weld-tolerance`: the mesh welded as the analyses see it.
  const Mesh welded_mesh =
      stored.weld_tolerance > 0 ? weld(stored.mesh, stored.weld_tolerance).mesh : Mesh{};
  const Mesh& mesh = stored.weld_tolerance > 0 ? welded_mesh : stored.mesh;
  try {
    model->tank = tank::make_tank(mesh);
  } catch (const std::invalid_argument& e) {
    model->problem = stored.name + ": " + e.what();
    return model;
  }
  const tank::Tank& t = model->tank;
  // The rule of `pgamesh fuel` (tank::tank_fitness), with its reasons.
  const tank::TankFitness fitness = tank::tank_fitness(mesh, t);
  if (!fitness.fit) {
    model->problem = stored.name + ": not a closed, outward-oriented tank";
    for (const auto& problem : fitness.problems) model->problem += "; " + problem;
    return model;
  }
  model->index = std::make_unique<tank::FuelIndex>(model->tank);
  return model;
}

}  // namespace

std::shared_ptr<const FuelModel> fuel_model(const StoredMesh& stored) {
  std::lock_guard lock(stored.cache_mutex);
  if (!stored.fuel) stored.fuel = build(stored);
  return stored.fuel;
}

}  // namespace pgamesh::viewer
