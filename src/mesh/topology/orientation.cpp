#include "pgamesh/mesh/topology/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/polygon_face.hpp"
#include "pgamesh/mesh/topology/components.hpp"
#include "pgamesh/mesh/topology/edges.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh {

OrientationFix fix_orientation(Mesh& mesh, const OrientationOptions& options) {
  check_mesh_structure(mesh);
  const WeldMap weld = weld_map(mesh.vertices, options.weld_tolerance);
  std::vector<std::uint32_t> welded_corner(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    welded_corner[c] = weld.to_welded[mesh.corners[c]];
  const EdgeTable edges = build_edges(mesh, welded_corner, weld.welded_count());
  const FaceComponents comps = face_components(mesh, edges);
  const std::size_t face_count = mesh.face_count();

  // Faces of each component, ascending (CSR by component).
  std::vector<std::uint32_t> comp_start(comps.count() + 1, 0);
  for (std::size_t k = 0; k < comps.count(); ++k)
    comp_start[k + 1] = comp_start[k] + comps.face_count[k];
  std::vector<std::uint32_t> comp_faces(comp_start.back());
  {
    std::vector<std::uint32_t> fill(comp_start.begin(), comp_start.end() - 1);
    for (std::uint32_t f = 0; f < face_count; ++f)
      if (comps.face_component[f] != no_edge) comp_faces[fill[comps.face_component[f]]++] = f;
  }

  std::vector<std::uint8_t> flip(face_count, 0), seen(face_count, 0);
  std::vector<std::uint32_t> queue;
  OrientationFix out;
  for (std::size_t k = 0; k < comps.count(); ++k) {
    ComponentOrientation rep;
    rep.component = static_cast<std::uint32_t>(k);
    rep.first_face = comps.first_face[k];
    rep.faces = comps.face_count[k];

    // Walk from each unreached face of the component (the lowest first; faces joined only through
    // non-manifold edges start walks of their own). A face's side c runs forward along its edge iff
    // is_forward(c) != flip[face]; the neighbour across a manifold edge must run it the other way.
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t seed = comp_faces[i];
      if (seen[seed]) continue;
      seen[seed] = 1;
      queue.assign(1, seed);
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t f = queue[head];
        for (std::uint32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
          const std::uint32_t e = edges.corner_edge[c];
          if (e == no_edge || edges.use_count(e) != 2) continue;
          const auto uses = edges.uses_of(e);
          const std::uint32_t other = uses[0] == c ? uses[1] : uses[0];
          const std::uint32_t g = edges.corner_face[other];
          if (g == f) continue;
          const bool f_forward = is_forward(edges, welded_corner, c) != (flip[f] != 0);
          const bool g_needs_flip = is_forward(edges, welded_corner, other) == f_forward;
          if (!seen[g]) {
            seen[g] = 1;
            flip[g] = g_needs_flip ? 1 : 0;
            queue.push_back(g);
          } else if ((flip[g] != 0) != g_needs_flip && f < g) {
            ++rep.conflicts;  // a non-orientable cycle; counted once, from the edge's lower face
          }
        }
      }
    }

    // Closed after the walk? Every edge of the component has two opposite uses.
    rep.closed = rep.conflicts == 0;
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1] && rep.closed; ++i) {
      const std::uint32_t f = comp_faces[i];
      for (std::uint32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c) {
        const std::uint32_t e = edges.corner_edge[c];
        if (e == no_edge) continue;
        if (edges.use_count(e) != 2) {
          rep.closed = false;
          break;
        }
      }
    }

    // Signed volume with the walk's flips, about the component's bounding-box centre
    // (docs/conventions.md §13).
    Box3 box;
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t f = comp_faces[i];
      for (std::uint32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
        box.add(mesh.vertices[mesh.corners[c]]);
    }
    const Vec3d ref = box.centre();
    BoundarySums sums;
    std::size_t flipped = 0;
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t f = comp_faces[i];
      const std::uint32_t begin = mesh.face_offsets[f], n = mesh.face_offsets[f + 1] - begin;
      BoundarySums s = polygon_face_sums(n, [&](std::size_t j) {
        return mesh.vertices[weld.representative[welded_corner[begin + j]]] - ref;
      });
      if (flip[f]) {
        s.volume6 = -s.volume6;
        ++flipped;
      }
      sums.volume6 += s.volume6;
    }
    rep.volume = body_moments(sums).volume;
    const bool reverse_all = rep.closed ? rep.volume < 0 : 2 * flipped > rep.faces;
    if (reverse_all) {
      for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) flip[comp_faces[i]] ^= 1;
      rep.volume = -rep.volume;
    }

    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t f = comp_faces[i];
      if (!flip[f]) continue;
      std::reverse(mesh.corners.begin() + mesh.face_offsets[f] + 1,
                   mesh.corners.begin() + mesh.face_offsets[f + 1]);
      if (rep.flipped++ < options.list_cap) rep.flipped_faces.push_back(f);
    }
    out.flipped += rep.flipped;
    out.conflicts += rep.conflicts;
    if (rep.flipped > 0) out.components.push_back(std::move(rep));
  }
  return out;
}

}  // namespace pgamesh
