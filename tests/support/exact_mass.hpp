// Exact mass properties of a polygon mesh in rational arithmetic (GMP mpq_class) on the double
// input coordinates: the reference the floating-point accumulation is held to (issue item 3:
// ≤ 1e-12 relative). Polygons are fanned about their first vertex, as pgamesh does. Only
// available when GMP's C++ interface was found (PGAMESH_HAVE_GMP).
#pragma once

#ifdef PGAMESH_HAVE_GMP

#include <gmpxx.h>

#include <array>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh::test {

struct ExactMass {
  mpq_class volume;                 // ∫ dV
  std::array<mpq_class, 3> first;   // ∫ r dV about the coordinate origin
  std::array<mpq_class, 9> second;  // ∫ r rᵀ dV about the coordinate origin, row-major
};

// Sums the signed tetrahedra (o, v0, vi, vi+1) of every face exactly.
ExactMass exact_mass(const Mesh& mesh);

// Volume, centre of mass and the inertia tensor about the centre of mass (density 1, tensor
// convention I = ∫ (|r|² 1 − r rᵀ) dV), each rounded once to double.
struct ExactSummary {
  double volume;
  Vec3d center_of_mass;
  Mat3 inertia_com;
};
ExactSummary exact_summary(const Mesh& mesh);

}  // namespace pgamesh::test

#endif
