#include "pgamesh/mesh/repair/repair.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "pgamesh/mesh/topology/self_intersections.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace pgamesh {

namespace {

// The faces of `mesh` kept by `keep`, in order; `origin` (face → input face) follows them.
Mesh keep_faces(Mesh&& mesh, const std::vector<char>& keep, std::vector<std::uint32_t>& origin) {
  Mesh out;
  out.vertices = std::move(mesh.vertices);
  std::vector<std::uint32_t> kept_origin;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    if (!keep[f]) continue;
    out.corners.insert(out.corners.end(), mesh.face(f), mesh.face(f) + mesh.face_size(f));
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
    kept_origin.push_back(origin[f]);
  }
  origin = std::move(kept_origin);
  return out;
}

void list(std::vector<std::uint32_t>& to, std::uint32_t face, std::size_t cap) {
  if (to.size() < cap) to.push_back(face);
}

// Step 2: consecutive corners on one vertex merged (cyclically); faces with fewer than three
// distinct vertices marked for removal.
void merge_repeated_corners(Mesh& mesh, std::vector<char>& keep, RepairReport& report,
                            const std::vector<std::uint32_t>& origin, std::size_t cap) {
  Mesh out;
  out.vertices = std::move(mesh.vertices);
  std::vector<std::uint32_t> face;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    face.assign(mesh.face(f), mesh.face(f) + mesh.face_size(f));
    const std::size_t before = face.size();
    face.erase(std::unique(face.begin(), face.end()), face.end());
    while (face.size() > 1 && face.front() == face.back()) face.pop_back();
    std::vector<std::uint32_t> distinct = face;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (distinct.size() < 3) {
      keep[f] = 0;
      ++report.collapsed_faces;
      list(report.removed_faces, origin[f], cap);
    } else {
      report.repeated_corners += before - face.size();
    }
    out.corners.insert(out.corners.end(), face.begin(), face.end());
    out.face_offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
  }
  mesh = std::move(out);
}

// The face's vertex cycle from its lowest vertex, forward or reversed: equal for faces that run
// the same cycle (in that direction).
std::vector<std::uint32_t> cycle_key(const std::uint32_t* corners, std::size_t n, bool reversed) {
  std::vector<std::uint32_t> c(corners, corners + n);
  if (reversed) std::reverse(c.begin(), c.end());
  std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

// Step 3: later copies of a face dropped; a face and its reverse both dropped.
void remove_duplicate_faces(const Mesh& mesh, std::vector<char>& keep, RepairReport& report,
                            const std::vector<std::uint32_t>& origin, std::size_t cap) {
  std::map<std::vector<std::uint32_t>, std::uint32_t> live;  // cycle → the face that runs it
  for (std::uint32_t f = 0; f < mesh.face_count(); ++f) {
    if (!keep[f]) continue;
    auto forward = cycle_key(mesh.face(f), mesh.face_size(f), false);
    if (live.count(forward)) {
      keep[f] = 0;
      ++report.duplicate_faces;
      list(report.removed_faces, origin[f], cap);
      continue;
    }
    const auto opposite = live.find(cycle_key(mesh.face(f), mesh.face_size(f), true));
    if (opposite != live.end()) {
      keep[f] = keep[opposite->second] = 0;
      ++report.opposite_pairs;
      list(report.removed_faces, origin[opposite->second], cap);
      list(report.removed_faces, origin[f], cap);
      live.erase(opposite);
      continue;
    }
    live.emplace(std::move(forward), f);
  }
}

// Orients the mesh (fix_orientation) and toggles `reversed` for every face it turned.
std::size_t orient(Mesh& mesh, double weld_tolerance, std::vector<char>& reversed) {
  OrientationOptions o;
  o.weld_tolerance = weld_tolerance;
  o.list_cap = std::numeric_limits<std::size_t>::max();
  const OrientationFix fix = fix_orientation(mesh, o);
  for (const ComponentOrientation& c : fix.components)
    for (std::uint32_t f : c.flipped_faces) reversed[f] ^= 1;
  return fix.conflicts;
}

// Step 7: the vertices no face uses removed, the others kept in their order.
std::size_t drop_unreferenced_vertices(Mesh& mesh) {
  constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> renumber(mesh.vertices.size(), unused);
  for (std::uint32_t c : mesh.corners) renumber[c] = 0;
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (renumber[v] != unused) {
      mesh.vertices[kept] = mesh.vertices[v];
      renumber[v] = kept++;
    }
  for (std::uint32_t& c : mesh.corners) c = renumber[c];
  const std::size_t dropped = mesh.vertices.size() - kept;
  mesh.vertices.resize(kept);
  return dropped;
}

// A cap is laid in its rim's plane without looking at the rest of the mesh: a part whose wall
// bulges into the hole's plane, or two holes facing each other across a thin slot, would get a cap
// through a face. The mesh with its caps is searched for intersecting faces, and every cap with a
// triangle in an intersecting pair (against a face of the mesh or another hole's cap) is taken out
// again and its hole refused. Caps are faces [first_cap_face, …) of `mesh`; cap_hole_of[k] is the
// hole of cap face first_cap_face + k.
Mesh without_crossing_caps(Mesh&& mesh, std::size_t first_cap_face,
                           const std::vector<std::size_t>& cap_hole_of,
                           std::vector<CappedHole>& holes) {
  // The mesh is welded (step 1): the search takes its vertices as they are, without welding again.
  const SelfIntersections found = find_self_intersections(
      mesh.vertices, mesh.corners, mesh.face_offsets, std::numeric_limits<std::size_t>::max());
  const auto hole_of = [&](std::uint32_t f) {
    return f < first_cap_face ? holes.size() : cap_hole_of[f - first_cap_face];
  };
  std::vector<char> crossing(holes.size(), 0);
  for (const SelfIntersection& x : found.list) {
    const std::size_t h0 = hole_of(x.face0), h1 = hole_of(x.face1);
    if (h0 == h1) continue;  // two faces of the mesh, or of one cap (meeting along its diagonals)
    for (const std::size_t h : {h0, h1})
      if (h < holes.size() && !crossing[h]) {
        crossing[h] = 1;
        const std::uint32_t other = h == h0 ? x.face1 : x.face0;
        holes[h].refused = other < first_cap_face
                               ? "its cap would cross the mesh (at face " + std::to_string(other) +
                                     " of the welded mesh)"
                               : "its cap would cross the cap of another hole";
        holes[h].triangles = 0;
      }
  }
  if (!found.complete) {  // more than a million pairs: the caps could not all be checked
    for (CappedHole& hole : holes)
      if (hole.refused.empty() && hole.triangles > 0) {
        hole.refused = "its cap could not be checked against the mesh (the mesh has over " +
                       std::to_string(max_counted_intersections) + " intersecting face pairs)";
        hole.triangles = 0;
      }
  }
  std::vector<char> keep(mesh.face_count(), 1);
  for (std::size_t k = 0; k < cap_hole_of.size(); ++k)
    if (!holes[cap_hole_of[k]].refused.empty()) keep[first_cap_face + k] = 0;
  std::vector<std::uint32_t> unused_origin(mesh.face_count());
  return keep_faces(std::move(mesh), keep, unused_origin);
}

}  // namespace

RepairReport repair(Mesh& mesh, const RepairOptions& options) {
  check_mesh_structure(mesh);
  RepairReport report;
  const std::size_t cap = options.list_cap;
  report.input_vertices = mesh.vertices.size();
  report.input_faces = mesh.face_count();

  // 1. Weld.
  WeldResult welded = weld(std::move(mesh), options.weld_tolerance);
  report.merged_vertices = welded.map.merged;
  report.weld_tolerance = welded.map.tolerance;
  report.weld_max_moved = welded.map.max_moved;
  Mesh m = std::move(welded.mesh);

  // 2, 3. Faces that bound nothing.
  std::vector<std::uint32_t> origin(m.face_count());  // face → input face
  for (std::uint32_t f = 0; f < origin.size(); ++f) origin[f] = f;
  std::vector<char> keep(m.face_count(), 1);
  merge_repeated_corners(m, keep, report, origin, cap);
  if (options.remove_duplicate_faces) remove_duplicate_faces(m, keep, report, origin, cap);
  m = keep_faces(std::move(m), keep, origin);

  // 4. A consistent orientation, so that each hole's rim runs one way.
  std::vector<char> reversed(m.face_count(), 0);
  if (options.orient) report.orientation_conflicts = orient(m, 0, reversed);

  // 5. Caps, on the closed boundary loops of the welded mesh (found and reported even when caps
  // are not asked for).
  {
    TopologyOptions t;
    t.list_cap = 0;
    t.self_intersections = false;  // only the loops are wanted here
    const TopologyReport r = analyze_topology(m, t);
    // A rim that is one face's outline (a lone face, a flap) is no hole: its cap would be that
    // face again, reversed — a double wall.
    std::map<std::vector<std::uint32_t>, char> outlines;
    if (!r.boundary_loops.empty())
      for (std::size_t f = 0; f < m.face_count(); ++f)
        outlines.emplace(cycle_key(m.face(f), m.face_size(f), false), 1);
    const std::size_t first_cap_face = m.face_count();
    std::vector<std::size_t> cap_hole_of;  // cap face − first_cap_face → its hole in report.holes
    for (const BoundaryLoop& loop : r.boundary_loops) {
      CappedHole hole;
      std::vector<std::uint32_t> rim;
      rim.reserve(loop.half_edges.size());
      // The loops name corners of the mesh as it was; caps are appended after them.
      for (std::uint32_t c : loop.half_edges) rim.push_back(m.corners[c]);
      hole.rim_vertices = rim.size();
      if (!rim.empty()) hole.first_vertex = m.vertices[rim.front()];
      if (!options.cap_holes) {
        hole.refused = "left open (caps not asked for)";
      } else if (!loop.closed) {
        hole.refused =
            "an open chain of boundary edges (the orientation around it is not "
            "consistent)";
      } else if (outlines.count(cycle_key(rim.data(), rim.size(), false)) ||
                 outlines.count(cycle_key(rim.data(), rim.size(), true))) {
        hole.refused = "the rim is the outline of one face: its cap would double that face";
      } else {
        const HoleCap c = cap_hole(m.vertices, rim, options.hole);
        hole.area = c.area;
        hole.max_deviation = c.max_deviation;
        hole.refused = c.refused;
        hole.triangles = c.triangles.size();
        for (const auto& tri : c.triangles) {
          m.add_face({tri[0], tri[1], tri[2]});
          cap_hole_of.push_back(report.holes.size());
        }
      }
      report.holes.push_back(std::move(hole));
    }
    if (!cap_hole_of.empty())
      m = without_crossing_caps(std::move(m), first_cap_face, cap_hole_of, report.holes);
    for (const CappedHole& hole : report.holes) {
      if (hole.refused.empty()) {
        ++report.holes_capped;
        report.cap_triangles += hole.triangles;
      } else {
        ++report.holes_refused;
      }
    }
    reversed.resize(m.face_count(), 0);
  }

  // 6. Orientation by nesting, now that the shells are closed.
  if (options.orient) report.orientation_conflicts = orient(m, 0, reversed);
  for (std::size_t f = 0; f < origin.size(); ++f)  // input faces only: caps are new
    if (reversed[f]) {
      ++report.reversed_faces;
      list(report.reversed_list, origin[f], cap);
    }

  // 7. Vertices no face uses.
  report.unreferenced_vertices = drop_unreferenced_vertices(m);
  report.output_vertices = m.vertices.size();
  report.output_faces = m.face_count();
  mesh = std::move(m);
  return report;
}

}  // namespace pgamesh
