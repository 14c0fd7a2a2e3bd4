// Internal: the signs of the orientation determinants of points with double coordinates, exactly
// (docs/topology.md, "Self-intersections"). A floating-point filter answers when the rounded
// determinant is farther from 0 than its error bound (Shewchuk 1997, "Adaptive precision
// floating-point arithmetic and fast robust geometric predicates", the bounds of orient2d and
// orient3d stage A); otherwise the determinant is evaluated exactly in expansion arithmetic (the
// same paper: Two-Sum, Two-Product by fused multiply-add, Grow-Expansion, Scale-Expansion).
// Exact for coordinates whose products neither overflow nor fall into the subnormal range (|x|
// between about 1e-100 and 1e100, or 0); the mass properties refuse far smaller extremes first.
#pragma once

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::detail {

// Sign (−1, 0, +1) of det[b − a, c − a] = (b − a) × (c − a): +1 when a, b, c turn
// counter-clockwise.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

// Sign of det[b − a, c − a, d − a] = ((b − a) × (c − a)) · (d − a): +1 when d lies on the side
// the normal of the triangle a, b, c (counter-clockwise) points to.
int orient3d(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d);

// orient2d of a, b, c projected on the coordinate plane without axis `drop` (the axes that remain
// in cyclic order: drop z → (x, y), drop x → (y, z), drop y → (z, x)).
int orient2d_without(int drop, const Vec3d& a, const Vec3d& b, const Vec3d& c);

// Whether a, b, c are exactly collinear (or coincide): every projection's orient2d is 0.
bool collinear(const Vec3d& a, const Vec3d& b, const Vec3d& c);

}  // namespace pgamesh::detail
