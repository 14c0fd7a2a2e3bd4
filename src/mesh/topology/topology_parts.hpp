// The parts of the topology report shared by the topology pass (welded_topology.cpp, both its face
// layouts) and the PLY pass that re-reads its faces from the file (ply_topology.cpp): how a face
// and an edge count in the report, and how the report is finished. Every route feeds them the same
// faces and edges in the same order, so they give the same report bit for bit. Internal to the
// library.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "pgamesh/geometry/body_moments.hpp"
#include "pgamesh/mesh/topology/topology.hpp"

namespace pgamesh::detail {

// A welded mesh as the shared parts see it.
struct WeldedFaces {
  std::span<const Vec3d> positions;               // welded vertex → coordinates
  std::span<const std::uint32_t> representative;  // welded vertex → lowest input vertex; empty: w
  std::span<const std::uint32_t> corners;         // corner → welded vertex
  std::span<const std::uint32_t> face_offsets;    // CSR; empty when every face is a triangle
  // When `corners` is empty: corner c's welded vertex, looked up elsewhere (the PLY pass keeps no
  // corner array and reads the few faces the report names from the file: ply_topology.cpp).
  std::function<std::uint32_t(std::uint32_t)> corner_lookup = {};

  std::uint32_t begin(std::size_t f) const {
    return face_offsets.empty() ? static_cast<std::uint32_t>(3 * f) : face_offsets[f];
  }
  std::uint32_t size(std::size_t f) const {
    return face_offsets.empty() ? 3 : face_offsets[f + 1] - face_offsets[f];
  }
  Vec3d corner_position(std::uint32_t c) const {
    return positions[corners.empty() ? corner_lookup(c) : corners[c]];
  }
  std::uint32_t input_vertex(std::uint32_t w) const {
    return representative.empty() ? w : representative[w];
  }
};

// The sums a report is built from, face by face and edge by edge.
struct TopologyTally {
  TopologyTally(TopologyReport& report, const WeldedFaces& faces, const TopologyOptions& options)
      : r(report),
        mesh(faces),
        cap(options.list_cap),
        area_threshold(options.area_threshold),
        self_intersections(options.self_intersections) {}

  TopologyReport& r;
  const WeldedFaces& mesh;
  std::size_t cap;
  double area_threshold;
  bool self_intersections;                   // finish_report looks for them
  std::vector<ComponentSummary> components;  // first_face and faces filled by the caller
  std::vector<double> area2, volume6;        // per component, Σ ‖F‖ and Σ o ∨ F
  // Face → component (no_edge: none), kept by tally_component_sums for the nesting of closed
  // components in finish_report; a pass that keeps no corner array sets it itself.
  std::span<const std::uint32_t> face_component;
  BoundarySums total;  // only the surface parts: area2, carrier_sum, volume6
};

// Throws std::invalid_argument for a bad option.
void check_topology_options(const TopologyOptions& options);

// Face f: its sums about r.reference_point into the total, its triangle count and whether it has
// zero or small area. Call in face order. Touches neither `components` nor `area2`/`volume6`, so it
// may run while another thread finds the components.
void tally_face(TopologyTally& t, std::uint32_t f, bool collapsed);

// Triangle f whose corners are `corner` (welded coordinates) and whose carrier about
// r.reference_point is `carrier` (triangle_carrier of the corners minus the reference point, as
// add_triangle forms it): what tally_face does for a triangle, without forming the carrier again —
// the pass on welded triangles computes it and its norm (pga3::norm(carrier)) once for the mass
// sums and the tally.
void tally_triangle(TopologyTally& t, std::uint32_t f, bool collapsed,
                    const std::array<Vec3d, 3>& corner, const pga3::Plane<double>& carrier,
                    double carrier_norm);

// The per-component sums, once every face has been tallied: face_component[f] is f's component
// or no_edge. When one component holds every face its sums are the total's (the same additions in
// the same order); otherwise a second pass over the faces.
void tally_component_sums(TopologyTally& t, std::span<const std::uint32_t> face_component);

// tally_component_sums in parts, for a pass that keeps no corner array: sizes the per-component
// sums and returns true when one component holds every face (its sums are the total's); else call
// add_component_triangle for every face that has a component, in face order.
bool start_component_sums(TopologyTally& t);
void add_component_triangle(TopologyTally& t, std::uint32_t component,
                            const std::array<Vec3d, 3>& corner);

// The edge {v0 < v1} with `uses` half-edges, `forward` of them running v0 → v1, lowest face
// `face` in `component`: boundary, inconsistent, non-manifold. Call in edge order ((v0, v1)
// ascending); edges used twice in opposite directions may be left out.
void tally_edge(TopologyTally& t, std::uint32_t v0, std::uint32_t v1, std::uint32_t face,
                std::size_t uses, std::size_t forward, std::uint32_t component);

// After every face and edge: totals, gap and volume range, closedness, components and their
// nesting (t.face_component must still be alive when two or more are closed), the duplicated
// faces (face, earlier face with the same vertices; ascending by face), the boundary loops, the
// self-intersections when asked for (the faces' corners read through t.mesh) and the notes.
void finish_report(TopologyTally& t,
                   std::span<const std::pair<std::uint32_t, std::uint32_t>> duplicates,
                   std::vector<BoundaryLoop> loops);

}  // namespace pgamesh::detail
