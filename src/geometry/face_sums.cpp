#include "pgamesh/geometry/face_sums.hpp"

#include <vector>

namespace pgamesh {

void add_mesh_polygon(BoundarySums& s, const Vec3d* vertices, const std::uint32_t* c, std::size_t n,
                      Vec3d reference) {
  // Relative coordinates of one polygon; a buffer per thread, so that a mesh of polygons allocates
  // once.
  thread_local std::vector<Vec3d> v;
  v.resize(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = vertices[c[k]] - reference;
  add_polygon(s, v.data(), n);
}

}  // namespace pgamesh
