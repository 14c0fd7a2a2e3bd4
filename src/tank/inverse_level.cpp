#include "pgamesh/tank/inverse_level.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pgamesh/core/number_text.hpp"

namespace pgamesh::tank {

LevelSolution level_for_volume(const FuelIndex& index, Vec3d up_in, double volume) {
  const Vec3d up = unit_up(up_in);
  return level_for_volume([&](const FuelPlane& p) { return index.query(p); }, up, index.range(up),
                          index.tank().volume, volume);
}

LevelSolution level_for_volume(const std::function<FuelState(const FuelPlane&)>& query, Vec3d up,
                               LevelRange range, double total, double volume) {
  if (!std::isfinite(volume)) throw std::domain_error("the volume must be finite");
  if (volume < 0) throw std::domain_error("the volume " + format_number(volume) + " is negative");
  if (volume > total * (1 + 1e-12))
    throw std::domain_error("the volume " + format_number(volume) + " exceeds the tank's volume " +
                            format_number(total));
  LevelSolution s;
  if (volume == 0) return {range.lowest, 0, 0};
  if (volume >= total) return {range.highest, total, 0};
  double lo = range.lowest, hi = range.highest;
  const double height_tol = 1e-13 * (range.highest - range.lowest);
  const double volume_tol = 1e-14 * total;
  double level = lo + (hi - lo) * (volume / total);
  for (;;) {
    const FuelState st = query(FuelPlane{up, level});
    ++s.iterations;
    s.level = level;
    s.volume = st.volume;
    const double f = st.volume - volume;
    if (std::abs(f) <= volume_tol || s.iterations >= 200) break;
    (f < 0 ? lo : hi) = level;
    if (hi - lo <= height_tol) break;
    const double step = st.surface_area > 0 ? -f / st.surface_area : 0;
    double next = level + step;
    if (!(st.surface_area > 0) || !(next > lo && next < hi)) next = (lo + hi) / 2;
    if (std::abs(next - level) <= height_tol) {
      s.level = next;
      s.volume = query(FuelPlane{up, next}).volume;
      ++s.iterations;
      break;
    }
    level = next;
  }
  return s;
}

LevelSolution level_for_fraction(const FuelIndex& index, Vec3d up, double fraction) {
  if (!std::isfinite(fraction) || fraction < 0 || fraction > 1 + 1e-12)
    throw std::domain_error("the fraction " + format_number(fraction) + " is outside [0, 1]");
  return level_for_volume(index, up, std::min(fraction, 1.0) * index.tank().volume);
}

std::vector<LevelSolution> levels_for_volumes(const FuelIndex& index, Vec3d up,
                                              std::span<const double> volumes) {
  std::vector<LevelSolution> out;
  out.reserve(volumes.size());
  for (double v : volumes) out.push_back(level_for_volume(index, up, v));
  return out;
}

}  // namespace pgamesh::tank
