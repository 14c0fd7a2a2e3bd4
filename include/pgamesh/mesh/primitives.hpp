// Closed, outward-oriented (CCW seen from outside) triangle meshes of simple solids, for tests,
// examples and benchmarks. Every solid is centred on the origin with its axis along z.
#pragma once

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

/// The icosahedron subdivided `level` times (each triangle into four), vertices pushed onto the
/// sphere of radius r: 20·4^level triangles. level ≤ 10.
Mesh icosphere(int level, double radius);

/// The box [−a/2, a/2] × [−b/2, b/2] × [−c/2, c/2]: 8 vertices, 12 triangles.
Mesh box(double a, double b, double c);

/// The prism over a regular `segments`-gon inscribed in the circle of radius r, z ∈ [−h/2, h/2],
/// its side cut into `rings` bands; the ends are fans around their centres. Its exact volume is
/// (segments/2) r² sin(2π/segments) h.
Mesh cylinder(double radius, double height, int segments, int rings);

/// A cylinder of radius r and length `length` (z ∈ [−length/2, length/2]) closed by two
/// hemispheres, each cut into `rings` latitude bands of `segments` quads.
Mesh capsule(double radius, double length, int segments, int rings);

}  // namespace pgamesh
