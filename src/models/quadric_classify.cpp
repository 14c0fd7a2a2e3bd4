// Classification of a quadric by the eigenvalues of M3 and its reduced form
// (docs/models-quadrics.md §6).
#include <algorithm>
#include <cmath>
#include <vector>

#include "pgamesh/models/quadric.hpp"
#include "quadric_linalg.hpp"

namespace pgamesh::quadric {

std::string_view to_string(QuadricType type) {
  switch (type) {
    case QuadricType::ellipsoid:
      return "ellipsoid";
    case QuadricType::sphere:
      return "sphere";
    case QuadricType::hyperboloid_one_sheet:
      return "hyperboloid_one_sheet";
    case QuadricType::hyperboloid_two_sheets:
      return "hyperboloid_two_sheets";
    case QuadricType::cone:
      return "cone";
    case QuadricType::elliptic_paraboloid:
      return "elliptic_paraboloid";
    case QuadricType::hyperbolic_paraboloid:
      return "hyperbolic_paraboloid";
    case QuadricType::elliptic_cylinder:
      return "elliptic_cylinder";
    case QuadricType::hyperbolic_cylinder:
      return "hyperbolic_cylinder";
    case QuadricType::parabolic_cylinder:
      return "parabolic_cylinder";
    case QuadricType::intersecting_planes:
      return "intersecting_planes";
    case QuadricType::parallel_planes:
      return "parallel_planes";
    case QuadricType::single_plane:
      return "single_plane";
    case QuadricType::point:
      return "point";
    case QuadricType::line:
      return "line";
    case QuadricType::imaginary:
      return "imaginary";
    case QuadricType::degenerate:
      return "degenerate";
  }
  return "degenerate";
}

Classification classify(const Quadric& q, double tol) {
  check_finite(q);
  Classification out;
  const Mat3 m3 = matrix3(q);
  const Mat4 m4 = matrix4(q);
  std::vector<double> a3(9), a4(16);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a3[static_cast<std::size_t>(r * 3 + c)] = m3[r][c];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a4[static_cast<std::size_t>(r * 4 + c)] = m4[r][c];
  const detail::SymmetricEigen e3 = detail::symmetric_eigen(a3, 3);
  const detail::SymmetricEigen e4 = detail::symmetric_eigen(a4, 4);
  double max3 = 0, max4 = 0;
  for (int k = 0; k < 3; ++k) {
    out.eigenvalues[k] = e3.values[static_cast<std::size_t>(k)];
    for (int r = 0; r < 3; ++r) out.axes[k][r] = e3.vectors[static_cast<std::size_t>(k * 3 + r)];
    max3 = std::max(max3, std::abs(out.eigenvalues[k]));
  }
  for (int k = 0; k < 4; ++k) {
    out.eigenvalues4[k] = e4.values[static_cast<std::size_t>(k)];
    max4 = std::max(max4, std::abs(out.eigenvalues4[k]));
  }
  for (double l : out.eigenvalues4)
    if (std::abs(l) > tol * max4) ++out.rank4;

  // Reduced form in M3's eigenframe: Σ λ_k y_k² + l_k y_k + j.
  const Vec3d lin{q.k[6], q.k[7], q.k[8]};
  const double lin_norm = std::hypot(lin[0], lin[1], lin[2]);
  double j_red = q.k[9], j_terms = std::abs(q.k[9]), lin_res2 = 0;
  int npos = 0, nneg = 0;
  std::array<double, 3> nonzero{};
  for (int k = 0; k < 3; ++k) {
    const double lam = out.eigenvalues[k];
    const double lk = out.axes[k][0] * lin[0] + out.axes[k][1] * lin[1] + out.axes[k][2] * lin[2];
    if (max3 > 0 && std::abs(lam) > tol * max3) {
      nonzero[static_cast<std::size_t>(npos + nneg)] = lam;
      (lam > 0 ? npos : nneg)++;
      const double term = lk * lk / (4 * lam);
      j_red -= term;
      j_terms += std::abs(term);
    } else {
      lin_res2 += lk * lk;
    }
  }
  out.rank3 = npos + nneg;
  const int r = out.rank3;
  const double lin_res = std::sqrt(lin_res2);
  const bool lin_zero =
      lin_res <= tol * (lin_norm + std::sqrt(max3 * std::max(std::abs(q.k[9]), j_terms)));
  const bool c_zero = std::abs(j_red) <= tol * j_terms;
  const int csign = c_zero ? 0 : (j_red > 0 ? 1 : -1);
  const bool same = npos == 0 || nneg == 0;
  const int lsign = npos > 0 ? 1 : -1;  // sign of the λs when they all agree
  using T = QuadricType;
  T t = T::degenerate;
  if (r == 3) {
    if (csign == 0) {
      t = same ? T::point : T::cone;
    } else if (same) {
      if (csign == lsign) {
        t = T::imaginary;
      } else {
        const double lo =
            std::min({std::abs(nonzero[0]), std::abs(nonzero[1]), std::abs(nonzero[2])});
        const double hi =
            std::max({std::abs(nonzero[0]), std::abs(nonzero[1]), std::abs(nonzero[2])});
        t = hi - lo <= tol * hi ? T::sphere : T::ellipsoid;
      }
    } else {
      // Σ λ y² = −c: the surface has one sheet when two λ share the sign of −c.
      const int rhs = -csign;
      const int agree = rhs > 0 ? npos : nneg;
      t = agree == 2 ? T::hyperboloid_one_sheet : T::hyperboloid_two_sheets;
    }
  } else if (r == 2) {
    if (!lin_zero) {
      t = same ? T::elliptic_paraboloid : T::hyperbolic_paraboloid;
    } else if (csign == 0) {
      t = same ? T::line : T::intersecting_planes;
    } else if (same) {
      t = csign == lsign ? T::imaginary : T::elliptic_cylinder;
    } else {
      t = T::hyperbolic_cylinder;
    }
  } else if (r == 1) {
    if (!lin_zero)
      t = T::parabolic_cylinder;
    else if (csign == 0)
      t = T::single_plane;
    else
      t = csign == lsign ? T::imaginary : T::parallel_planes;
  } else {
    const bool any_lin = lin_norm > 0;
    if (any_lin)
      t = T::single_plane;
    else
      t = q.k[9] == 0 ? T::degenerate : T::imaginary;
  }
  out.type = t;
  return out;
}

}  // namespace pgamesh::quadric
