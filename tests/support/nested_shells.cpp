#include "nested_shells.hpp"

#include <cmath>
#include <numbers>

#include "solids.hpp"

namespace pgamesh::test {

Mesh centred_cube(double side, Vec3d centre, bool outward) {
  const Vec3d corner = centre - Vec3d{side / 2, side / 2, side / 2};
  Mesh m = transformed(box_mesh(side, side, side), [&](Vec3d p) { return p + corner; });
  return outward ? m : flipped(m);
}

Mesh torus_mesh(double major, double minor, int around, int across, Vec3d centre, bool outward) {
  Mesh m;
  const double pi = std::numbers::pi;
  for (int i = 0; i < around; ++i) {
    const double u = 2 * pi * i / around;
    for (int j = 0; j < across; ++j) {
      const double v = 2 * pi * j / across;
      const double rho = major + minor * std::cos(v);
      m.vertices.push_back(centre +
                           Vec3d{rho * std::cos(u), rho * std::sin(u), minor * std::sin(v)});
    }
  }
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>((i % around) * across + (j % across));
  };
  // Counter-clockwise seen from outside: u runs about z, v about the tube.
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j)
      m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return outward ? m : flipped(m);
}

Mesh joined(std::initializer_list<Mesh> shells) {
  Mesh out;
  for (const Mesh& s : shells) {
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), s.vertices.begin(), s.vertices.end());
    for (std::size_t f = 0; f < s.face_count(); ++f) {
      for (std::size_t i = 0; i < s.face_size(f); ++i) out.corners.push_back(s.face(f)[i] + base);
      out.face_offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
    }
  }
  return out;
}

}  // namespace pgamesh::test
