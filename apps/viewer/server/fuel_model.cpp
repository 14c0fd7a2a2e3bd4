#include "fuel_model.hpp"

#include <cstdio>
#include <stdexcept>

namespace pgamesh::viewer {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::shared_ptr<const FuelModel> build(const StoredMesh& stored) {
  auto model = std::make_shared<FuelModel>();
  try {
    model->tank = tank::make_tank(stored.mesh);
  } catch (const std::invalid_argument& e) {
    model->problem = stored.name + ": " + e.what();
    return model;
  }
  const tank::Tank& t = model->tank;
  // The same test and words as `pgamesh fuel` (tank::is_gaugeable: closed within 1e-9 of the
  // area, positive volume).
  if (!tank::is_gaugeable(t)) {
    if (t.gap_area > 1e-9 * t.area)
      model->problem = stored.name + ": the mesh is open (gap area " + fmt(t.gap_area) + ", " +
                       fmt(t.gap_area / t.area) +
                       " of its area): fuel needs a closed, outward-oriented tank";
    else
      model->problem = stored.name + ": the mesh is inside out or flat (signed volume " +
                       fmt(t.volume) + "): fuel needs a closed, outward-oriented tank";
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
