#include "pgamesh/tank/tank.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "pgamesh/core/number_text.hpp"

namespace pgamesh::tank {

namespace {

// Marks the fan triangles [first, end) of one polygon face that fold back against the face's
// summed normal (fan_area_sign), with coordinates relative to the tank's reference point as the
// mass properties take them.
void mark_folded_fan(Tank& t, std::size_t first) {
  auto normal = [&](const std::array<std::uint32_t, 3>& tri) {
    return triangle_carrier(t.vertices[tri[0]] - t.reference, t.vertices[tri[1]] - t.reference,
                            t.vertices[tri[2]] - t.reference)
        .normal();
  };
  Vec3d face{};
  for (std::size_t i = first; i < t.triangles.size(); ++i) face += normal(t.triangles[i]);
  for (std::size_t i = first; i < t.triangles.size(); ++i) {
    if (fan_area_sign(normal(t.triangles[i]), face) > 0) continue;
    t.folded.resize(t.triangles.size(), 0);  // the faces before this one fold nowhere
    t.folded[i] = 1;
  }
}

}  // namespace

Tank make_tank(const Mesh& mesh) {
  Tank t;
  if (mesh.vertices.empty() || mesh.face_count() == 0)
    throw std::invalid_argument("the mesh has no faces");
  t.vertices = mesh.vertices;
  const double inf = std::numeric_limits<double>::infinity();
  t.lower = {inf, inf, inf};
  t.upper = {-inf, -inf, -inf};
  for (const Vec3d& v : t.vertices) {
    if (!is_finite(v)) throw std::invalid_argument("the mesh has a non-finite vertex coordinate");
    for (int i = 0; i < 3; ++i) {
      t.lower[i] = std::min(t.lower[i], v[i]);
      t.upper[i] = std::max(t.upper[i], v[i]);
    }
  }
  t.reference = (t.lower + t.upper) / 2.0;
  const auto n = t.vertices.size();
  t.triangles.reserve(mesh.corners.size());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    const std::size_t k = mesh.face_size(f);
    for (std::size_t i = 0; i < k; ++i)
      if (c[i] >= n)
        throw std::invalid_argument("face " + std::to_string(f) +
                                    " has a vertex index out of range");
    const std::size_t first = t.triangles.size();
    for (std::size_t i = 1; i + 1 < k; ++i) t.triangles.push_back({c[0], c[i], c[i + 1]});
    if (k > 3) mark_folded_fan(t, first);
  }
  if (!t.folded.empty()) t.folded.resize(t.triangles.size(), 0);
  // The whole tank's sums over the very triangles the slices cut, so that fuel + ullage = tank
  // holds for the wall area too.
  for (std::size_t i = 0; i < t.triangles.size(); ++i) {
    const auto& tri = t.triangles[i];
    add_fan_triangle(t.total, t.vertices[tri[0]] - t.reference, t.vertices[tri[1]] - t.reference,
                     t.vertices[tri[2]] - t.reference, area_sign(t, i));
  }
  const BodyMoments m = body_moments(t.total);
  // Coordinates so large that the sums overflow (a tank of size around 1e77 and up: the norm of a
  // face's vector area squares its L² components) would give an infinite or undefined area or
  // volume, which no gauge may print as a result.
  if (!std::isfinite(m.volume) || !std::isfinite(m.area))
    throw std::invalid_argument(
        "the coordinates are too large for double precision: the tank's area or volume "
        "overflows (scale the mesh down, e.g. express it in a larger unit)");
  t.volume = m.volume;
  t.area = m.area;
  t.gap_area = m.gap_area;
  return t;
}

LevelRange level_range(const Tank& tank, Vec3d unit_up) {
  LevelRange r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Vec3d& v : tank.vertices) {
    const double h = dot(unit_up, v);
    r.lowest = std::min(r.lowest, h);
    r.highest = std::max(r.highest, h);
  }
  return r;
}

TankFitness tank_fitness(const Mesh& mesh, const Tank& tank) {
  TankFitness f;
  f.topology = analyze_topology(mesh);
  const TopologyReport& r = f.topology;
  f.fit = r.closed && r.orientation_consistent && r.volume_valid && tank.volume > 0;
  if (f.fit) return f;
  f.problems = r.notes;
  if (!(tank.volume > 0))
    f.problems.push_back("the signed volume " + format_number(tank.volume) +
                         " is not positive (inside out or flat)");
  return f;
}

}  // namespace pgamesh::tank
