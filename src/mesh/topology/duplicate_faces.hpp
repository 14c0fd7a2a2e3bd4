// Internal: the duplicated faces of the topology report (docs/topology.md), found by the edge pass
// without an edge table. Face g duplicates face f < g when the two have the same set of welded
// vertices (in either orientation), f duplicates no face itself, and f's first side
// (face_layout.hpp: the first that lies on an edge) lies on an edge g uses too; g's `same_as` is
// the lowest such f. Two triangles with the same vertices share all their edges, so a triangle
// duplicates the lowest earlier triangle with its vertices; two polygons with the same vertex set
// in a different cyclic order that share no edge are not matched.
//
// Whether f duplicates a face is known only once the faces below it are judged, and the edge pass
// sees one edge at a time (on two threads). So along each edge it keeps runs — a face whose first
// side lies on the edge, then every later face on the edge with its vertex set — and
// duplicated_faces resolves them in face order at the end. A mesh without duplicates keeps none.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pgamesh::detail {

struct SameVertexRuns {
  struct Member {
    std::uint32_t face;
    bool first_side_here;  // the face's first side lies on the run's edge
  };
  std::vector<Member> members;    // the runs one after another, each ascending by face
  std::vector<std::size_t> ends;  // where each run ends in `members`

  std::size_t begin_of(std::size_t run) const { return run == 0 ? 0 : ends[run - 1]; }
  // Whether face f is in one of the runs from `run` on.
  bool holds(std::size_t run, std::uint32_t f) const {
    for (; run < ends.size(); ++run) {
      const auto first = members.begin() + static_cast<std::ptrdiff_t>(begin_of(run));
      const auto last = members.begin() + static_cast<std::ptrdiff_t>(ends[run]);
      const auto it = std::lower_bound(first, last, f,
                                       [](const Member& m, std::uint32_t x) { return m.face < x; });
      if (it != last && it->face == f) return true;
    }
    return false;
  }
  // Appends another part's runs (the edge pass's vertex ranges, joined in vertex order).
  void append(const SameVertexRuns& other) {
    const std::size_t base = members.size();
    members.insert(members.end(), other.members.begin(), other.members.end());
    for (std::size_t end : other.ends) ends.push_back(base + end);
  }
};

// Adds the runs of one edge, whose uses are group[begin, end): in ascending half-edge order, so the
// uses of a face are adjacent and the faces ascend. sides.face(u) is the face of use u,
// sides.first_side(u) whether u is its face's first side, sides.same_vertices(u, w) whether the
// faces of two uses have the same set of welded vertices.
template <class Group, class Sides>
void add_same_vertex_runs(const Group& group, std::size_t begin, std::size_t end, Sides& sides,
                          SameVertexRuns& out) {
  const std::size_t edge_runs = out.ends.size();
  for (std::size_t j = begin; j < end; ++j) {
    if (!sides.first_side(group[j])) continue;
    const std::uint32_t f = sides.face(group[j]);
    if (out.holds(edge_runs, f)) continue;  // in the run of a lower face with its vertices
    const std::size_t run_begin = out.members.size();
    out.members.push_back({f, true});
    for (std::size_t m = j + 1; m < end; ++m) {
      const std::uint32_t g = sides.face(group[m]);
      if (g == f || g == out.members.back().face) continue;  // a face's second use of the edge
      // A face's first use of the edge comes first: its first side, if any use is.
      if (sides.same_vertices(group[j], group[m]))
        out.members.push_back({g, sides.first_side(group[m])});
    }
    if (out.members.size() - run_begin < 2) {
      out.members.resize(run_begin);
    } else {
      out.ends.push_back(out.members.size());
    }
  }
}

// (face, the face it duplicates), ascending by face.
std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicated_faces(const SameVertexRuns& runs);

}  // namespace pgamesh::detail
