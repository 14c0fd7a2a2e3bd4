#include "mesh/topology/welded_topology.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "detail/memory/uninitialized_array.hpp"
#include "detail/parallel/two_threads.hpp"
#include "geometry/chunked_sums.hpp"
#include "mesh/topology/duplicate_faces.hpp"
#include "mesh/topology/edge_group.hpp"
#include "mesh/topology/face_layout.hpp"
#include "mesh/topology/topology_parts.hpp"
#include "mesh/topology/union_find.hpp"
#include "pgamesh/mesh/topology/boundary_loops.hpp"

namespace pgamesh {

namespace {

using detail::EdgePart;
using detail::OddEdge;
using detail::PolygonLayout;
using detail::TriangleLayout;

// What the edge pass finds.
struct EdgePass {
  std::size_t edges = 0, collapsed_faces = 0;
  // Face → component (numbered by lowest face) or no_edge, for the faces of the mesh.
  detail::UninitializedArray<std::uint32_t> component;
  std::vector<ComponentSummary> components;  // first_face and faces
  std::vector<OddEdge> odd;                  // in edge order
  std::vector<std::uint32_t> sides;          // boundary half-edges
  detail::SameVertexRuns same_vertices;      // for duplicated_faces
};

// Welded vertices that no corner names.
std::size_t unreferenced_vertices(std::span<const std::uint32_t> corners,
                                  std::size_t vertex_count) {
  std::vector<bool> referenced(vertex_count);
  for (std::uint32_t v : corners) referenced[v] = true;
  return static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
}

// The half-edges of one vertex's group, elements (upper end, half-edge) of `layout`, as
// judge_vertex_edges asks about them.
template <class Layout>
class GroupSides {
 public:
  using Element = std::pair<std::uint32_t, std::uint32_t>;
  explicit GroupSides(const Layout& layout) : layout_(layout), same_(layout.same_vertices()) {}

  std::uint32_t half_edge(const Element& e) const { return e.second; }
  std::uint32_t face(const Element& e) const { return layout_.face_of(e.second); }
  bool runs_from(const Element& e, std::uint32_t v) const { return layout_.tail(e.second) == v; }
  bool first_side(const Element& e) const { return layout_.first_side(e.second); }
  bool same_vertices(const Element& a, const Element& b) { return same_(a.second, b.second); }

 private:
  const Layout& layout_;
  typename Layout::SameVertices same_;
};

// The edges whose lower end is in [v_begin, v_end): each vertex's bucket (its half-edges, in
// ascending order, bucket[start[v], start[v + 1])) grouped by upper end, one group per edge, edges
// in (v0, v1) order; the faces on each edge united in `parent`, shared with the other part.
template <class Layout>
void group_edges(const Layout& layout, const std::uint32_t* start, const std::uint32_t* bucket,
                 std::uint32_t v_begin, std::uint32_t v_end, std::uint32_t* parent, EdgePart& out) {
  detail::EdgeGroup group;  // (upper end, half-edge)
  GroupSides<Layout> sides(layout);
  for (std::uint32_t v = v_begin; v < v_end; ++v) {
    group.clear();
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
      const std::uint32_t h = bucket[i];
      group.emplace_back(std::max(layout.tail(h), layout.head(h)), h);
    }
    detail::sort_by_upper_end(group);
    detail::judge_vertex_edges(v, group, sides, parent, out);
  }
}

// The edge pass over the faces of `layout` on `vertex_count` welded vertices, its work cut in two
// parts that run at once when `parallel`: the faces' halves for the counting sort, the vertices'
// halves (by half-edge count) for the grouping. The union–find is shared through atomic
// operations (union_find.hpp); everything else each part writes is its own, and the parts'
// findings are joined in vertex order — the result of one sequential pass.
template <class Layout>
EdgePass edge_pass(const Layout& layout, std::size_t vertex_count, bool parallel) {
  EdgePass out;
  const std::size_t face_count = layout.face_count();
  const std::size_t face_split = face_count / 2;

  // Counting sort of the half-edges on edges by their lower end, each half of the faces counted
  // into its own array; within a bucket the first half's half-edges come first, so every bucket
  // ascends.
  detail::HugeVector<std::uint32_t> start, second_cursor;  // counts first, then fill cursors
  std::size_t collapsed_faces[2] = {0, 0};
  auto count = [&](int part, std::uint32_t* counts) {
    const std::size_t begin = part == 0 ? 0 : face_split, end = part == 0 ? face_split : face_count;
    for (std::size_t f = begin; f < end; ++f) {
      if (layout.collapsed(f)) {
        ++collapsed_faces[part];
        continue;
      }
      layout.for_each_side(
          f, [&](std::uint32_t, std::uint32_t a, std::uint32_t b) { ++counts[std::min(a, b)]; });
    }
  };
  detail::run_both(
      parallel,
      [&] {
        start.assign(vertex_count + 1, 0);
        count(0, start.data());
      },
      [&] {
        second_cursor.assign(vertex_count + 1, 0);
        count(1, second_cursor.data());
      });
  out.collapsed_faces = collapsed_faces[0] + collapsed_faces[1];
  std::uint32_t total = 0;
  for (std::size_t v = 0; v <= vertex_count; ++v) {
    const std::uint32_t first = start[v], second = second_cursor[v];
    start[v] = total;
    second_cursor[v] = total + first;
    total += first + second;
  }
  detail::UninitializedArray<std::uint32_t> bucket =
      detail::uninitialized_array<std::uint32_t>(total);
  auto fill = [&](int part, std::uint32_t* cursor) {
    const std::size_t begin = part == 0 ? 0 : face_split, end = part == 0 ? face_split : face_count;
    for (std::size_t f = begin; f < end; ++f) {
      if (layout.collapsed(f)) continue;
      layout.for_each_side(f, [&](std::uint32_t h, std::uint32_t a, std::uint32_t b) {
        bucket[cursor[std::min(a, b)]++] = h;
      });
    }
  };
  detail::run_both(
      parallel, [&] { fill(0, start.data()); }, [&] { fill(1, second_cursor.data()); });
  // The second cursor has stopped at each bucket's end, the next one's start.
  start[0] = 0;
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] = second_cursor[v];
  detail::HugeVector<std::uint32_t>().swap(second_cursor);  // `= {}` would keep its capacity

  // The union–find starts with every face its own set. Not zero-filled first, and each half set
  // (and its pages faulted in) on a thread of its own: zero-filled and set on one thread, between
  // the fill and the grouping, it took 3–4 ms at 10^6 triangles with the other core idle.
  detail::UninitializedArray<std::uint32_t> parent =
      detail::uninitialized_array<std::uint32_t>(face_count);
  auto singletons = [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) parent[f] = static_cast<std::uint32_t>(f);
  };
  detail::run_both(
      parallel, [&] { singletons(0, face_split); }, [&] { singletons(face_split, face_count); });

  // Each part groups the buckets of about half the half-edges.
  const auto vertex_split = static_cast<std::uint32_t>(
      std::lower_bound(start.begin(), start.begin() + static_cast<std::ptrdiff_t>(vertex_count),
                       total / 2) -
      start.begin());
  EdgePart low, high;
  detail::run_both(
      parallel,
      [&] { group_edges(layout, start.data(), bucket.get(), 0, vertex_split, parent.get(), low); },
      [&] {
        group_edges(layout, start.data(), bucket.get(), vertex_split,
                    static_cast<std::uint32_t>(vertex_count), parent.get(), high);
      });
  bucket.reset();
  detail::HugeVector<std::uint32_t>().swap(start);
  out.edges = low.edges + high.edges;
  out.odd = std::move(low.odd);
  out.odd.insert(out.odd.end(), high.odd.begin(), high.odd.end());
  out.sides = std::move(low.sides);
  out.sides.insert(out.sides.end(), high.sides.begin(), high.sides.end());
  out.same_vertices = std::move(low.same_vertices);
  out.same_vertices.append(high.same_vertices);

  // Components numbered by their lowest face.
  auto& components = out.components;
  detail::number_components(
      parent.get(), face_count, [&](std::size_t f) { return layout.collapsed(f); }, no_edge,
      [&](std::uint32_t first_face) {
        components.push_back({});
        components.back().first_face = first_face;
      },
      [&](std::uint32_t k) { ++components[k].faces; });
  out.component = std::move(parent);
  return out;
}

// The faces' pass of triangles: the mass sums of every triangle (add_triangle, as
// mass_properties of welded_triangles.hpp) and its tally (sums, degenerate faces), with each
// carrier formed once for both. One thread walks the chunks in order, so the mass sums are
// chunked_sums' (fixed chunking: the same bits as on any number of threads) and the tally sees the
// faces in order. Four faces at a time are summed in Double4 lanes (the same bits as one at a
// time), then tallied one by one.
BoundarySums face_pass(const WeldedTriangles& mesh, const TriangleLayout& layout, Vec3d reference,
                       detail::TopologyTally& tally) {
  const Vec3d* p = mesh.positions.data();
  const std::uint32_t* corner = mesh.corners.data();
  const Vec3<Double4> reference4{reference.x, reference.y, reference.z};
  auto corners = [&](std::size_t f) {
    const std::uint32_t* c = corner + 3 * f;
    return std::array<Vec3d, 3>{p[c[0]], p[c[1]], p[c[2]]};
  };
  return chunked_sums(
      mesh.triangle_count(), 1, [&](LanedSums<>& s, std::size_t begin, std::size_t end) {
        BasicBoundarySums<Double4> four;
        std::size_t f = begin;
        for (; f + sum_lanes <= end; f += sum_lanes) {
          const std::array<Vec3d, 3> v[4] = {corners(f), corners(f + 1), corners(f + 2),
                                             corners(f + 3)};
          Vec3<Double4> v4[3];
          for (int k = 0; k < 3; ++k) v4[k] = lanes(v[0][k], v[1][k], v[2][k], v[3][k]);
          Double4 norm4;
          const pga3::Plane<Double4> carrier4 =
              add_triangle(four, v4[0] - reference4, v4[1] - reference4, v4[2] - reference4, norm4);
          for (int j = 0; j < 4; ++j) {
            const pga3::Plane<double> carrier{carrier4.e0.lane(j), carrier4.e1.lane(j),
                                              carrier4.e2.lane(j), carrier4.e3.lane(j)};
            const std::size_t g = f + static_cast<std::size_t>(j);
            detail::tally_triangle(tally, static_cast<std::uint32_t>(g), layout.collapsed(g), v[j],
                                   carrier, norm4.lane(j));
          }
        }
        set_lanes(s, four);
        for (; f < end; ++f) {
          const std::array<Vec3d, 3> v = corners(f);
          double carrier_norm = 0;
          const pga3::Plane<double> carrier = add_triangle(s[f], v[0] - reference, v[1] - reference,
                                                           v[2] - reference, carrier_norm);
          detail::tally_triangle(tally, static_cast<std::uint32_t>(f), layout.collapsed(f), v,
                                 carrier, carrier_norm);
        }
      });
}

// Faces per thread below which the face pass is not worth a thread of its own.
constexpr std::size_t faces_per_thread = std::size_t{1} << 14;

// The report on the faces of `layout`, whose welded mesh is tally.mesh (the weld's counts, the
// threshold and the reference point already in tally.r). The face pass needs no edges:
// `tally_faces` (every face tallied in order) runs on a thread of its own while the edge pass
// runs on two more (the cores share the three). Each pass writes only its own data, so the result
// is the same as in one thread. Then the edges, components, duplicated faces and boundary loops.
template <class Layout, class TallyFaces>
void analyze_faces(const Layout& layout, detail::TopologyTally& tally,
                   const TallyFaces& tally_faces) {
  TopologyReport& r = tally.r;
  const detail::WeldedFaces& mesh = tally.mesh;
  const std::size_t face_count = layout.face_count();
  const bool parallel = face_count >= faces_per_thread;
  std::size_t unreferenced = 0;
  EdgePass edges;
  detail::run_both(
      parallel, [&] { edges = edge_pass(layout, mesh.positions.size(), parallel); },
      [&] {
        tally_faces();
        // Here rather than in the longer edge pass.
        unreferenced = unreferenced_vertices(mesh.corners, mesh.positions.size());
      });

  r.edges = edges.edges;
  r.collapsed_faces = edges.collapsed_faces;
  r.unreferenced_vertices = unreferenced;
  tally.components = std::move(edges.components);
  detail::tally_component_sums(tally, {edges.component.get(), face_count});
  for (const OddEdge& e : edges.odd)
    detail::tally_edge(tally, e.v0, e.v1, e.face, e.uses, e.forward, edges.component[e.face]);

  std::vector<std::uint32_t>& sides = edges.sides;
  std::sort(sides.begin(), sides.end());
  std::vector<std::uint32_t> tails(sides.size()), heads(sides.size());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    tails[i] = layout.tail(sides[i]);
    heads[i] = layout.head(sides[i]);
  }
  detail::finish_report(
      tally, detail::duplicated_faces(edges.same_vertices),
      trace_boundary_loops(sides, tails, heads, mesh.positions, r.reference_point));
}

}  // namespace

TopologyReport analyze_welded_triangles(const WeldedTriangles& mesh, Vec3d reference,
                                        const TopologyOptions& options) {
  return analyze_welded_triangles(mesh, reference, MassOptions{}, options, false).topology;
}

WeldedTriangleProps analyze_welded_triangles(const WeldedTriangles& mesh, Vec3d reference,
                                             const MassOptions& mass_options,
                                             const TopologyOptions& options,
                                             bool single_precision) {
  detail::check_topology_options(options);
  WeldedTriangleProps props;
  TopologyReport& r = props.topology;
  r.faces = mesh.triangle_count();
  r.input_vertices = mesh.input_vertices;
  r.vertices = mesh.positions.size();
  r.merged_vertices = mesh.merged;
  r.weld_tolerance = mesh.tolerance;
  r.weld_max_moved = mesh.max_moved;
  r.area_threshold = options.area_threshold;
  r.reference_point = reference;
  const detail::WeldedFaces faces{mesh.positions, mesh.representative, mesh.corners, {}};
  detail::TopologyTally tally(r, faces, options);
  const TriangleLayout layout{mesh.corners.data(), mesh.triangle_count()};
  BoundarySums sums;
  analyze_faces(layout, tally, [&] { sums = face_pass(mesh, layout, reference, tally); });
  props.mass =
      mass_properties_from_welded_sums(mesh, sums, reference, mass_options, single_precision);
  return props;
}

TopologyReport analyze_welded_mesh(const WeldResult& welded, Vec3d reference,
                                   const TopologyOptions& options) {
  detail::check_topology_options(options);
  const Mesh& mesh = welded.mesh;
  const WeldMap& weld = welded.map;
  TopologyReport r;
  r.faces = mesh.face_count();
  r.input_vertices = weld.to_welded.size();
  r.vertices = weld.welded_count();
  r.merged_vertices = weld.merged;
  r.weld_tolerance = weld.tolerance;
  r.weld_max_moved = weld.max_moved;
  r.area_threshold = options.area_threshold;
  r.reference_point = reference;
  const detail::WeldedFaces faces{mesh.vertices, weld.representative, mesh.corners,
                                  mesh.face_offsets};
  detail::TopologyTally tally(r, faces, options);
  const std::vector<std::uint32_t> corner_face = detail::corner_faces(mesh.face_offsets);
  const PolygonLayout layout{mesh.corners.data(), mesh.face_offsets.data(), corner_face.data(),
                             mesh.face_count()};
  analyze_faces(layout, tally, [&] {
    for (std::size_t f = 0; f < layout.face_count(); ++f)
      detail::tally_face(tally, static_cast<std::uint32_t>(f), layout.collapsed(f));
  });
  return r;
}

}  // namespace pgamesh
