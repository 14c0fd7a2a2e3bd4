#include "mesh/topology/topology_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "pgamesh/core/bounding_box.hpp"
#include "pgamesh/geometry/carrier.hpp"
#include "pgamesh/geometry/gap.hpp"
#include "pgamesh/geometry/polygon_face.hpp"
#include "pgamesh/mesh/topology/self_intersections.hpp"
#include "pgamesh/mesh/topology/shell_nesting.hpp"

namespace pgamesh::detail {

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
    r.notes.push_back(
        "orientation inconsistent: " + n(r.inconsistent_edges) +
        " edges are used by two or more faces in the same direction; volume, centre of mass and "
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
  if (r.inward_components > 0)
    r.notes.push_back("inward: " + n(r.inward_components) +
                      " closed components face the wrong way for their nesting (an outer skin or "
                      "island with negative volume, or a cavity with positive volume; "
                      "--fix-orientation reverses them)");
  if (r.self_intersecting_pairs > 0)
    r.notes.push_back(
        "self-intersecting: " + std::string(r.self_intersections_complete ? "" : "at least ") +
        n(r.self_intersecting_pairs) +
        " face pairs intersect; the volume counts the overlap twice or not at all, "
        "so volume, centre of mass and inertia are not those of a solid");
  if (r.zero_area_faces + r.small_area_faces > 0)
    r.notes.push_back("degenerate faces: " + n(r.zero_area_faces) + " with zero area, " +
                      n(r.small_area_faces) + " nearly zero; they do not change area or volume");
  if (r.components > 1) r.notes.push_back(n(r.components) + " connected components");
}

// The self-intersections of the welded faces (self_intersections.hpp). A pass that keeps no corner
// array (the PLY pass) has them read once more through the lookup.
void find_face_intersections(TopologyTally& t) {
  TopologyReport& r = t.r;
  const WeldedFaces& mesh = t.mesh;
  std::vector<std::uint32_t> looked_up;
  std::span<const std::uint32_t> corners = mesh.corners;
  if (corners.empty() && r.faces > 0) {
    const std::size_t count = mesh.face_offsets.empty() ? 3 * r.faces : mesh.face_offsets.back();
    looked_up.resize(count);
    for (std::size_t c = 0; c < count; ++c)
      looked_up[c] = mesh.corner_lookup(static_cast<std::uint32_t>(c));
    corners = looked_up;
  }
  SelfIntersections found =
      find_self_intersections(mesh.positions, corners, mesh.face_offsets, t.cap);
  r.self_intersections_checked = true;
  r.self_intersecting_pairs = found.pairs;
  r.self_intersections_complete = found.complete;
  r.self_intersection_list = std::move(found.list);
}

// The mean of k corners, corner(i) the i-th.
template <class CornerAt>
Vec3d centroid_of(std::uint32_t k, const CornerAt& corner) {
  Vec3d c{};
  for (std::uint32_t i = 0; i < k; ++i) c += corner(i);
  return k > 0 ? c / static_cast<double>(k) : c;
}

// The mean of the face's corners.
Vec3d face_centroid(const WeldedFaces& mesh, std::uint32_t f) {
  const std::uint32_t begin = mesh.begin(f);
  return centroid_of(mesh.size(f),
                     [&](std::uint32_t i) { return mesh.corner_position(begin + i); });
}

// 2 × the face's vector area about its own first corner (polygon_normal): exact zero for a face
// whose corners are collinear in the digits they have.
Vec3d own_normal(const WeldedFaces& mesh, std::uint32_t f) {
  const std::uint32_t begin = mesh.begin(f);
  return polygon_normal(mesh.size(f), [&](std::size_t i) {
    return mesh.corner_position(begin + static_cast<std::uint32_t>(i));
  });
}

// The surface parts of polygon_face_sums — area2, carrier_sum, volume6, all the report uses —
// from the same fan carriers with the same additions, without the first and second moments: of
// the k corners corner(i).
template <class CornerAt>
BoundarySums surface_sums(std::uint32_t k, const CornerAt& corner, Vec3d ref) {
  BoundarySums p;
  if (k < 3) return p;
  auto relative = [&](std::size_t i) { return corner(static_cast<std::uint32_t>(i)) - ref; };
  const Vec3d a = relative(0);
  Vec3d b = relative(1);
  pga3::Plane<double> f{};
  for (std::uint32_t i = 2; i < k; ++i) {
    const Vec3d c = relative(i);
    const pga3::Plane<double> carrier = triangle_carrier(a, b, c);
    p.volume6 += origin_join(carrier);  // as add_tetrahedron
    f += carrier;
    b = c;
  }
  if (k == 3)
    add_face_carrier(p, f);
  else
    add_polygon_surface(p, k, relative, f);
  return p;
}

// surface_sums of face f.
BoundarySums face_surface_sums(const WeldedFaces& mesh, std::uint32_t f, Vec3d ref) {
  const std::uint32_t begin = mesh.begin(f);
  return surface_sums(
      mesh.size(f), [&](std::uint32_t i) { return mesh.corner_position(begin + i); }, ref);
}

// total += s for the surface parts (BoundarySums::operator+= field by field).
void add_surface(BoundarySums& total, const BoundarySums& s) {
  total.area2 += s.area2;
  total.carrier_sum.e0 += s.carrier_sum.e0;
  total.carrier_sum.e1 += s.carrier_sum.e1;
  total.carrier_sum.e2 += s.carrier_sum.e2;
  total.carrier_sum.e3 += s.carrier_sum.e3;
  total.volume6 += s.volume6;
}

}  // namespace

void check_topology_options(const TopologyOptions& options) {
  if (!(options.area_threshold >= 0) || !std::isfinite(options.area_threshold))
    throw std::invalid_argument("area threshold must be a finite number >= 0");
}

namespace {

// The degenerate-face part of tally_face: face f (k corners, corner(i) its i-th position) is
// counted as zero-area or small when it is. Degenerate faces are judged on the normal about the
// face's own first corner (digits).
template <class CornerAt>
void tally_degenerate(TopologyTally& t, std::uint32_t f, bool collapsed, std::uint32_t k,
                      CornerAt corner) {
  TopologyReport& r = t.r;
  const Vec3d n = polygon_normal(k, corner);  // own_normal
  const bool zero = collapsed || (n.x == 0 && n.y == 0 && n.z == 0);
  bool small = false;
  double own_area = 0;
  if (!zero) {
    double longest2 = 0;
    for (std::uint32_t i = 0; i < k; ++i) {
      const Vec3d d = corner((i + 1) % k) - corner(i);
      longest2 = std::max(longest2, dot(d, d));
    }
    const double bound = t.area_threshold * longest2;
    // Nearly every face is far from small: when ‖n‖² exceeds (2 bound)² by a margin much wider
    // than the rounding of either side, own_area = ½‖n‖ > bound is certain without the square
    // root (for bound in the normal range; below it the exact test decides).
    if (bound > 1e-100 && dot(n, n) > 4 * bound * bound * (1 + 1e-9)) return;
    own_area = 0.5 * length(n);
    small = own_area <= bound;
    if (!small) return;
  } else {
    own_area = 0.5 * length(n);
  }
  FaceLocation loc;
  loc.face = f;
  loc.area = own_area;
  loc.centroid = centroid_of(k, corner);
  if (zero) {
    if (r.zero_area_faces++ < t.cap) r.zero_area_list.push_back(loc);
  } else {
    if (r.small_area_faces++ < t.cap) r.small_area_list.push_back(loc);
  }
}

}  // namespace

void tally_face(TopologyTally& t, std::uint32_t f, bool collapsed) {
  const WeldedFaces& mesh = t.mesh;
  const std::uint32_t begin = mesh.begin(f), k = mesh.size(f);
  if (k == 3) {
    const std::array<Vec3d, 3> p{mesh.corner_position(begin), mesh.corner_position(begin + 1),
                                 mesh.corner_position(begin + 2)};
    const Vec3d ref = t.r.reference_point;
    const pga3::Plane<double> carrier = triangle_carrier(p[0] - ref, p[1] - ref, p[2] - ref);
    tally_triangle(t, f, collapsed, p, carrier, pga3::norm(carrier));
    return;
  }
  if (k >= 3) t.r.triangles += k - 2;
  add_surface(t.total, face_surface_sums(mesh, f, t.r.reference_point));
  tally_degenerate(t, f, collapsed, k, [&](std::size_t i) {
    return mesh.corner_position(begin + static_cast<std::uint32_t>(i));
  });
}

void tally_triangle(TopologyTally& t, std::uint32_t f, bool collapsed,
                    const std::array<Vec3d, 3>& corner, const pga3::Plane<double>& carrier,
                    double carrier_norm) {
  t.r.triangles += 1;
  // face_surface_sums of a triangle, with the same additions.
  BoundarySums p;
  p.volume6 += origin_join(carrier);
  add_face_carrier(p, carrier, carrier_norm);
  add_surface(t.total, p);
  tally_degenerate(t, f, collapsed, 3, [&](std::size_t i) { return corner[i]; });
}

bool start_component_sums(TopologyTally& t) {
  const std::size_t n = t.components.size();
  t.area2.assign(n, 0.0);
  t.volume6.assign(n, 0.0);
  if (n == 1 && t.components[0].faces == t.r.faces) {
    t.area2[0] = t.total.area2;
    t.volume6[0] = t.total.volume6;
    return true;
  }
  return false;
}

void add_component_triangle(TopologyTally& t, std::uint32_t component,
                            const std::array<Vec3d, 3>& corner) {
  const BoundarySums s = surface_sums(
      3, [&](std::uint32_t i) { return corner[i]; }, t.r.reference_point);
  t.area2[component] += s.area2;
  t.volume6[component] += s.volume6;
}

void tally_component_sums(TopologyTally& t, std::span<const std::uint32_t> face_component) {
  t.face_component = face_component;
  if (start_component_sums(t)) return;
  for (std::size_t f = 0; f < face_component.size(); ++f) {
    const std::uint32_t k = face_component[f];
    if (k == no_edge) continue;
    const BoundarySums s =
        face_surface_sums(t.mesh, static_cast<std::uint32_t>(f), t.r.reference_point);
    t.area2[k] += s.area2;
    t.volume6[k] += s.volume6;
  }
}

void tally_edge(TopologyTally& t, std::uint32_t v0, std::uint32_t v1, std::uint32_t face,
                std::size_t uses, std::size_t forward, std::uint32_t component) {
  TopologyReport& r = t.r;
  auto location = [&] {
    EdgeLocation loc;
    loc.face = face;
    loc.vertex0 = t.mesh.input_vertex(v0);
    loc.vertex1 = t.mesh.input_vertex(v1);
    loc.p0 = t.mesh.positions[v0];
    loc.p1 = t.mesh.positions[v1];
    loc.face_count = static_cast<std::uint32_t>(uses);
    return loc;
  };
  const std::size_t backward = uses - forward;
  const std::size_t imbalance = forward > backward ? forward - backward : backward - forward;
  ComponentSummary& comp = t.components[component];
  if (uses == 1) {
    ++comp.boundary_edges;
    if (r.boundary_edges++ < t.cap) r.boundary_edge_list.push_back(location());
    return;
  }
  // Uses pair up in opposite directions; an odd one out is allowed for an odd count.
  if (imbalance > uses % 2) {
    ++comp.inconsistent_edges;
    if (r.inconsistent_edges++ < t.cap) r.inconsistent_edge_list.push_back(location());
  }
  if (uses > 2) {
    ++comp.nonmanifold_edges;
    if (r.nonmanifold_edges++ < t.cap) r.nonmanifold_edge_list.push_back(location());
  }
}

void finish_report(TopologyTally& t,
                   std::span<const std::pair<std::uint32_t, std::uint32_t>> duplicates,
                   std::vector<BoundaryLoop> loops) {
  TopologyReport& r = t.r;
  const Vec3d ref = r.reference_point;
  const BodyMoments moments = body_moments(t.total);
  r.area = moments.area;
  r.volume = moments.volume;
  r.gap_area = moments.gap_area;
  r.gap_vector = gap_vector(t.total);
  r.carrier_sum = t.total.carrier_sum;
  // About the origin: a carrier built from a − ref has e0 = −n·(a − ref) = e0(origin) + n·ref.
  r.carrier_sum.e0 -= dot(t.total.carrier_sum.normal(), ref);

  // The range of V(q) over the vertices q, for an open surface: V is affine in q, so its extremes
  // over the mesh's convex hull are at vertices (gap.hpp). A closed surface's Σ F has no normal
  // part beyond rounding, and V does not depend on q.
  r.volume_min = r.volume_max = r.volume;
  if (r.boundary_edges > 0) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec3d& p : t.mesh.positions) {
      const double v = volume_about(t.total, p - ref);
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
  r.closed = r.faces > 0 && r.edges > 0 && r.boundary_edges == 0 && r.nonmanifold_edges == 0 &&
             r.inconsistent_edges == 0;

  r.components = t.components.size();
  std::vector<std::uint8_t> is_shell(t.components.size(), 0);
  for (std::size_t k = 0; k < t.components.size(); ++k) {
    ComponentSummary& s = t.components[k];
    s.area = t.area2[k] / 2;
    s.volume = t.volume6[k] / 6;
    s.closed = s.boundary_edges == 0 && s.nonmanifold_edges == 0 && s.inconsistent_edges == 0;
    is_shell[k] = s.closed ? 1 : 0;
    if (s.closed) ++r.closed_components;
  }
  // Orientation by nesting (docs/conventions.md §8): the volumes are about the reference point,
  // the centre of the box of every vertex, so that box's diagonal bounds the apex distances.
  const std::vector<std::uint32_t> depth =
      shell_depths(t.face_component, is_shell, [&](std::uint32_t f, std::vector<Vec3d>& out) {
        out.clear();
        for (std::uint32_t c = t.mesh.begin(f), end = c + t.mesh.size(f); c < end; ++c)
          out.push_back(t.mesh.corner_position(c));
      });
  double mesh_diagonal = -1;  // computed at the first shell that needs it
  auto diagonal = [&] {
    if (mesh_diagonal < 0) {
      Box3 box;
      for (const Vec3d& p : t.mesh.positions) box.add(p);
      mesh_diagonal = box.diagonal();
    }
    return mesh_diagonal;
  };
  for (std::size_t k = 0; k < t.components.size(); ++k) {
    ComponentSummary& s = t.components[k];
    if (s.closed) {
      s.depth = depth[k];
      // A residue encloses nothing: at odd depth it is not a cavity.
      s.cavity = s.depth % 2 == 1 && std::abs(s.volume) > volume_residue_bound(s.area, diagonal());
      s.inward = judge_shell(s.volume, s.depth, s.area, diagonal) == ShellOrientation::wrong;
      if (s.cavity) ++r.cavity_components;
      if (s.inward) ++r.inward_components;
    }
    if (k < t.cap) r.component_list.push_back(s);
  }

  r.duplicated_faces = duplicates.size();
  for (const auto& d : duplicates) {
    const Vec3d n = own_normal(t.mesh, d.first);  // duplicated faces are never collapsed
    r.duplicated_area_faces += (n.x == 0 && n.y == 0 && n.z == 0) ? 0 : 1;
  }
  for (std::size_t i = 0; i < duplicates.size() && i < t.cap; ++i) {
    FaceLocation loc;
    loc.face = duplicates[i].first;
    loc.same_as = duplicates[i].second;
    loc.area = face_surface_sums(t.mesh, loc.face, ref).area2 / 2;
    loc.centroid = face_centroid(t.mesh, loc.face);
    r.duplicated_list.push_back(loc);
  }

  r.boundary_loops = std::move(loops);
  for (const BoundaryLoop& loop : r.boundary_loops) r.loops_area += loop.area;

  if (t.self_intersections) find_face_intersections(t);

  r.volume_valid = r.faces > 0 && r.boundary_edges == 0 && r.orientation_consistent &&
                   r.duplicated_area_faces == 0 && r.self_intersecting_pairs == 0;
  write_notes(r);
}

}  // namespace pgamesh::detail
