#include "pgamesh/mesh/topology/topology.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "mesh/topology/topology_parts.hpp"
#include "mesh/topology/triangle_topology.hpp"
#include "mesh/weld/welded_triangles.hpp"
#include "pgamesh/geometry/reference_point.hpp"
#include "pgamesh/mesh/topology/components.hpp"
#include "pgamesh/mesh/topology/duplicate_faces.hpp"
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
  if (!all_triangles(mesh)) return analyze_polygon_topology(mesh, options);
  const WeldedTriangles welded = weld_triangles(mesh, options.weld_tolerance);
  return analyze_welded_triangles(welded, reference_point(mesh), options);
}

TopologyReport analyze_topology(Mesh&& mesh, const TopologyOptions& options) {
  detail::check_topology_options(options);
  check_mesh_structure(mesh);
  if (!all_triangles(mesh)) return analyze_polygon_topology(mesh, options);
  const Vec3d reference = reference_point(mesh);
  // Welded in the mesh's own arrays: the welded triangles hold everything the triangle pass reads.
  const WeldedTriangles welded = weld_triangles(std::move(mesh), options.weld_tolerance);
  return analyze_welded_triangles(welded, reference, options);
}

TopologyReport analyze_polygon_topology(const Mesh& mesh, const TopologyOptions& options) {
  detail::check_topology_options(options);
  check_mesh_structure(mesh);
  TopologyReport r;
  const std::size_t face_count = mesh.face_count();
  r.faces = face_count;
  r.input_vertices = mesh.vertices.size();
  r.area_threshold = options.area_threshold;
  r.reference_point = reference_point(mesh);

  // Weld, then describe every corner by its welded vertex.
  const WeldMap weld = weld_map(mesh.vertices, options.weld_tolerance);
  r.vertices = weld.welded_count();
  r.merged_vertices = weld.merged;
  r.weld_tolerance = weld.tolerance;
  r.weld_max_moved = weld.max_moved;
  std::vector<std::uint32_t> welded_corner(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    welded_corner[c] = weld.to_welded[mesh.corners[c]];
  std::vector<Vec3d> positions(r.vertices);
  for (std::size_t w = 0; w < r.vertices; ++w) positions[w] = mesh.vertices[weld.representative[w]];
  {
    std::vector<std::uint8_t> referenced(r.vertices, 0);
    for (std::uint32_t w : welded_corner) referenced[w] = 1;
    r.unreferenced_vertices =
        static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), std::uint8_t{0}));
  }
  const detail::WeldedFaces faces{positions, weld.representative, welded_corner, mesh.face_offsets};
  detail::TopologyTally tally(r, faces, options);

  const EdgeTable edges = build_edges(mesh, welded_corner, r.vertices);
  const FaceComponents comps = face_components(mesh, edges);
  r.edges = edges.edge_count();
  tally.components.resize(comps.count());
  for (std::size_t k = 0; k < comps.count(); ++k) {
    tally.components[k].first_face = comps.first_face[k];
    tally.components[k].faces = comps.face_count[k];
  }

  // Faces: the boundary sums about the reference point, and the degenerate ones.
  std::vector<std::uint8_t> collapsed(face_count, 0);
  for (std::uint32_t f : edges.collapsed_faces) collapsed[f] = 1;
  r.collapsed_faces = edges.collapsed_faces.size();
  for (std::size_t f = 0; f < face_count; ++f)
    detail::tally_face(tally, static_cast<std::uint32_t>(f), collapsed[f] != 0);
  detail::tally_component_sums(tally, comps.face_component);

  // Edges: boundary, non-manifold, inconsistently oriented.
  for (std::size_t e = 0; e < edges.edge_count(); ++e) {
    const auto uses = edges.uses_of(e);
    const std::uint32_t face = edges.corner_face[uses[0]];
    std::size_t forward = 0;
    for (std::uint32_t c : uses) forward += is_forward(edges, welded_corner, c) ? 1 : 0;
    detail::tally_edge(tally, edges.v0[e], edges.v1[e], face, uses.size(), forward,
                       comps.face_component[face]);
  }

  const auto dups = duplicated_faces(mesh, edges, welded_corner);
  detail::finish_report(tally, dups,
                        boundary_loops(mesh, weld, welded_corner, edges, r.reference_point));
  return r;
}

}  // namespace pgamesh
