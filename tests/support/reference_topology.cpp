#include "reference_topology.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

namespace pgamesh::test {

namespace {

// A face's side along an edge {v0 < v1}.
struct Side {
  std::pair<std::uint32_t, std::uint32_t> edge;
  std::uint32_t corner, face;
  bool forward;  // runs v0 → v1
};

bool boundary(const ReferenceEdge& e) {
  return e.uses == 1;
}
bool nonmanifold(const ReferenceEdge& e) {
  return e.uses > 2;
}
// More uses in one direction than the other can pair (an odd one out is allowed for an odd count).
bool inconsistent(const ReferenceEdge& e) {
  const std::size_t backward = e.uses - e.forward;
  const std::size_t imbalance = e.forward > backward ? e.forward - backward : backward - e.forward;
  return e.uses > 1 && imbalance > e.uses % 2;
}

}  // namespace

ReferenceTopology reference_topology(const Mesh& mesh, double weld_tolerance) {
  ReferenceTopology out;
  out.weld = weld_map(mesh.vertices, weld_tolerance);
  const std::size_t faces = mesh.face_count();
  auto welded = [&](std::uint32_t c) { return out.weld.to_welded[mesh.corners[c]]; };
  auto next = [&](std::size_t f, std::uint32_t c) {
    return c + 1 == mesh.face_offsets[f + 1] ? mesh.face_offsets[f] : c + 1;
  };

  // Every side of a face that is not collapsed and whose ends differ, sorted by edge.
  std::vector<bool> referenced(out.weld.welded_count());
  std::vector<std::vector<std::uint32_t>> vertex_set(faces);  // sorted, each once
  std::vector<bool> collapsed(faces);
  std::vector<Side> sides;
  std::vector<std::uint32_t> first_side(faces, no_edge);  // its corner
  for (std::size_t f = 0; f < faces; ++f) {
    const std::uint32_t begin = mesh.face_offsets[f], end = mesh.face_offsets[f + 1];
    if (end - begin >= 3) out.triangles += end - begin - 2;
    std::vector<std::uint32_t>& set = vertex_set[f];
    for (std::uint32_t c = begin; c < end; ++c) set.push_back(welded(c));
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    for (std::uint32_t v : set) referenced[v] = true;
    collapsed[f] = set.size() < 3;
    if (collapsed[f]) {
      ++out.collapsed_faces;
      continue;
    }
    for (std::uint32_t c = begin; c < end; ++c) {
      const std::uint32_t a = welded(c), b = welded(next(f, c));
      if (a == b) continue;  // a collapsed side lies on no edge
      sides.push_back({{std::min(a, b), std::max(a, b)}, c, static_cast<std::uint32_t>(f), a < b});
      if (first_side[f] == no_edge) first_side[f] = c;
    }
  }
  out.unreferenced_vertices =
      static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return std::tie(x.edge, x.corner) < std::tie(y.edge, y.corner);
  });

  // The edges: runs of sides along one pair of vertices.
  std::vector<std::uint32_t> edge_of_corner(mesh.corners.size(), no_edge);
  std::vector<std::vector<std::uint32_t>> edges_of(faces), faces_on(1);
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (i > 0 && sides[i].edge != sides[i - 1].edge) faces_on.emplace_back();
    if (i == 0 || sides[i].edge != sides[i - 1].edge) {
      ReferenceEdge e;
      e.v0 = sides[i].edge.first;
      e.v1 = sides[i].edge.second;
      e.lowest_face = sides[i].face;
      out.edges.push_back(e);
    }
    ReferenceEdge& e = out.edges.back();
    const auto id = static_cast<std::uint32_t>(out.edges.size() - 1);
    ++e.uses;
    e.forward += sides[i].forward ? 1 : 0;
    e.lowest_face = std::min(e.lowest_face, sides[i].face);
    edge_of_corner[sides[i].corner] = id;
    edges_of[sides[i].face].push_back(id);
    faces_on[id].push_back(sides[i].face);
  }
  for (std::size_t i = 0; i < sides.size(); ++i)
    if (out.edges[edge_of_corner[sides[i].corner]].uses == 1)
      out.boundary_sides.push_back(sides[i].corner);
  std::sort(out.boundary_sides.begin(), out.boundary_sides.end());

  // Components: faces joined by any edge, numbered by their lowest face.
  std::vector<std::uint32_t> component(faces, no_edge);
  for (std::size_t f = 0; f < faces; ++f) {
    if (collapsed[f] || component[f] != no_edge) continue;
    const auto k = static_cast<std::uint32_t>(out.components.size());
    out.components.push_back({});
    out.components.back().first_face = static_cast<std::uint32_t>(f);
    std::vector<std::uint32_t> stack{static_cast<std::uint32_t>(f)};
    component[f] = k;
    while (!stack.empty()) {
      const std::uint32_t g = stack.back();
      stack.pop_back();
      ++out.components[k].faces;
      for (std::uint32_t e : edges_of[g])
        for (std::uint32_t h : faces_on[e])
          if (component[h] == no_edge) {
            component[h] = k;
            stack.push_back(h);
          }
    }
  }
  for (const ReferenceEdge& e : out.edges) {
    ComponentSummary& s = out.components[component[e.lowest_face]];
    s.boundary_edges += boundary(e) ? 1 : 0;
    s.nonmanifold_edges += nonmanifold(e) ? 1 : 0;
    s.inconsistent_edges += !boundary(e) && inconsistent(e) ? 1 : 0;
  }
  for (ComponentSummary& s : out.components)
    s.closed = s.boundary_edges == 0 && s.nonmanifold_edges == 0 && s.inconsistent_edges == 0;

  // Duplicates: g repeats the lowest earlier face f with its vertex set that repeats no face itself
  // and whose first side lies on an edge of g.
  std::vector<std::uint32_t> by_set;  // the faces by vertex set, then index
  for (std::size_t f = 0; f < faces; ++f)
    if (!collapsed[f]) by_set.push_back(static_cast<std::uint32_t>(f));
  std::stable_sort(by_set.begin(), by_set.end(),
                   [&](std::uint32_t x, std::uint32_t y) { return vertex_set[x] < vertex_set[y]; });
  std::vector<std::size_t> set_begin(faces);  // where the faces with f's vertex set start
  for (std::size_t i = 0; i < by_set.size(); ++i)
    set_begin[by_set[i]] =
        i > 0 && vertex_set[by_set[i]] == vertex_set[by_set[i - 1]] ? set_begin[by_set[i - 1]] : i;
  std::vector<std::uint32_t> same_as(faces, no_edge);
  for (std::size_t g = 0; g < faces; ++g) {
    if (collapsed[g]) continue;
    for (std::size_t i = set_begin[g]; by_set[i] < g; ++i) {
      const std::uint32_t f = by_set[i];
      const std::uint32_t edge = edge_of_corner[first_side[f]];
      if (same_as[f] == no_edge &&
          std::find(edges_of[g].begin(), edges_of[g].end(), edge) != edges_of[g].end()) {
        same_as[g] = f;
        out.duplicated.emplace_back(static_cast<std::uint32_t>(g), f);
        break;
      }
    }
  }
  return out;
}

void expect_matches_reference(const TopologyReport& r, const Mesh& mesh,
                              const TopologyOptions& options) {
  const ReferenceTopology ref = reference_topology(mesh, options.weld_tolerance);
  const std::size_t cap = options.list_cap;
  EXPECT_EQ(r.faces, mesh.face_count());
  EXPECT_EQ(r.triangles, ref.triangles);
  EXPECT_EQ(r.input_vertices, mesh.vertices.size());
  EXPECT_EQ(r.vertices, ref.weld.welded_count());
  EXPECT_EQ(r.merged_vertices, ref.weld.merged);
  EXPECT_EQ(r.unreferenced_vertices, ref.unreferenced_vertices);
  EXPECT_EQ(r.collapsed_faces, ref.collapsed_faces);
  EXPECT_EQ(r.edges, ref.edges.size());

  // The defective edges, in (v0, v1) order, as the lists name them.
  auto expect_edges = [&](const char* what, std::size_t count,
                          const std::vector<EdgeLocation>& list, auto is) {
    SCOPED_TRACE(what);
    std::vector<ReferenceEdge> expected;
    for (const ReferenceEdge& e : ref.edges)
      if (is(e)) expected.push_back(e);
    EXPECT_EQ(count, expected.size());
    ASSERT_EQ(list.size(), std::min(cap, expected.size()));
    for (std::size_t i = 0; i < list.size(); ++i) {
      EXPECT_EQ(list[i].vertex0, ref.weld.representative[expected[i].v0]);
      EXPECT_EQ(list[i].vertex1, ref.weld.representative[expected[i].v1]);
      EXPECT_EQ(list[i].face, expected[i].lowest_face);
      EXPECT_EQ(list[i].face_count, expected[i].uses);
    }
  };
  expect_edges("boundary", r.boundary_edges, r.boundary_edge_list, boundary);
  expect_edges("non-manifold", r.nonmanifold_edges, r.nonmanifold_edge_list, nonmanifold);
  expect_edges("inconsistent", r.inconsistent_edges, r.inconsistent_edge_list,
               [](const ReferenceEdge& e) { return !boundary(e) && inconsistent(e); });
  EXPECT_EQ(r.orientation_consistent, r.inconsistent_edges == 0);
  EXPECT_EQ(r.closed, mesh.face_count() > 0 && !ref.edges.empty() && r.boundary_edges == 0 &&
                          r.nonmanifold_edges == 0 && r.inconsistent_edges == 0);

  EXPECT_EQ(r.duplicated_faces, ref.duplicated.size());
  ASSERT_EQ(r.duplicated_list.size(), std::min(cap, ref.duplicated.size()));
  for (std::size_t i = 0; i < r.duplicated_list.size(); ++i) {
    EXPECT_EQ(r.duplicated_list[i].face, ref.duplicated[i].first);
    EXPECT_EQ(r.duplicated_list[i].same_as, ref.duplicated[i].second);
  }

  EXPECT_EQ(r.components, ref.components.size());
  std::size_t closed = 0;
  for (const ComponentSummary& s : ref.components) closed += s.closed ? 1 : 0;
  EXPECT_EQ(r.closed_components, closed);
  ASSERT_EQ(r.component_list.size(), std::min(cap, ref.components.size()));
  for (std::size_t k = 0; k < r.component_list.size(); ++k) {
    SCOPED_TRACE(k);
    const ComponentSummary &got = r.component_list[k], &want = ref.components[k];
    EXPECT_EQ(got.first_face, want.first_face);
    EXPECT_EQ(got.faces, want.faces);
    EXPECT_EQ(got.boundary_edges, want.boundary_edges);
    EXPECT_EQ(got.nonmanifold_edges, want.nonmanifold_edges);
    EXPECT_EQ(got.inconsistent_edges, want.inconsistent_edges);
    EXPECT_EQ(got.closed, want.closed);
  }

  // Every boundary side in exactly one loop.
  std::vector<std::uint32_t> looped;
  for (const BoundaryLoop& loop : r.boundary_loops)
    looped.insert(looped.end(), loop.half_edges.begin(), loop.half_edges.end());
  std::sort(looped.begin(), looped.end());
  EXPECT_EQ(looped, ref.boundary_sides);
}

}  // namespace pgamesh::test
