#include "pgamesh/mesh/topology/orientation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/polygon_face.hpp"
#include "pgamesh/mesh/topology/components.hpp"
#include "pgamesh/mesh/topology/edges.hpp"
#include "pgamesh/mesh/topology/shell_nesting.hpp"
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
  std::vector<ComponentOrientation> reps(comps.count());
  std::vector<std::size_t> walk_flipped(comps.count(), 0);
  std::vector<double> area(comps.count(), 0), diagonal(comps.count(), 0);
  for (std::size_t k = 0; k < comps.count(); ++k) {
    ComponentOrientation& rep = reps[k];
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

    // Signed volume and area with the walk's flips, about the component's bounding-box centre
    // (docs/conventions.md §13).
    Box3 box;
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t f = comp_faces[i];
      for (std::uint32_t c = mesh.face_offsets[f]; c < mesh.face_offsets[f + 1]; ++c)
        box.add(mesh.vertices[mesh.corners[c]]);
    }
    const Vec3d ref = box.centre();
    diagonal[k] = box.diagonal();
    BoundarySums sums;
    for (std::uint32_t i = comp_start[k]; i < comp_start[k + 1]; ++i) {
      const std::uint32_t f = comp_faces[i];
      const std::uint32_t begin = mesh.face_offsets[f], n = mesh.face_offsets[f + 1] - begin;
      BoundarySums s = polygon_face_sums(n, [&](std::size_t j) {
        return mesh.vertices[weld.representative[welded_corner[begin + j]]] - ref;
      });
      if (flip[f]) {
        s.volume6 = -s.volume6;
        ++walk_flipped[k];
      }
      sums.volume6 += s.volume6;
      sums.area2 += s.area2;
    }
    rep.volume = body_moments(sums).volume;
    area[k] = sums.area2 / 2;
  }

  // The depth of each closed component among the others, on the faces as the walk turned them
  // (the winding number needs each shell consistent, not outward).
  std::vector<std::uint8_t> is_shell(comps.count(), 0);
  for (std::size_t k = 0; k < comps.count(); ++k) is_shell[k] = reps[k].closed ? 1 : 0;
  const std::vector<std::uint32_t> depth =
      shell_depths(comps.face_component, is_shell, [&](std::uint32_t f, std::vector<Vec3d>& out) {
        out.clear();
        const std::uint32_t begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
        for (std::uint32_t c = begin; c < end; ++c)
          out.push_back(mesh.vertices[weld.representative[welded_corner[c]]]);
        if (flip[f]) std::reverse(out.begin() + 1, out.end());
      });

  OrientationFix out;
  for (std::size_t k = 0; k < comps.count(); ++k) {
    ComponentOrientation& rep = reps[k];
    // A closed shell faces the way its depth asks (docs/conventions.md §8); a rounding residue
    // has no inside and, like an open component, keeps the orientation most of its faces had
    // (ties: its lowest face's).
    const ShellOrientation verdict =
        rep.closed ? judge_shell(rep.volume, depth[k], area[k], [&] { return diagonal[k]; })
                   : ShellOrientation::undecided;
    rep.depth = rep.closed ? depth[k] : 0;
    const bool reverse_all =
        verdict == ShellOrientation::wrong ||
        (verdict == ShellOrientation::undecided && 2 * walk_flipped[k] > rep.faces);
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
