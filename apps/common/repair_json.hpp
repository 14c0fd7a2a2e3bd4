// The JSON of `pgamesh repair`, built in one place for the CLI and the viewer's Repair action.
// Field definitions: docs/topology.md, "Repair".
#pragma once

#include <cstddef>
#include <string>

#include "json_text.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/mesh/repair/repair.hpp"

namespace pgamesh::cli {

// The report of one repair: what changed (the first `list_cap` holes), and `result`, the front
// door's verdict on the repaired mesh (analyze_mesh with topology). `output` names where the mesh
// went (a file, or the viewer's id).
Json repair_fields(const MeshSource& source, const RepairReport& report, const Analysis& result,
                   std::size_t list_cap, const std::string& output);

}  // namespace pgamesh::cli
