// The fuel API: GET /api/mesh/ID/fuel?pitch=&roll=&(level=|volume=) and
// GET /api/mesh/ID/fuel/table?pitch=&roll=&n= — the library's fuel queries (hierarchy, inverse
// gauge, sorted sweep) for a tank at an attitude, in the JSON fields of `pgamesh fuel --json`
// (apps/cli/fuel_json.hpp writes them for both).
#pragma once

#include <httplib.h>

#include "mesh_store.hpp"

namespace pgamesh::viewer {

/// Registers the fuel routes on `svr`; `store` must outlive the server.
void add_fuel_routes(httplib::Server& svr, MeshStore& store);

}  // namespace pgamesh::viewer
