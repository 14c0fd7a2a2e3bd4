// The JSON of `pgamesh check`, built in one place so that the CLI and the viewer could serve the
// same document. Field definitions: docs/json.md.
#pragma once

#include <cstddef>
#include <string>

#include "json_text.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::cli {

struct CheckJsonOptions {
  std::size_t list_cap = 20;        // entries per location list (loops, edges, faces, components)
  std::size_t loop_point_cap = 20;  // points listed per boundary loop
};

// The check report's fields as one object. `analysis` is the analysis of `mesh` with its topology
// (analyze_mesh with topology on): its topology report is the one described, its volume_valid,
// reasons and warnings are those of `pgamesh props`. `mesh` gives the loops' coordinates; `fix` is
// the orientation repair when one was made.
Json check_fields(const Mesh& mesh, const MeshSource& source, const Analysis& analysis,
                  const OrientationFix* fix, const CheckJsonOptions& options = {});

// The whole `pgamesh check --json` document (one line and a newline).
std::string check_json(const Mesh& mesh, const MeshSource& source, const Analysis& analysis,
                       const OrientationFix* fix, const CheckJsonOptions& options = {});

}  // namespace pgamesh::cli
