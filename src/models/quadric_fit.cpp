// Least-squares quadric fit and the quadric through nine points (docs/models-quadrics.md §7).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pgamesh/models/quadric.hpp"
#include "quadric_linalg.hpp"

namespace pgamesh::quadric {

namespace {

// Centroid m and scale s with mean |p − m|² = 3 s² (unit RMS per coordinate after scaling).
struct Frame {
  Vec3d m{};
  double s = 1;
};

Frame normalizing_frame(std::span<const Vec3d> pts, const char* who) {
  Frame f;
  for (const Vec3d& p : pts) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw ModelError(std::string(who) + ": a point coordinate is NaN or infinite");
    for (int k = 0; k < 3; ++k) f.m[k] += p[k];
  }
  const double n = static_cast<double>(pts.size());
  for (int k = 0; k < 3; ++k) f.m[k] /= n;
  double s2 = 0;
  for (const Vec3d& p : pts)
    for (int k = 0; k < 3; ++k) s2 += (p[k] - f.m[k]) * (p[k] - f.m[k]);
  f.s = std::sqrt(s2 / (3 * n));
  if (!(f.s > 0)) throw ModelError(std::string(who) + ": the points coincide");
  return f;
}

Vec3d to_frame(const Frame& f, const Vec3d& p) {
  return {(p[0] - f.m[0]) / f.s, (p[1] - f.m[1]) / f.s, (p[2] - f.m[2]) / f.s};
}

// G is a quadric in frame coordinates u = (x − m)/s: F(x) = G((x − m)/s).
Quadric from_frame(const Frame& f, const Quadric& g) {
  const double w = 1 / f.s;
  return substitute(g, {{{w, 0, 0}, {0, w, 0}, {0, 0, w}}},
                    {-f.m[0] * w, -f.m[1] * w, -f.m[2] * w});
}

}  // namespace

Residuals residuals(const Quadric& q_in, std::span<const Vec3d> pts) {
  const Quadric q = normalized(q_in);
  Residuals r;
  if (pts.empty()) return r;
  double sa = 0, sg = 0;
  for (const Vec3d& p : pts) {
    const double v = std::abs(value(q, p));
    const Vec3d g = gradient(q, p);
    const double gl = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double d = v == 0 ? 0.0 : (gl > 0 ? v / gl : std::numeric_limits<double>::infinity());
    sa += v * v;
    sg += d * d;
    r.algebraic_max = std::max(r.algebraic_max, v);
    r.geometric_max = std::max(r.geometric_max, d);
  }
  const double n = static_cast<double>(pts.size());
  r.algebraic_rms = std::sqrt(sa / n);
  r.geometric_rms = std::sqrt(sg / n);
  return r;
}

FitResult fit(std::span<const Vec3d> pts) {
  if (pts.size() < 9)
    throw ModelError("quadric::fit: needs at least 9 points, got " + std::to_string(pts.size()));
  const Frame f = normalizing_frame(pts, "quadric::fit");
  // Scatter matrix Σ v vᵀ of the monomials in frame coordinates (upper triangle, 55 sums).
  std::array<double, 55> acc{};
  for (const Vec3d& p : pts) {
    const std::array<double, 10> v = monomials(to_frame(f, p));
    std::size_t n = 0;
    for (std::size_t r = 0; r < 10; ++r)
      for (std::size_t c = r; c < 10; ++c) acc[n++] += v[r] * v[c];
  }
  std::vector<double> s(100);
  std::size_t idx = 0;
  for (std::size_t r = 0; r < 10; ++r)
    for (std::size_t c = r; c < 10; ++c) s[r * 10 + c] = s[c * 10 + r] = acc[idx++];
  const detail::SymmetricEigen e = detail::symmetric_eigen(s, 10);
  const double lmax = std::max(std::abs(e.values[9]), std::numeric_limits<double>::min());
  FitResult out;
  out.smallest_eigenvalue_ratio = std::max(0.0, e.values[0]) / lmax;
  out.second_smallest_eigenvalue_ratio = e.values[1] / lmax;
  if (!(out.second_smallest_eigenvalue_ratio > 1e-12))
    throw ModelError(
        "quadric::fit: the points do not determine a unique quadric (they lie on a lower-order "
        "surface or are otherwise degenerate)");
  Quadric g;
  for (std::size_t k = 0; k < 10; ++k) g.k[k] = e.vectors[k];
  const Quadric global = from_frame(f, g);
  out.quadric = normalized(global);
  out.local = g;
  out.centroid = f.m;
  out.scale = f.s;
  // Residuals in the frame: F(x) = G(u)/N with N the norm of the global coefficients, and the
  // first-order distance |G(u)|/‖∇_u G‖ · scale (exact in exact arithmetic, no cancellation).
  double norm2 = 0;
  for (double c : global.k) norm2 += c * c;
  const double nrm = std::sqrt(norm2);
  double sa = 0, sg = 0;
  for (const Vec3d& p : pts) {
    const Vec3d u = to_frame(f, p);
    const double v = std::abs(value(g, u));
    const Vec3d gr = gradient(g, u);
    const double gl = std::sqrt(gr[0] * gr[0] + gr[1] * gr[1] + gr[2] * gr[2]);
    const double a = v / nrm;
    const double d =
        v == 0 ? 0.0 : (gl > 0 ? v / gl * f.s : std::numeric_limits<double>::infinity());
    sa += a * a;
    sg += d * d;
    out.algebraic_max = std::max(out.algebraic_max, a);
    out.geometric_max = std::max(out.geometric_max, d);
  }
  const double n = static_cast<double>(pts.size());
  out.algebraic_rms = std::sqrt(sa / n);
  out.geometric_rms = std::sqrt(sg / n);
  return out;
}

Quadric through_nine_points(std::span<const Vec3d, 9> pts) {
  const Frame f = normalizing_frame(pts, "quadric::through_nine_points");
  double m[9][10];
  for (std::size_t r = 0; r < 9; ++r) {
    const std::array<double, 10> v = monomials(to_frame(f, pts[r]));
    for (std::size_t c = 0; c < 10; ++c) m[r][c] = v[c];
  }
  // Gaussian elimination with complete pivoting; col[k] is the column eliminated at step k.
  std::array<int, 10> col{};
  for (int c = 0; c < 10; ++c) col[static_cast<std::size_t>(c)] = c;
  double first_pivot = 0;
  for (int k = 0; k < 9; ++k) {
    int pr = k, pc = k;
    double best = -1;
    for (int r = k; r < 9; ++r)
      for (int c = k; c < 10; ++c)
        if (std::abs(m[r][col[static_cast<std::size_t>(c)]]) > best) {
          best = std::abs(m[r][col[static_cast<std::size_t>(c)]]);
          pr = r;
          pc = c;
        }
    if (k == 0) first_pivot = best;
    if (!(best > 1e-10 * first_pivot))
      throw ModelError(
          "quadric::through_nine_points: the points do not determine a unique quadric (they lie "
          "on a lower-order surface or are otherwise degenerate)");
    std::swap(col[static_cast<std::size_t>(k)], col[static_cast<std::size_t>(pc)]);
    for (int c = 0; c < 10; ++c) std::swap(m[k][c], m[pr][c]);
    const int ck = col[static_cast<std::size_t>(k)];
    for (int r = k + 1; r < 9; ++r) {
      const double factor = m[r][ck] / m[k][ck];
      if (factor == 0) continue;
      for (int c = 0; c < 10; ++c) m[r][c] -= factor * m[k][c];
    }
  }
  // Null vector: the free column col[9] = 1, back substitution for the pivot columns.
  Quadric g;
  g.k[static_cast<std::size_t>(col[9])] = 1;
  for (int k = 8; k >= 0; --k) {
    double sum = 0;
    for (int c = k + 1; c < 10; ++c)
      sum += m[k][col[static_cast<std::size_t>(c)]] *
             g.k[static_cast<std::size_t>(col[static_cast<std::size_t>(c)])];
    const int ck = col[static_cast<std::size_t>(k)];
    g.k[static_cast<std::size_t>(ck)] = -sum / m[k][ck];
  }
  return normalized(from_frame(f, g));
}

}  // namespace pgamesh::quadric
