// Orientation by nesting (docs/conventions.md §8, "Orientation by nesting"): which way each closed
// shell should face. A closed shell's depth is the number of other closed shells around it; at
// even depth (an outer skin, an island in a cavity) it should face out (positive signed volume), at
// odd depth (a cavity) in. The one rule that the topology report and fix_orientation both use.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

// How a closed shell's signed volume compares with the orientation its depth asks for.
enum class ShellOrientation : std::uint8_t {
  right,      // the sign its depth asks for
  wrong,      // the other sign, beyond rounding: reversing every face repairs it
  undecided,  // |volume| within the rounding residue bound: neither inward nor outward
};

// The factor k of the residue bound |V| ≤ k·ε·A·D (docs/conventions.md §8).
inline constexpr double shell_residue_factor = 16;

// The largest |signed volume| that is a rounding residue for a shell of area `area` whose volume
// was summed about a point of a box of diagonal `diameter` that holds the shell: each
// tetrahedron's volume is rounded at about ε × its face's area × the apex distance (≤ D).
inline double volume_residue_bound(double area, double diameter) {
  return shell_residue_factor * std::numeric_limits<double>::epsilon() * area * diameter;
}

// The verdict for a closed shell of signed volume `volume` and area `area` at depth `depth`;
// `diameter()` gives D of volume_residue_bound and is called only when the sign is not the one
// the depth asks for (the report computes it from every vertex).
template <class Diameter>
ShellOrientation judge_shell(double volume, std::uint32_t depth, double area, Diameter&& diameter) {
  const bool wants_positive = depth % 2 == 0;
  if (wants_positive ? volume > 0 : volume < 0) return ShellOrientation::right;
  return std::abs(volume) > volume_residue_bound(area, diameter()) ? ShellOrientation::wrong
                                                                   : ShellOrientation::undecided;
}

// Fills `out` (cleared first) with the positions of face f's corners, in the face's order.
using FaceCorners = std::function<void(std::uint32_t face, std::vector<Vec3d>& out)>;

// The depth of every component: for a shell (is_shell[k] != 0: closed and consistently oriented)
// the number of other shells whose generalised winding number about its test point is odd; 0 for
// every other component. face_component[f] is face f's component or no_edge (none). The test point
// of a shell is the centroid of the first fan triangle of non-zero area of its lowest such face:
// strictly inside one of its own faces, so on none of its edges or vertices. The winding number
// (Σ solid angles of the other shell's fan triangles / 4π) needs no ray and is rounded to the
// nearest integer; a point within 1/4 of a half-integer lies on the other shell's surface (shells
// that touch or overlap there) and counts as outside it. Reads no face when fewer than two
// components are shells; otherwise two passes over the faces, each face of a shell costing one
// solid angle per other shell whose test point lies in its bounding box (found among the points
// sorted by x: O(S log S) plus the points in each box's x range, for S shells).
std::vector<std::uint32_t> shell_depths(std::span<const std::uint32_t> face_component,
                                        std::span<const std::uint8_t> is_shell,
                                        const FaceCorners& corners);

}  // namespace pgamesh
