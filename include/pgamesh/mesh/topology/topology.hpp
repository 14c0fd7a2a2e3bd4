// The topology pass (`pgamesh check`, the summary of `pgamesh props`): weld, edges, boundary loops
// and the gap, non-manifold edges, orientation, degenerate and duplicated faces, components — and
// whether volume, centre of mass and inertia mean anything for this mesh. Definitions in
// docs/topology.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/mesh.hpp"
#include "pgamesh/core/vec3.hpp"
#include "pgamesh/mesh/topology/boundary_loops.hpp"
#include "pgamesh/mesh/topology/edges.hpp"
#include "pgamesh/mesh/topology/self_intersections.hpp"

namespace pgamesh {

struct TopologyOptions {
  double weld_tolerance = 0;     // 0 = weld bitwise-equal coordinates only (weld.hpp)
  double area_threshold = 1e-9;  // a face is "small" when area ≤ this × (its longest side)²
  std::size_t list_cap = 20;     // at most this many locations per list (counts are never capped)
  // Also look for faces that intersect (self_intersections.hpp); a mesh with any is not a solid.
  // Costs about as much as the rest of the pass again (docs/topology.md, "Self-intersections").
  bool self_intersections = true;
};

// An edge, named by the input vertices that represent its welded ends.
struct EdgeLocation {
  std::uint32_t face = 0;  // the lowest face along the edge
  std::uint32_t vertex0 = 0, vertex1 = 0;
  Vec3d p0{}, p1{};
  std::uint32_t face_count = 0;  // faces along the edge (1 = boundary, > 2 = non-manifold)
};

struct FaceLocation {
  std::uint32_t face = 0;
  Vec3d centroid{};  // mean of the face's corners
  double area = 0;
  std::uint32_t same_as = no_edge;  // duplicated faces: the earlier face with the same vertices
};

struct ComponentSummary {
  std::uint32_t first_face = 0;  // lowest face index in the component
  std::size_t faces = 0;
  double area = 0;
  double volume = 0;  // signed, about the mesh's reference point
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;
  std::size_t inconsistent_edges = 0;
  bool closed = false;  // no boundary, non-manifold or inconsistent edge
  // Closed components only (docs/conventions.md §8, orientation by nesting): how many other closed
  // components enclose it (odd: a cavity, which should face inward), and whether its volume has
  // the sign its depth forbids beyond the rounding residue bound (a defect --fix-orientation
  // repairs).
  std::uint32_t depth = 0;
  bool cavity = false;  // closed, at odd depth, and not a rounding residue
  bool inward = false;  // closed and oriented against its depth
};

struct TopologyReport {
  // Counts.
  std::size_t faces = 0;
  std::size_t triangles = 0;  // Σ (corners − 2): triangles of the faces' fans
  std::size_t input_vertices = 0;
  std::size_t vertices = 0;               // after welding
  std::size_t merged_vertices = 0;        // input − welded
  std::size_t unreferenced_vertices = 0;  // welded vertices no face uses
  double weld_tolerance = 0;
  double weld_max_moved = 0;  // largest distance a merged vertex moved
  std::size_t edges = 0;
  std::size_t boundary_edges = 0;      // used by one face
  std::size_t nonmanifold_edges = 0;   // used by more than two faces
  std::size_t inconsistent_edges = 0;  // more uses in one direction than the other can pair
  bool closed = false;  // every edge used by exactly two faces in opposite directions
  bool orientation_consistent = true;  // no inconsistent edge

  // Measures (doubles, accumulated about `reference_point`, mesh/reference_point.hpp:
  // docs/conventions.md §13).
  Vec3d reference_point{};
  double area = 0;
  double volume = 0;                  // signed volume about reference_point (the volume if closed)
  pga3::Plane<double> carrier_sum{};  // Σ F_i, e0 part about the origin
  Vec3d gap_vector{};                 // ½ normal part of Σ F_i (geometry/gap.hpp)
  double gap_area = 0;                // ½ ‖Σ F_i‖ (Cor. 4.1)
  double volume_min = 0, volume_max = 0;     // range of V(q), q over the vertices (gap.hpp)
  double loops_area = 0;                     // Σ of the loops' areas (≥ gap_area)
  std::vector<BoundaryLoop> boundary_loops;  // all of them

  // Faces.
  std::size_t zero_area_faces = 0;   // vector area exactly zero or < 3 distinct welded vertices
  std::size_t collapsed_faces = 0;   // of those, faces with < 3 distinct welded vertices
  std::size_t small_area_faces = 0;  // non-zero but ≤ area_threshold × (longest side)²
  std::size_t duplicated_faces = 0;  // same vertex set as an earlier face, either orientation
  std::size_t duplicated_area_faces = 0;  // of those, faces with non-zero area (they change volume)
  double area_threshold = 0;              // the threshold the small faces were judged by
  std::vector<FaceLocation> zero_area_list, small_area_list, duplicated_list;

  // Edges.
  std::vector<EdgeLocation> boundary_edge_list, nonmanifold_edge_list, inconsistent_edge_list;

  // Components (edge-connected after the weld; collapsed faces belong to none).
  std::size_t components = 0;
  std::size_t closed_components = 0;
  std::size_t cavity_components = 0;  // ComponentSummary::cavity
  std::size_t inward_components = 0;  // closed components oriented against their depth (inward)
  std::vector<ComponentSummary> component_list;

  // Self-intersections (self_intersections.hpp), when TopologyOptions::self_intersections.
  bool self_intersections_checked = false;
  std::size_t self_intersecting_pairs = 0;  // face pairs that intersect (at least, when the
  bool self_intersections_complete = true;  // pass stopped at max_counted_intersections)
  std::vector<SelfIntersection> self_intersection_list;

  // Whether volume, centre of mass and inertia are meaningful: no boundary, consistent
  // orientation, no duplicated faces of non-zero area, no self-intersection (when checked), at
  // least one face. Notes say why not, in plain words.
  bool volume_valid = false;
  std::vector<std::string> notes;

  double volume_ambiguity() const { return volume_max - volume_min; }
};

// Welds (exactly, or within options.weld_tolerance), finds the edges and reports on them, in one
// pass for faces of any size (welded_topology.hpp). Throws std::out_of_range for corner indices
// beyond the vertex list and std::invalid_argument for a bad option; the mesh itself may be
// anything (empty, open, non-manifold, degenerate).
TopologyReport analyze_topology(const Mesh& mesh, const TopologyOptions& options = {});

// The same report from a mesh the caller no longer needs: it is welded in its own arrays (the
// coordinates compacted, the corners renumbered in place), so no second copy of them exists at the
// peak. The mesh is left empty.
TopologyReport analyze_topology(Mesh&& mesh, const TopologyOptions& options = {});

// A mesh's structure is usable: face_offsets starts at 0, ascends and ends at corners.size(), and
// every corner names an existing vertex. Throws std::out_of_range otherwise.
void check_mesh_structure(const Mesh& mesh);

}  // namespace pgamesh
