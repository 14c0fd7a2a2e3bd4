#include "pgamesh/tank/attitude.hpp"

#include <cmath>
#include <stdexcept>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/tank/fuel_plane.hpp"

namespace pgamesh::tank {

Vec3d up_from_attitude(Vec3d level_up, double pitch, double roll) {
  if (!std::isfinite(pitch) || !std::isfinite(roll))
    throw std::invalid_argument("pitch and roll must be finite");
  const Vec3d u = unit_up(level_up);
  // Nose up is a right-handed turn about the right axis −y; right side down about forward +x.
  // In the quaternion order, whose bits the fuel results keep (docs/pga3.md "Two summation
  // orders").
  namespace qo = pga3::quaternion_order;
  const pga3::Motor<double> r =
      qo::geometric_product(pga3::rotor(pitch, Vec3d{0, -1, 0}), pga3::rotor(roll, Vec3d{1, 0, 0}));
  const pga3::Point<double> d = qo::apply(pga3::reverse(r), pga3::direction(u.x, u.y, u.z));
  return unit_up(d.weighted());
}

Vec3d up_from_gravity(Vec3d g) {
  if (!is_finite(g)) throw std::invalid_argument("the acceleration must be finite");
  if (dot(g, g) == 0) throw std::invalid_argument("the apparent gravity must not be zero");
  return unit_up(-g);
}

}  // namespace pgamesh::tank
