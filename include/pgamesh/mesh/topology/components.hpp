// Connected components of a welded mesh: faces are connected when they share an edge (any edge,
// manifold or not). Collapsed faces (fewer than three distinct welded vertices) have no edges and
// belong to no component.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh {

struct FaceComponents {
  std::vector<std::uint32_t> face_component;  // face → component, or no_edge for collapsed faces
  std::vector<std::uint32_t> first_face;      // component → its lowest face index
  std::vector<std::uint32_t> face_count;      // component → number of faces

  std::size_t count() const { return first_face.size(); }
};

// Components numbered by their lowest face index (deterministic), by union–find over the edges.
FaceComponents face_components(const Mesh& mesh, const EdgeTable& edges);

}  // namespace pgamesh
