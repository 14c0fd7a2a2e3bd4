#include "support/cube_file.hpp"

#include <cstdio>

namespace pgamesh::test {

std::string cube_obj(double side, double low, CubeDefect defect) {
  std::string text;
  char line[160];
  const double high = low + side;
  for (int i = 0; i < 8; ++i) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", i & 1 ? high : low,
                  i & 2 ? high : low, i & 4 ? high : low);
    text += line;
  }
  // Counter-clockwise seen from outside (OBJ indices from 1); the last face is the top, z = high.
  const int faces[6][4] = {{1, 3, 4, 2}, {1, 2, 6, 5}, {3, 7, 8, 4},
                           {1, 5, 7, 3}, {2, 4, 8, 6}, {5, 6, 8, 7}};
  for (int f = 0; f < 6; ++f) {
    const bool top = f == 5;
    if (top && defect == CubeDefect::open) continue;
    const bool reversed = defect == CubeDefect::inward || (top && defect == CubeDefect::one_flip);
    const int* c = faces[f];
    if (reversed)
      std::snprintf(line, sizeof line, "f %d %d %d %d\n", c[3], c[2], c[1], c[0]);
    else
      std::snprintf(line, sizeof line, "f %d %d %d %d\n", c[0], c[1], c[2], c[3]);
    text += line;
  }
  return text;
}

}  // namespace pgamesh::test
