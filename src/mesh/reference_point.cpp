#include "pgamesh/mesh/reference_point.hpp"

#include "pgamesh/geometry/bounding_box.hpp"

namespace pgamesh {

Vec3d reference_point(const Mesh& mesh) {
  return bounding_box(mesh.vertices).centre();
}

}  // namespace pgamesh
