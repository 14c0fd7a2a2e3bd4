// The point about which a mesh's carriers are accumulated. PGA leaves the origin free, so sums are
// formed from coordinates relative to a point near the mesh: that keeps every digit however far
// the mesh lies from the coordinate origin (docs/conventions.md §13). Mass properties, topology and
// fuel slicing all take it from here.
#pragma once

#include <span>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

// The centre of the bounding box of the mesh's vertices (the origin for a mesh without vertices).
Vec3d reference_point(const Mesh& mesh);

// The same point for the vertices a reader has kept (a summing consumer builds no Mesh).
Vec3d reference_point(std::span<const Vec3d> vertices);

}  // namespace pgamesh
