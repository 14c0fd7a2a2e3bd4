#include "pgamesh/mesh/mass/mass_properties.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/chunked_sums.hpp"
#include "pgamesh/geometry/face_sums.hpp"
#include "pgamesh/geometry/reference_point.hpp"

namespace pgamesh {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

void check_corners(const Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    for (std::size_t k = 0; k < mesh.face_size(f); ++k)
      if (c[k] >= n)
        throw std::out_of_range("face " + std::to_string(f) + " refers to vertex " +
                                std::to_string(c[k]) + " of " + std::to_string(n));
  }
}

Mat3 nan_matrix() {
  Mat3 m;
  for (auto& row : m) row.fill(nan);
  return m;
}

}  // namespace

BoundarySums mesh_boundary_sums(const Mesh& mesh, Vec3d reference, unsigned threads) {
  check_corners(mesh);
  return chunked_sums(
      mesh.face_count(), threads, [&](LanedSums<>& s, std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f)
          add_mesh_face(s[f], mesh.vertices.data(), mesh.face(f), mesh.face_size(f), reference);
      });
}

ProductsOfInertia products_of_inertia(const Mat3& inertia) {
  return {-inertia[0][1], -inertia[1][2], -inertia[2][0]};
}

MassProperties mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                         const MassOptions& options) {
  // A density or mass of zero or less describes no body (its masses and inertias would be negative
  // or zero): refused like a non-finite one.
  if (options.density && !(std::isfinite(*options.density) && *options.density > 0))
    throw std::invalid_argument("density must be a positive finite number");
  if (options.mass && !(std::isfinite(*options.mass) && *options.mass > 0))
    throw std::invalid_argument("mass must be a positive finite number");
  const BodyMoments m = body_moments(sums);
  MassProperties p;
  if (auto w = nonplanar_faces_warning(sums.planarity)) p.warnings.push_back(*w);
  p.reference_point = reference;
  p.area = m.area;
  p.volume = m.volume;
  p.gap_area = m.gap_area;
  // Σ F about the coordinate origin: a plane n·(x − ref) + d = 0 is n·x + (d − n·ref) = 0.
  p.carrier_sum = sums.carrier_sum;
  p.carrier_sum.e0 -= dot(sums.carrier_sum.normal(), reference);
  if (options.mass) {
    p.mass = *options.mass;
    p.density = m.volume != 0 ? *options.mass / m.volume : nan;
  } else {
    p.density = options.density.value_or(1.0);
    p.mass = p.density * m.volume;
  }
  if (m.volume == 0 || !std::isfinite(p.density)) {
    // No solid: neither centre of mass nor inertia exist.
    p.center_of_mass = {nan, nan, nan};
    p.inertia_com = p.inertia_origin = nan_matrix();
    p.products_com = p.products_origin = {nan, nan, nan};
    p.principal.moments = {nan, nan, nan};
    p.principal.degenerate = true;
    p.principal_motor = pga3::translator(Vec3d{nan, nan, nan});
    return p;
  }
  // Second moments about the centre of mass by the exact parallel-axis shift from the reference
  // point, which lies near the mesh, so the shift cancels few digits (docs/conventions.md §13).
  const Vec3d c = centroid(m);
  p.center_of_mass = reference + c;
  p.inertia_com = inertia_from_second_moment(central_second_moment(m), p.density);
  const Mat3 shift = parallel_axis(p.center_of_mass);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.inertia_origin[i][j] = p.inertia_com[i][j] + p.mass * shift[i][j];
  p.products_com = products_of_inertia(p.inertia_com);
  p.products_origin = products_of_inertia(p.inertia_origin);
  p.principal = principal_frame(p.inertia_com, options.degeneracy_tolerance);
  // In the quaternion order, as the principal frame (docs/pga3.md "Two summation orders").
  p.principal_motor = pga3::quaternion_order::geometric_product(pga3::translator(p.center_of_mass),
                                                                p.principal.rotor);
  return p;
}

std::optional<std::string> nonplanar_faces_warning(const FacePlanarity& planarity) {
  if (planarity.nonplanar_faces == 0) return std::nullopt;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "%llu polygon face%s not planar: a corner lies up to %.3g from its face's mean "
                "plane (%.2g of that face's size); the area of a bent face is that of its fan from "
                "its first corner, the surface its volume is measured under",
                static_cast<unsigned long long>(planarity.nonplanar_faces),
                planarity.nonplanar_faces == 1 ? " is" : "s are", planarity.largest_deviation,
                planarity.largest_relative);
  return std::string(buf);
}

std::optional<std::string> float32_precision_warning(const Box3& box) {
  if (box.empty()) return std::nullopt;
  const double far = box.max_abs(), size = box.diagonal();
  // Spacing of float32 numbers at `far`: 2^(exponent − 23).
  int exponent = 0;
  std::frexp(static_cast<float>(far), &exponent);
  const double spacing = std::ldexp(1.0, exponent - 24);
  if (!(spacing > 1e-6 * size)) return std::nullopt;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "float32 coordinates reach %.3g from the origin, where their spacing is %.3g = "
                "%.2g of the part size %.3g: the input carries relative errors of that order; "
                "move the part near the origin before exporting for full precision",
                far, spacing, spacing / size, size);
  return std::string(buf);
}

MassProperties mesh_mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                              std::span<const Vec3d> vertices, std::uint64_t faces,
                                              std::uint64_t triangles, const MassOptions& options,
                                              bool single_precision) {
  return mesh_mass_properties_from_sums(
      sums, reference, single_precision ? bounding_box(vertices) : Box3{}, vertices.size(), faces,
      triangles, options, single_precision);
}

MassProperties mesh_mass_properties_from_sums(const BoundarySums& sums, Vec3d reference,
                                              const Box3& box, std::size_t vertex_count,
                                              std::uint64_t faces, std::uint64_t triangles,
                                              const MassOptions& options, bool single_precision) {
  MassProperties p = mass_properties_from_sums(sums, reference, options);
  p.faces = faces;
  p.vertices = vertex_count;
  p.triangles = triangles;
  if (single_precision)
    if (auto w = float32_precision_warning(box)) p.warnings.push_back(*w);
  return p;
}

MassProperties mass_properties(const Mesh& mesh, const MassOptions& options,
                               const MeshSource* source) {
  const Vec3d ref = reference_point(mesh);
  std::uint64_t triangles = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) >= 3) triangles += mesh.face_size(f) - 2;
  return mesh_mass_properties_from_sums(mesh_boundary_sums(mesh, ref, options.threads), ref,
                                        mesh.vertices, mesh.face_count(), triangles, options,
                                        source && source->single_precision);
}

}  // namespace pgamesh
