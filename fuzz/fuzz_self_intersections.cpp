// libFuzzer harness: the self-intersection pass (self_intersections.hpp) on small meshes decoded
// from the bytes — corners on a coarse grid, so that shared, coplanar, collinear and touching
// cases are common, or any double the bytes spell within the predicates' range. The pass must
// find exactly the pairs that testing every pair of fan triangles finds (the hierarchy loses
// none), and the exact test must not depend on the order of the two triangles or on where each
// triangle's corner list starts. The exact rational reference (tests/support, GMP) is checked
// against the pass by tests/mesh/test_self_intersections.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <utility>

#include "fuzz_common.hpp"
#include "mesh/topology/exact_predicates.hpp"
#include "mesh/topology/triangle_intersection.hpp"
#include "pgamesh/mesh/topology/self_intersections.hpp"
#include "pgamesh/mesh/weld/weld.hpp"

namespace {

using pgamesh::Vec3d;
using pgamesh::detail::IndexedTriangle;

// Reads the bytes in order; zero past the end.
struct ByteReader {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  std::uint8_t next() { return at < size ? data[at++] : 0; }
  bool done() const { return at >= size; }
};

double coordinate(ByteReader& in) {
  const std::uint8_t b = in.next();
  if (b < 250) return (b % 9) / 8.0;
  double x = 0;
  std::uint8_t raw[sizeof x];
  for (auto& r : raw) r = in.next();
  std::memcpy(&x, raw, sizeof x);
  // The predicates are exact for magnitudes in about [1e-100, 1e100] (exact_predicates.hpp).
  if (!std::isfinite(x) || std::abs(x) > 1e30 || (x != 0 && std::abs(x) < 1e-30)) return 0;
  return x;
}

IndexedTriangle rotated(const IndexedTriangle& t) {
  IndexedTriangle r;
  for (int k = 0; k < 3; ++k) {
    r.p[k] = t.p[(k + 1) % 3];
    r.v[k] = t.v[(k + 1) % 3];
  }
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pgamesh;
  ByteReader in{data, size};
  const std::size_t vertex_count = 3 + in.next() % 14;
  std::vector<Vec3d> positions;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const double x = coordinate(in), y = coordinate(in), z = coordinate(in);
    positions.push_back({x, y, z});
  }
  Mesh mesh;
  mesh.vertices = positions;
  while (!in.done() && mesh.face_count() < 48) {
    const std::size_t corners = 3 + in.next() % 3;  // triangles, quads and pentagons
    for (std::size_t k = 0; k < corners; ++k) mesh.corners.push_back(in.next() % vertex_count);
    mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
  }
  const SelfIntersections found = find_self_intersections(mesh, SIZE_MAX);
  fuzz::require(found.list.size() == found.pairs);

  // Every pair of fan triangles of different faces, on the same welded mesh the pass welds.
  const WeldResult welded = weld(mesh);
  const Mesh& m = welded.mesh;
  std::vector<std::pair<IndexedTriangle, std::uint32_t>> fan;
  for (std::uint32_t f = 0; f < m.face_count(); ++f)
    for (std::size_t k = 1; k + 1 < m.face_size(f); ++k) {
      IndexedTriangle t;
      const std::uint32_t v[3] = {m.face(f)[0], m.face(f)[k], m.face(f)[k + 1]};
      for (int i = 0; i < 3; ++i) {
        t.v[i] = v[i];
        t.p[i] = m.vertices[v[i]];
      }
      if (!detail::collinear(t.p[0], t.p[1], t.p[2])) fan.emplace_back(t, f);
    }
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::size_t i = 0; i < fan.size(); ++i)
    for (std::size_t j = i + 1; j < fan.size(); ++j) {
      if (fan[i].second == fan[j].second) continue;
      const IndexedTriangle &t = fan[i].first, &u = fan[j].first;
      const bool meet = detail::triangles_intersect(t, u);
      fuzz::require(meet == detail::triangles_intersect(u, t));
      fuzz::require(meet == detail::triangles_intersect(rotated(t), u));
      fuzz::require(meet == detail::triangles_intersect(t, rotated(rotated(u))));
      if (meet) expected.insert(std::minmax(fan[i].second, fan[j].second));
    }
  fuzz::require(expected.size() == found.pairs);
  std::size_t i = 0;
  for (const auto& [f, g] : expected) {
    fuzz::require(found.list[i].face0 == f && found.list[i].face1 == g);
    ++i;
  }
  return 0;
}
