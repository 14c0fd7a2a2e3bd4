// Repairing a mesh into a solid (`pgamesh repair`): weld, drop the faces that bound nothing, orient
// by nesting, cap the holes. Every change is counted and the first ones listed, so a report can say
// exactly what was done; the steps and their order are in docs/topology.md, "Repair".
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pgamesh/core/mesh.hpp"
#include "pgamesh/mesh/repair/hole_cap.hpp"
#include "pgamesh/mesh/topology/orientation.hpp"

namespace pgamesh {

struct RepairOptions {
  double weld_tolerance = 0;  // 0: weld bitwise-equal coordinates (weld.hpp)
  bool remove_duplicate_faces = true;
  bool orient = true;
  bool cap_holes = true;      // false: holes are found and reported, left open
  HoleCapOptions hole;        // planarity tolerance and --force for the caps
  std::size_t list_cap = 20;  // faces and holes listed per kind (counts are complete)
};

struct CappedHole {
  std::size_t rim_vertices = 0;
  Vec3d first_vertex{};  // where the rim starts, to find it
  double area = 0;
  double max_deviation = 0;
  std::size_t triangles = 0;  // 0 when refused
  std::string refused;        // why not capped; empty when capped
};

struct RepairReport {
  // Weld.
  std::size_t input_vertices = 0;
  std::size_t merged_vertices = 0;
  double weld_tolerance = 0;
  double weld_max_moved = 0;
  // Faces that bound nothing, removed (input face indices, the first list_cap as found).
  std::size_t input_faces = 0;
  std::size_t collapsed_faces = 0;   // fewer than three distinct vertices after the weld
  std::size_t repeated_corners = 0;  // consecutive corners on one vertex, merged (faces kept)
  std::size_t duplicate_faces = 0;   // a later copy of a face, same orientation
  std::size_t opposite_pairs = 0;    // a face and its reverse, both removed (two faces each)
  std::vector<std::uint32_t> removed_faces;
  // Orientation (by nesting, after the caps): input faces whose corner order was reversed
  // (the first list_cap, ascending).
  std::size_t reversed_faces = 0;
  std::vector<std::uint32_t> reversed_list;
  std::size_t orientation_conflicts = 0;  // edges no orientation could make consistent
  // Holes: every boundary loop found, capped or not.
  std::vector<CappedHole> holes;
  std::size_t holes_capped = 0, holes_refused = 0, cap_triangles = 0;
  std::size_t unreferenced_vertices = 0;  // dropped from the output
  std::size_t output_vertices = 0, output_faces = 0;
  bool changed() const {
    return merged_vertices + collapsed_faces + repeated_corners + duplicate_faces + opposite_pairs +
               reversed_faces + cap_triangles + unreferenced_vertices >
           0;
  }
};

// Repairs `mesh` in place: (1) weld within options.weld_tolerance (vertices move to their class's
// first vertex); (2) merge consecutive corners on one vertex and drop faces left with fewer than
// three distinct vertices; (3) drop later copies of a face (same vertex cycle) and remove both
// faces of a pair running the same cycle in opposite directions (a double wall: the two bound no
// volume, and removing them joins the solids on either side); (4) orient faces consistently;
// (5) cap each closed boundary loop (cap_hole); (6) orient by nesting (orientation.hpp), so the
// capped shells point out and cavities in; (7) drop vertices no face uses. Faces keep their order
// (removed ones leave no gap); caps come last. Throws std::out_of_range for a corner beyond the
// vertex list and std::invalid_argument for a bad tolerance.
RepairReport repair(Mesh& mesh, const RepairOptions& options = {});

}  // namespace pgamesh
