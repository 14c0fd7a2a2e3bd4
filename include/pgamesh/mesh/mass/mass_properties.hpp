// Mass properties of a solid bounded by a polygon mesh: area, signed volume, mass, centre of mass,
// inertia about the centre of mass and about the origin, products of inertia, principal moments and
// axes with the motor of the principal frame, and the gap of an open boundary. Everything comes
// from one pass of boundary sums (geometry/body_moments.hpp: paper Table 1, eqs. 5.3–5.6 as
// corrected in docs/conventions.md §8–§10) accumulated about a reference point near the mesh
// (docs/conventions.md §13), and the rotor Jacobi of geometry/inertia_frame.hpp (eqs. 5.7–5.9).
//
// Conventions (docs/mass-properties.md): faces counter-clockwise seen from outside; the volume is
// signed (negative for an inward-oriented mesh, never abs()'d); inertia is the tensor
// I = ∫ρ (|r|² 1 − r rᵀ) dV, whose off-diagonal entries are minus the products of inertia.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/inertia_frame.hpp"

namespace pgamesh {

struct MassOptions {
  std::optional<double> density;  // mass per unit volume (default 1: mass = volume)
  std::optional<double> mass;     // total mass instead: density = mass / volume
  unsigned threads = 0;           // 0: every hardware thread; the result does not depend on it
  // Principal moments closer than this, relative to the largest, are reported as degenerate.
  double degeneracy_tolerance = default_degeneracy_tolerance;
};

// Products of inertia ∫ x y dm, ∫ y z dm, ∫ z x dm (about the same point as the tensor they come
// from): the tensor's off-diagonal entries with the sign flipped (docs/conventions.md §10).
struct ProductsOfInertia {
  double xy = 0, yz = 0, zx = 0;
};

struct MassProperties {
  std::uint64_t faces = 0;      // polygons
  std::uint64_t triangles = 0;  // Σ (corners − 2): triangles of the polygons' fans
  std::uint64_t vertices = 0;
  Vec3d reference_point{};  // the point the sums were accumulated about

  double area = 0;
  double volume = 0;   // signed: positive for an outward-oriented closed surface
  double density = 1;  // as given, or mass / volume
  double mass = 0;     // density × volume
  // Undefined (NaN) when the volume is 0: then neither the centre of mass nor the inertia exist.
  Vec3d center_of_mass{};
  Mat3 inertia_com{};     // tensor about the centre of mass
  Mat3 inertia_origin{};  // tensor about the coordinate origin (parallel-axis shift)
  ProductsOfInertia products_com, products_origin;
  PrincipalFrame principal;  // principal moments ascending with their axes, rotor, degeneracy
  // The motor M = T R placing the principal frame: M o M̃ = centre of mass, M e_i M̃ = principal
  // axis i (as directions). Its reverse takes the body into its principal frame.
  pga3::Motor<double> principal_motor{1.0};  // the identity until computed

  double gap_area = 0;                // ½‖Σ F‖ (Cor. 4.1): 0 for a closed surface
  pga3::Plane<double> carrier_sum{};  // Σ F in coordinates about the origin
  std::vector<std::string> warnings;
};

// The boundary sums of every face of the mesh, coordinates relative to `reference`, on up to
// `threads` threads (deterministic: see geometry/chunked_sums.hpp). Faces with fewer than three
// corners add nothing. Throws std::out_of_range when a corner index is not a vertex.
BoundarySums mesh_boundary_sums(const Mesh& mesh, Vec3d reference, unsigned threads = 0);

// Mass properties from boundary sums accumulated about `reference`. The counts (faces, triangles,
// vertices) are left for the caller to fill in. Throws std::invalid_argument for a density or mass
// that is not positive and finite.
MassProperties mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                         const MassOptions& options);

// What mass_properties() below returns, from the boundary sums of the faces about `reference` (the
// reference_point of `vertices`) accumulated by a caller that summed them itself (add_mesh_face of
// face_sums.hpp, in face order and chunking of chunked_sums.hpp): the sums turned into figures,
// the counts filled in and, with `single_precision`, the float32 warning.
MassProperties mesh_mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                              std::span<const Vec3d> vertices, std::uint64_t faces,
                                              std::uint64_t triangles, const MassOptions& options,
                                              bool single_precision);

// The same, for a caller that keeps no array of the vertices as doubles: `box` is their bounding
// box (read only with `single_precision`) and `vertex_count` their number.
MassProperties mesh_mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                              const Box3& box, std::size_t vertex_count,
                                              std::uint64_t faces, std::uint64_t triangles,
                                              const MassOptions& options, bool single_precision);

// Mass properties of a mesh, accumulated about reference_point(mesh). When `source` says the
// coordinates were float32, adds float32_precision_warning's warning.
MassProperties mass_properties(const Mesh& mesh, const MassOptions& options = {},
                               const MeshSource* source = nullptr);

// When float32 coordinates (binary STL, float PLY) spanning `box` are spaced more coarsely, at the
// farthest coordinate from the origin, than 1e-6 of the part's size (its bounding-box diagonal),
// a warning saying so: the input itself then carries relative errors of that order, whatever the
// accumulation does. nullopt otherwise.
std::optional<std::string> float32_precision_warning(const Box3& box);

// When polygon faces were bent beyond face_planarity_tolerance (body_moments.hpp), a warning
// giving their number and the largest deviation of a corner from its face's mean plane, absolute
// and relative to that face's size. nullopt otherwise. mass_properties_from_sums adds it.
std::optional<std::string> nonplanar_faces_warning(const FacePlanarity& planarity);

// The products of inertia of an inertia tensor.
ProductsOfInertia products_of_inertia(const Mat3& inertia);

}  // namespace pgamesh
