// The JSON of `pgamesh check` (DESIGN.md §5), built in one place so that the CLI and the viewer
// serve the same document. Field definitions: docs/topology.md.
#pragma once

#include <cstddef>
#include <string>

#include "json_writer.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::cli {

struct CheckJsonOptions {
  std::size_t list_cap = 20;        // entries per location list (loops, edges, faces, components)
  std::size_t loop_point_cap = 20;  // points listed per boundary loop
};

// Writes the check report's fields into the object `json` is currently inside. `mesh` is the mesh
// the report describes (for loop coordinates); `fix` is the orientation repair when one was made.
void write_check_fields(JsonWriter& json, const Mesh& mesh, const MeshSource& source,
                        const TopologyReport& report, const OrientationFix* fix,
                        const CheckJsonOptions& options = {});

// The whole `pgamesh check --json` document.
std::string check_json(const Mesh& mesh, const MeshSource& source, const TopologyReport& report,
                       const OrientationFix* fix, const CheckJsonOptions& options = {});

}  // namespace pgamesh::cli
