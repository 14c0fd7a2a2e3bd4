// Cubes as mesh files, whole or with one defect, for tests that run the CLI on a body whose figures
// are known in closed form (volume side³, inertia about the centre side⁵/6 on the diagonal).
#pragma once

#include <string>

namespace pgamesh::test {

enum class CubeDefect {
  none,      // closed and outward
  open,      // the top face missing
  inward,    // every face reversed: volume −side³
  one_flip,  // the top face reversed: inconsistent orientation
};

// OBJ text of the cube [low, low + side]³ as six quads (coordinates %.17g).
std::string cube_obj(double side, double low = 0, CubeDefect defect = CubeDefect::none);

}  // namespace pgamesh::test
