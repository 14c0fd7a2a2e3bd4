// Duplicated faces: faces with the same set of welded vertices as an earlier face, in either
// orientation. Same orientation counts their volume twice, opposite orientation cancels it; either
// way the mesh's volume is not what it looks like.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/topology/edges.hpp"

namespace pgamesh {

// (face, earliest earlier face with the same welded vertex set), ascending by face. Candidates are
// the faces along each face's first edge, so the search is linear; a polygon whose vertex set
// repeats in a different cyclic order that shares no edge with it is not found (two triangles with
// the same vertices always share all their edges).
std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicated_faces(
    const Mesh& mesh, const EdgeTable& edges, std::span<const std::uint32_t> welded_corner);

}  // namespace pgamesh
