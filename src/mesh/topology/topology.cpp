#include "pgamesh/mesh/topology/topology.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesh/topology/topology_parts.hpp"
#include "mesh/topology/welded_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/geometry/reference_point.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh {

void check_mesh_structure(const Mesh& mesh) {
  const auto& off = mesh.face_offsets;
  if (off.empty() || off.front() != 0 || off.back() != mesh.corners.size())
    throw std::out_of_range("mesh: face offsets do not span the corner list");
  for (std::size_t f = 0; f + 1 < off.size(); ++f)
    if (off[f + 1] < off[f])
      throw std::out_of_range("mesh: face offsets descend at face " + std::to_string(f));
  if (mesh.corners.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::out_of_range("mesh: more than 2^32 - 2 corners");
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    if (mesh.corners[c] >= mesh.vertices.size())
      throw std::out_of_range("mesh: corner " + std::to_string(c) + " names vertex " +
                              std::to_string(mesh.corners[c]) + " of " +
                              std::to_string(mesh.vertices.size()));
}

TopologyReport analyze_topology(const Mesh& mesh, const TopologyOptions& options) {
  detail::check_topology_options(options);
  check_mesh_structure(mesh);
  const Vec3d reference = reference_point(mesh);
  if (all_triangles(mesh))
    return analyze_welded_triangles(weld_triangles(mesh, options.weld_tolerance), reference,
                                    options);
  return analyze_welded_mesh(weld(mesh, options.weld_tolerance), reference, options);
}

TopologyReport analyze_topology(Mesh&& mesh, const TopologyOptions& options) {
  detail::check_topology_options(options);
  check_mesh_structure(mesh);
  const Vec3d reference = reference_point(mesh);
  // Welded in the mesh's own arrays: the welded mesh holds everything the pass reads.
  if (all_triangles(mesh))
    return analyze_welded_triangles(weld_triangles(std::move(mesh), options.weld_tolerance),
                                    reference, options);
  return analyze_welded_mesh(weld(std::move(mesh), options.weld_tolerance), reference, options);
}

}  // namespace pgamesh
