// Least-squares fits of spheres, planes and cylinders to points (docs/models-cga.md §8), used by
// `pgamesh fit`. Each returns the shape's parameters and the RMS and largest distance of the
// points from the fitted surface, and throws ModelError for too few points, non-finite
// coordinates and degenerate point sets.
#pragma once

#include <cstddef>
#include <span>

#include "pgamesh/core/vec3.hpp"
#include "pgamesh/models/cga_algebra.hpp"

namespace pgamesh::cga {

struct SphereFit {
  Vec3d center;
  double radius = 0;
  double rms = 0;        // sqrt(mean of (|x − c| − r)²)
  double max_error = 0;  // max |(|x − c| − r)|
  Vector dual_sphere;    // the fitted σ = up(c) − ½ r² e_∞ (weight 1)
};

struct PlaneFit {
  Vec3d point;           // the centroid of the points (on the plane)
  Vec3d normal;          // unit; its largest-magnitude component is positive
  double distance = 0;   // signed distance from the origin: normal · x = distance
  double rms = 0;        // of the signed distances of the points from the plane
  double max_error = 0;  // largest |distance|
  Vector dual_plane;     // n̂ + δ e_∞
};

struct CylinderFit {
  Vec3d axis_point;      // the point of the axis nearest the centroid of the points
  Vec3d axis_direction;  // unit; its largest-magnitude component is positive
  double radius = 0;
  double rms = 0;  // of |distance to the axis| − radius
  double max_error = 0;
  int iterations = 0;  // Gauss–Newton (Levenberg–Marquardt) steps taken
};

// The conformal (linear) sphere fit: the dual sphere S minimising Σ (X_i · S)² subject to
// S² = 1 (Hitzer eq. 50's σ with ρ² w² = 1; Pratt's normalisation), a 5×5 generalised symmetric
// eigenproblem, solved about the centroid with the points scaled to unit RMS spread. Needs at
// least 4 points not all on one plane (for coplanar points the best "sphere" is the plane: use
// fit_plane).
SphereFit fit_sphere(std::span<const Vec3d> points);

// Total least squares: the centroid and the eigenvector of the smallest eigenvalue of the
// scatter matrix. Needs at least 3 points not all on one line.
PlaneFit fit_plane(std::span<const Vec3d> points);

// Distance-to-axis least squares: the axis direction is searched over the PCA axes and a set of
// directions on the hemisphere (each scored by an algebraic circle fit of the points projected
// along it), then refined with Levenberg–Marquardt on r_i = |(x_i − p) × d| − ρ. Needs at least
// 6 points not all on one line.
CylinderFit fit_cylinder(std::span<const Vec3d> points);

}  // namespace pgamesh::cga
