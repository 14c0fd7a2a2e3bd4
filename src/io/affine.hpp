// Affine maps of 3-D points, x' = A x + t, as the formats that place objects write them (3MF build
// items and components, glTF nodes): one type, one product and one determinant for every reader.
// Internal to the io layer.
#pragma once

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::detail {

// Three rows of (A | t): 3MF's row-vector matrices (3MF core specification §3.3) and glTF's
// column-major ones (glTF 2.0 §3.5.2) both become this form. `identity` is kept apart so that
// untransformed coordinates are copied bit for bit rather than multiplied by ones and zeros.
struct Affine {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  bool identity = true;

  Vec3d apply(const Vec3d& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  // det A: negative for a mirror, whose faces must be reversed to keep facing out.
  double determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
};

// a ∘ b: b applied first, then a.
inline Affine compose(const Affine& a, const Affine& b) {
  if (a.identity) return b;
  if (b.identity) return a;
  Affine r;
  r.identity = false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
      if (j == 3) s += a.m[i][3];
      r.m[i][j] = s;
    }
  return r;
}

}  // namespace pgamesh::detail
