// Polygons as 2-complexes given by their boundary edges, on the R(d,0,1) complex code with d = 2.
#include "pgamesh/geometry/polygon2d.hpp"

#include <limits>

#include "pgamesh/geometry/complex.hpp"

namespace pgamesh::geometry {

PolygonMeasures polygon_measures(std::span<const std::vector<Vec2>> rings) {
  std::vector<pgad::Vec<2>> vertices;
  std::vector<int> edges;
  for (const auto& ring : rings) {
    if (ring.size() < 2) continue;
    const int first = static_cast<int>(vertices.size());
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i) {
      vertices.push_back(ring[static_cast<std::size_t>(i)]);
      edges.push_back(first + i);
      edges.push_back(first + (i + 1) % n);
    }
  }
  PolygonMeasures m;
  if (vertices.empty()) {
    m.centroid = {std::numeric_limits<double>::quiet_NaN(),
                  std::numeric_limits<double>::quiet_NaN()};
    return m;
  }
  // Reference point: the bounding-box centre (docs/conventions.md §13).
  Vec2 lo = vertices[0], hi = vertices[0];
  for (const auto& v : vertices)
    for (std::size_t i = 0; i < 2; ++i) {
      lo[i] = std::min(lo[i], v[i]);
      hi[i] = std::max(hi[i], v[i]);
    }
  const Vec2 ref = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2};
  const BoundaryChain<2> chain{vertices, edges, 2};
  const BoundarySums<2> sums = boundary_sums<2>(chain, ref);
  m.signed_area = signed_volume(sums);
  m.centroid = m.signed_area != 0 ? center_of_mass(sums)
                                  : Vec2{std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN()};
  for (std::size_t e = 0; e < edges.size(); e += 2) {
    const pgad::Vec<2> edge[2] = {vertices[static_cast<std::size_t>(edges[e])],
                                  vertices[static_cast<std::size_t>(edges[e + 1])]};
    m.perimeter += magnitude<2>(edge);
  }
  return m;
}

}  // namespace pgamesh::geometry
