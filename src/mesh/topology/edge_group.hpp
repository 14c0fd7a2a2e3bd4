// Internal: one vertex's half-edges grouped by their upper end, the step shared by the edge table
// (edges.cpp), the topology pass (welded_topology.cpp) and the PLY pass that re-reads its faces
// from the file (ply_topology.cpp): after the sort, each run of equal upper ends is one edge, and
// its uses stay in ascending half-edge order; judge_vertex_edges then judges each edge on the spot.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/topology/duplicate_faces.hpp"
#include "mesh/topology/union_find.hpp"

namespace pgamesh::detail {

// (upper end, half-edge or corner id) pairs of one vertex.
using EdgeGroup = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// Stable sort by upper end (each element's `first`): insertion sort for the usual handful (a
// vertex of a mesh has about six), std::stable_sort for the rare large fan.
template <class Group>
inline void sort_by_upper_end(Group& group) {
  if (group.size() <= 16) {
    for (std::size_t i = 1; i < group.size(); ++i)
      for (std::size_t j = i; j > 0 && group[j - 1].first > group[j].first; --j)
        std::swap(group[j - 1], group[j]);
  } else {
    std::stable_sort(group.begin(), group.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
  }
}

// An edge that is not used exactly twice in opposite directions, kept until the components are
// known.
struct OddEdge {
  std::uint32_t v0, v1, face, uses, forward;
};

// What the grouping finds among the edges of a range of lower ends.
struct EdgePart {
  std::size_t edges = 0;
  std::vector<OddEdge> odd;          // in edge order
  std::vector<std::uint32_t> sides;  // boundary half-edges
  SameVertexRuns same_vertices;      // for duplicated_faces (duplicate_faces.hpp)
};

// Judges the edges whose lower end is v. `group` holds v's half-edges as elements whose `first` is
// the upper end, sorted by sort_by_upper_end with the half-edges ascending within each upper end.
// `sides` answers for an element e: half_edge(e), face(e), runs_from(e, v) (whether e runs from
// v), and what add_same_vertex_runs asks. Counts each edge, unites the faces on it in `parent`
// (shared with other threads: union_find.hpp), and keeps the boundary sides, the edges not used
// exactly twice in opposite directions and the runs of faces with the same vertices.
template <class Group, class Sides>
void judge_vertex_edges(std::uint32_t v, const Group& group, Sides& sides, std::uint32_t* parent,
                        EdgePart& out) {
  for (std::size_t i = 0; i < group.size();) {
    const std::uint32_t upper = group[i].first;
    std::size_t end = i + 1;
    while (end < group.size() && group[end].first == upper) ++end;
    ++out.edges;
    const std::uint32_t first_face = sides.face(group[i]);
    std::uint32_t forward = 0, root = first_face;
    for (std::size_t j = i; j < end; ++j) {
      forward += sides.runs_from(group[j], v) ? 1 : 0;
      if (j > i) root = unite_roots_shared(parent, root, sides.face(group[j]));
    }
    const auto uses = static_cast<std::uint32_t>(end - i);
    if (uses > 1) add_same_vertex_runs(group, i, end, sides, out.same_vertices);
    if (uses == 1) out.sides.push_back(sides.half_edge(group[i]));
    if (uses != 2 || forward != 1) out.odd.push_back({v, upper, first_face, uses, forward});
    i = end;
  }
}

// The components of faces [0, face_count) once every edge has united its faces in `parent`
// (every pointer pointing down, a root the lowest face of its set): `parent` is overwritten with
// each face's component, numbered by lowest face, or no_component for a collapsed face (no edges,
// nothing points at it); `add_component(first_face)` is called for each new component in order
// and `count_face(component)` for each face in it. One ascending pass: parent[f] < f has already
// been given its component's number.
template <class Collapsed, class AddComponent, class CountFace>
void number_components(std::uint32_t* parent, std::size_t face_count, const Collapsed& collapsed,
                       std::uint32_t no_component, const AddComponent& add_component,
                       const CountFace& count_face) {
  std::uint32_t components = 0;
  for (std::size_t f = 0; f < face_count; ++f) {
    if (collapsed(f)) {
      parent[f] = no_component;
      continue;
    }
    const std::uint32_t p = parent[f];
    if (p == f) {
      parent[f] = components++;
      add_component(static_cast<std::uint32_t>(f));
    } else {
      parent[f] = parent[p];
    }
    count_face(parent[f]);
  }
}

}  // namespace pgamesh::detail
