// Closed test solids built in code, outward and counter-clockwise seen from outside, with
// polygons kept as polygons: boxes (quads), tetrahedra, UV spheres (quads with triangle caps),
// and the transformations the invariance tests apply.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::test {

// The box [0,a]×[0,b]×[0,c] as six quads.
Mesh box_mesh(double a, double b, double c);

// The tetrahedron (p0, p1, p2, p3), oriented outward whatever the order of the points.
Mesh tetrahedron_mesh(Vec3d p0, Vec3d p1, Vec3d p2, Vec3d p3);

// The sphere of radius r about the origin: `stacks` bands of `slices` quads (triangles at the
// poles), vertices on the sphere.
Mesh uv_sphere(double r, int stacks, int slices);

// A copy with every vertex mapped by f.
Mesh transformed(const Mesh& m, const std::function<Vec3d(Vec3d)>& f);

// A copy with every face's corner order reversed (all normals flipped).
Mesh flipped(const Mesh& m);

// A copy with the polygons fanned into triangles about their first corner.
Mesh triangulated(const Mesh& m);

// The largest |m_ij|: the scale of an inertia tensor, for relative tolerances.
inline double max_abs(const Mat3& m) {
  double s = 0;
  for (const auto& row : m)
    for (double v : row) s = std::max(s, std::abs(v));
  return s;
}

}  // namespace pgamesh::test
