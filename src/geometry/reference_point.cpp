#include "pgamesh/geometry/reference_point.hpp"

#include "pgamesh/core/bounding_box.hpp"

namespace pgamesh {

Vec3d reference_point(const Mesh& mesh) {
  return reference_point(mesh.vertices);
}

Vec3d reference_point(std::span<const Vec3d> vertices) {
  return bounding_box(vertices).centre();
}

}  // namespace pgamesh
