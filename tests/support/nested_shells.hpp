// Meshes of several closed shells inside one another, for orientation by nesting
// (docs/conventions.md §8): cubes about a common centre, and polyhedral tori.
#pragma once

#include <initializer_list>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::test {

// The cube of side `side` centred on `centre`, six quads, facing out (positive volume) or in.
Mesh centred_cube(double side, Vec3d centre, bool outward);

// The torus about the z axis through `centre`: tube radius `minor` about the circle of radius
// `major`, `around` × `across` quads on the tube's surface, facing out or in.
Mesh torus_mesh(double major, double minor, int around, int across, Vec3d centre, bool outward);

// The shells' faces, in the order given, in one mesh (no vertex shared between shells).
Mesh joined(std::initializer_list<Mesh> shells);

}  // namespace pgamesh::test
