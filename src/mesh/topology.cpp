#include "pgamesh/mesh/topology.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/geometry/gap.hpp"
#include "pgamesh/geometry/polygon_face.hpp"
#include "pgamesh/mesh/components.hpp"
#include "pgamesh/mesh/duplicate_faces.hpp"
#include "pgamesh/mesh/reference_point.hpp"
#include "pgamesh/mesh/weld.hpp"

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

namespace {

std::string format_double(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// Notes that say in plain words what the numbers mean for this mesh (docs/topology.md).
void write_notes(TopologyReport& r) {
  auto n = [](std::size_t k) { return std::to_string(k); };
  if (r.faces == 0) r.notes.push_back("empty mesh: no faces");
  if (r.boundary_edges > 0)
    r.notes.push_back("open: " + n(r.boundary_edges) + " boundary edges in " +
                      n(r.boundary_loops.size()) + " loops, gap area " + format_double(r.gap_area) +
                      "; volume, centre of mass and inertia are not meaningful. Capping the holes "
                      "gives a volume between " +
                      format_double(r.volume_min) + " and " + format_double(r.volume_max));
  if (!r.orientation_consistent)
    r.notes.push_back("orientation inconsistent: " + n(r.inconsistent_edges) +
                      " edges are used twice in the same direction; volume, centre of mass and "
                      "inertia are not meaningful (--fix-orientation repairs this)");
  if (r.duplicated_area_faces > 0)
    r.notes.push_back("duplicated faces: " + n(r.duplicated_faces) +
                      " faces repeat an earlier face's vertices; their volume counts twice or "
                      "cancels, so volume, centre of mass and inertia are not meaningful");
  else if (r.duplicated_faces > 0)
    r.notes.push_back("duplicated faces: " + n(r.duplicated_faces) +
                      " faces repeat an earlier face's vertices, all with zero area: no effect on "
                      "area or volume");
  if (r.nonmanifold_edges > 0)
    r.notes.push_back("non-manifold: " + n(r.nonmanifold_edges) +
                      " edges are shared by more than two faces; the volume is the sum over the "
                      "pieces that meet there");
  if (r.negative_components > 0)
    r.notes.push_back("inward: " + n(r.negative_components) +
                      " closed components have negative volume (faces oriented inward; "
                      "--fix-orientation makes them outward)");
  if (r.zero_area_faces + r.small_area_faces > 0)
    r.notes.push_back("degenerate faces: " + n(r.zero_area_faces) + " with zero area, " +
                      n(r.small_area_faces) + " nearly zero; they do not change area or volume");
  if (r.components > 1) r.notes.push_back(n(r.components) + " connected components");
}

}  // namespace

TopologyReport analyze_topology(const Mesh& mesh, const TopologyOptions& options) {
  if (!(options.area_threshold >= 0) || !std::isfinite(options.area_threshold))
    throw std::invalid_argument("area threshold must be a finite number >= 0");
  check_mesh_structure(mesh);
  TopologyReport r;
  const std::size_t face_count = mesh.face_count();
  const std::size_t cap = options.list_cap;
  r.faces = face_count;
  r.input_vertices = mesh.vertices.size();
  r.area_threshold = options.area_threshold;

  // Weld, then describe every corner by its welded vertex.
  const WeldMap weld = weld_map(mesh.vertices, options.weld_tolerance);
  r.vertices = weld.welded_count();
  r.merged_vertices = weld.merged;
  r.weld_tolerance = weld.tolerance;
  r.weld_max_moved = weld.max_moved;
  std::vector<std::uint32_t> welded_corner(mesh.corners.size());
  for (std::size_t c = 0; c < mesh.corners.size(); ++c)
    welded_corner[c] = weld.to_welded[mesh.corners[c]];
  {
    std::vector<std::uint8_t> referenced(r.vertices, 0);
    for (std::uint32_t w : welded_corner) referenced[w] = 1;
    r.unreferenced_vertices =
        static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), std::uint8_t{0}));
  }

  const EdgeTable edges = build_edges(mesh, welded_corner, r.vertices);
  const FaceComponents comps = face_components(mesh, edges);
  r.edges = edges.edge_count();
  r.components = comps.count();
  std::vector<ComponentSummary> per_component(comps.count());
  for (std::size_t k = 0; k < comps.count(); ++k) {
    per_component[k].first_face = comps.first_face[k];
    per_component[k].faces = comps.face_count[k];
  }
  std::vector<double> component_volume6(comps.count(), 0.0);

  // Faces: the boundary sums (area, volume, Σ F) about the reference point, and the degenerate
  // ones.
  r.reference_point = reference_point(mesh);
  const Vec3d ref = r.reference_point;
  auto welded_position = [&](std::uint32_t c) {
    return mesh.vertices[weld.representative[welded_corner[c]]];
  };
  std::vector<std::uint8_t> collapsed(face_count, 0);
  for (std::uint32_t f : edges.collapsed_faces) collapsed[f] = 1;
  r.collapsed_faces = edges.collapsed_faces.size();
  std::vector<std::uint8_t> zero_face(face_count, 0);
  BoundarySums total;
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::uint32_t begin = mesh.face_offsets[f], k = mesh.face_offsets[f + 1] - begin;
    if (k >= 3) r.triangles += k - 2;
    const BoundarySums s =
        polygon_face_sums(k, [&](std::size_t i) { return welded_position(begin + i) - ref; });
    total += s;
    const double area = s.area2 / 2;
    const std::uint32_t comp = comps.face_component[f];
    if (comp != no_edge) {
      per_component[comp].area += area;
      component_volume6[comp] += s.volume6;
    }
    // Degenerate faces are judged on the normal about the face's own first corner (digits).
    const Vec3d n = polygon_normal(k, [&](std::size_t i) { return welded_position(begin + i); });
    const double own_area = 0.5 * length(n);
    const bool zero = collapsed[f] || (n.x == 0 && n.y == 0 && n.z == 0);
    bool small = false;
    if (!zero) {
      double longest2 = 0;
      for (std::uint32_t i = 0; i < k; ++i) {
        const Vec3d d = welded_position(begin + (i + 1) % k) - welded_position(begin + i);
        longest2 = std::max(longest2, dot(d, d));
      }
      small = own_area <= options.area_threshold * longest2;
    }
    zero_face[f] = zero ? 1 : 0;
    if (!zero && !small) continue;
    FaceLocation loc;
    loc.face = static_cast<std::uint32_t>(f);
    loc.area = own_area;
    for (std::uint32_t i = 0; i < k; ++i) loc.centroid += welded_position(begin + i);
    if (k > 0) loc.centroid = loc.centroid / static_cast<double>(k);
    if (zero) {
      if (r.zero_area_faces++ < cap) r.zero_area_list.push_back(loc);
    } else {
      if (r.small_area_faces++ < cap) r.small_area_list.push_back(loc);
    }
  }
  const BodyMoments moments = body_moments(total);
  r.area = moments.area;
  r.volume = moments.volume;
  r.gap_area = moments.gap_area;
  r.gap_vector = gap_vector(total);
  r.carrier_sum = total.carrier_sum;
  // About the origin: a carrier built from a − ref has e0 = −n·(a − ref) = e0(origin) + n·ref.
  r.carrier_sum.e0 -= dot(total.carrier_sum.normal(), ref);

  r.volume_min = r.volume_max = r.volume;
  // Edges: boundary, non-manifold, inconsistently oriented.
  auto edge_location = [&](std::size_t e) {
    EdgeLocation loc;
    const auto uses = edges.uses_of(e);
    loc.face = edges.corner_face[uses[0]];
    loc.vertex0 = weld.representative[edges.v0[e]];
    loc.vertex1 = weld.representative[edges.v1[e]];
    loc.p0 = mesh.vertices[loc.vertex0];
    loc.p1 = mesh.vertices[loc.vertex1];
    loc.face_count = static_cast<std::uint32_t>(uses.size());
    return loc;
  };
  for (std::size_t e = 0; e < edges.edge_count(); ++e) {
    const auto uses = edges.uses_of(e);
    const std::uint32_t comp = comps.face_component[edges.corner_face[uses[0]]];
    std::size_t forward = 0;
    for (std::uint32_t c : uses) forward += is_forward(edges, welded_corner, c) ? 1 : 0;
    const std::size_t backward = uses.size() - forward;
    const std::size_t imbalance = forward > backward ? forward - backward : backward - forward;
    if (uses.size() == 1) {
      ++per_component[comp].boundary_edges;
      if (r.boundary_edges++ < cap) r.boundary_edge_list.push_back(edge_location(e));
    } else {
      // Uses pair up in opposite directions; an odd one out is allowed for an odd count.
      if (imbalance > uses.size() % 2) {
        ++per_component[comp].inconsistent_edges;
        if (r.inconsistent_edges++ < cap) r.inconsistent_edge_list.push_back(edge_location(e));
      }
      if (uses.size() > 2) {
        ++per_component[comp].nonmanifold_edges;
        if (r.nonmanifold_edges++ < cap) r.nonmanifold_edge_list.push_back(edge_location(e));
      }
    }
  }
  // The range of V(q) over the vertices q, for an open surface: V is affine in q, so its extremes
  // over the mesh's convex hull are at vertices (gap.hpp). A closed surface's Σ F has no normal
  // part beyond rounding, and V does not depend on q.
  if (r.boundary_edges > 0) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::uint32_t w = 0; w < r.vertices; ++w) {
      const double v = volume_about(total, mesh.vertices[weld.representative[w]] - ref);
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (lo <= hi) {
      r.volume_min = lo;
      r.volume_max = hi;
    }
  }

  r.orientation_consistent = r.inconsistent_edges == 0;
  r.closed = face_count > 0 && r.edges > 0 && r.boundary_edges == 0 && r.nonmanifold_edges == 0 &&
             r.inconsistent_edges == 0;

  for (std::size_t k = 0; k < comps.count(); ++k) {
    ComponentSummary& s = per_component[k];
    s.volume = component_volume6[k] / 6;
    s.closed = s.boundary_edges == 0 && s.nonmanifold_edges == 0 && s.inconsistent_edges == 0;
    if (s.closed) ++r.closed_components;
    if (s.closed && s.volume < 0) ++r.negative_components;
    if (k < cap) r.component_list.push_back(s);
  }

  const auto dups = duplicated_faces(mesh, edges, welded_corner);
  r.duplicated_faces = dups.size();
  for (const auto& d : dups) r.duplicated_area_faces += zero_face[d.first] ? 0 : 1;
  for (std::size_t i = 0; i < dups.size() && i < cap; ++i) {
    FaceLocation loc;
    loc.face = dups[i].first;
    loc.same_as = dups[i].second;
    const std::uint32_t begin = mesh.face_offsets[loc.face], k = mesh.face_size(loc.face);
    const BoundarySums s =
        polygon_face_sums(k, [&](std::size_t j) { return welded_position(begin + j) - ref; });
    loc.area = s.area2 / 2;
    for (std::uint32_t j = 0; j < k; ++j) loc.centroid += welded_position(begin + j);
    loc.centroid = loc.centroid / static_cast<double>(k);
    r.duplicated_list.push_back(loc);
  }

  r.boundary_loops = boundary_loops(mesh, weld, welded_corner, edges, ref);
  for (const BoundaryLoop& loop : r.boundary_loops) r.loops_area += loop.area;

  r.volume_valid = face_count > 0 && r.boundary_edges == 0 && r.orientation_consistent &&
                   r.duplicated_area_faces == 0;
  write_notes(r);
  return r;
}

}  // namespace pgamesh
