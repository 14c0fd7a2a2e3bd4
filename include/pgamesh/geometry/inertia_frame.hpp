// The principal frame of an inertia tensor by the rotor Jacobi of paper eqs. 5.7–5.9, as
// corrected in docs/conventions.md §10, §11: each Givens step is a rotor R_k = exp(−½ φ e_pq) that
// turns the tensor's rows (vectors I_j) by I′_i = Σ_j (e_j · (R̃_k e_i R_k)) R_k I_j R̃_k, the rotors
// compose as R ← R_k R, and the eigenvectors are u_i = R̃ e_i R. Sorting the moments and fixing the
// axes' signs are rotors too (quarter and half turns about frame axes), so the frame stays
// right-handed and is always given by one rotor.
#pragma once

#include <array>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// Principal moments closer than this, relative to the largest |moment|, count as equal.
inline constexpr double default_degeneracy_tolerance = 1e-7;

// What the Jacobi iteration leaves: the diagonal of the turned tensor (unsorted) and the rotor R
// with R u_i R̃ = e_i for the eigenvector u_i of diagonal[i].
struct JacobiResult {
  std::array<double, 3> diagonal{};
  pga3::Motor<double> rotor{1.0};  // the identity
  int sweeps = 0;                  // cyclic sweeps over the pivots (1,2), (1,3), (2,3)
  int rotations = 0;               // Givens rotors applied
};

// Diagonalises the symmetric matrix m by rotor Jacobi (eqs. 5.7–5.9; τ = (I_q·e_q − I_p·e_p) /
// (2 I_p·e_q), φ = atan(sgn τ / (|τ| + √(1 + τ²))) with sgn(0) := +1). Stops when every
// off-diagonal entry is negligible next to its diagonal pair, or after 32 sweeps.
JacobiResult rotor_jacobi(const Mat3& m);

struct PrincipalFrame {
  std::array<double, 3> moments{};  // ascending
  // axes[i] is the unit axis of moments[i]; right-handed (axes[2] = axes[0] × axes[1]); axes 0
  // and 1 have their largest-|·| component positive (the first one on a tie).
  std::array<Vec3d, 3> axes{};
  // The rotor taking the coordinate frame to the principal frame: rotor e_i rotor~ = axes[i];
  // its scalar part is ≥ 0.
  pga3::Motor<double> rotor{1.0};  // the identity
  // Two moments are equal within the tolerance: the axes in their plane (or all three axes) are
  // one valid choice among infinitely many.
  bool degenerate = false;
  int sweeps = 0, rotations = 0;
};

// Principal moments and axes of a symmetric tensor (an inertia tensor), sorted and signed by the
// rules of PrincipalFrame.
PrincipalFrame principal_frame(const Mat3& tensor,
                               double degeneracy_tolerance = default_degeneracy_tolerance);

}  // namespace pgamesh
