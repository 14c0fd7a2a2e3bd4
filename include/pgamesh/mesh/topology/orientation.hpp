// Repairing face orientation: make every face agree with its neighbours, then turn each closed
// component the way its nesting asks — outward at even depth, inward in a cavity (odd depth)
// (docs/conventions.md §8, orientation by nesting).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pgamesh/core/mesh.hpp"

namespace pgamesh {

struct OrientationOptions {
  double weld_tolerance = 0;  // how faces find their neighbours (weld.hpp); vertices are not moved
  std::size_t list_cap = 20;  // flipped face indices listed per component (counts are complete)
};

struct ComponentOrientation {
  std::uint32_t component = 0;  // numbered by lowest face, as in TopologyReport
  std::uint32_t first_face = 0;
  std::size_t faces = 0;
  std::size_t flipped = 0;                   // faces of this component that were reversed
  std::vector<std::uint32_t> flipped_faces;  // the first list_cap of them, ascending
  bool closed = false;        // closed after the repair (every edge two opposite uses)
  std::uint32_t depth = 0;    // closed: the closed components around it (odd: a cavity)
  double volume = 0;          // signed volume after the repair (closed: > 0 at even depth, < 0
                              // at odd depth, unless a rounding residue)
  std::size_t conflicts = 0;  // manifold edges that could not be made consistent (non-orientable)
};

struct OrientationFix {
  std::size_t flipped = 0;  // faces reversed in all
  std::size_t conflicts = 0;
  std::vector<ComponentOrientation> components;  // only those in which a face was flipped
};

// Reverses faces of `mesh` in place (a face keeps its first corner, the others reverse order).
// In each component, a breadth-first walk from its lowest face across manifold edges (exactly two
// uses) orients every face against its neighbour. A closed component is then turned the way its
// depth among the other closed components asks (shell_nesting.hpp): its signed volume, summed
// about the component's bounding-box centre, must be positive at even depth and negative at odd
// depth; if it has the other sign beyond the rounding residue bound, all its faces are reversed.
// An open component or a residue has no inside; it keeps the orientation that the majority of its
// faces had (ties: its lowest face's). The report lists, per component, exactly the faces whose
// corner order changed.
OrientationFix fix_orientation(Mesh& mesh, const OrientationOptions& options = {});

}  // namespace pgamesh
