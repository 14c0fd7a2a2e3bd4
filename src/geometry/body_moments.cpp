#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// The scalings of the header's table: paper Table 1 (V = Σ D / 6, area = Σ ‖F‖ / 2), eq. 5.3 as
// corrected in docs/conventions.md §9 (∫r = Σ D (a + b + c) / 24 with o = 0 here), pyramid
// reference eq. 24 (∫rrᵀ = Σ D (…) / 120) and Cor. 4.1 (gap = ½ ‖Σ F‖).
BodyMoments body_moments(const BoundarySums& s) {
  BodyMoments m;
  m.area = s.area2 / 2;
  m.volume = s.volume6 / 6;
  m.first = s.moment24 / 24.0;
  const auto& q = s.second120;
  m.second = {{{q[0], q[3], q[5]}, {q[3], q[1], q[4]}, {q[5], q[4], q[2]}}};
  for (auto& row : m.second)
    for (double& v : row) v /= 120;
  m.gap_area = pga3::norm(s.carrier_sum) / 2;
  return m;
}

Mat3 central_second_moment(const BodyMoments& m) {
  const Vec3d c = centroid(m);
  Mat3 out = m.second;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] -= m.volume * c[i] * c[j];
  return out;
}

// I = ρ ∫ parallel(r) dV = ρ (tr(M) 1 − M) (pyramid reference eq. 24; I_xy = −∫xy dm,
// docs/conventions.md §10).
Mat3 inertia_from_second_moment(const Mat3& second, double density) {
  const double trace = second[0][0] + second[1][1] + second[2][2];
  Mat3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = density * ((i == j ? trace : 0.0) - second[i][j]);
  return out;
}

Mat3 parallel_axis(Vec3d r) {
  const double r2 = dot(r, r);
  Mat3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = (i == j ? r2 : 0.0) - r[i] * r[j];
  return out;
}

}  // namespace pgamesh
