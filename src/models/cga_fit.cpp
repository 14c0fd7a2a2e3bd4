// Sphere, plane and cylinder fits (docs/models-cga.md §8).
#include "pgamesh/models/cga_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pgamesh/models/cga_objects.hpp"
#include "pgamesh/models/cga_point.hpp"
#include "pgamesh/models/model_error.hpp"

namespace pgamesh::cga {

namespace {

template <std::size_t N>
using Mat = std::array<std::array<double, N>, N>;

// Cyclic Jacobi for a symmetric N×N matrix: eigenvalues ascending, eigenvectors as columns of v.
template <std::size_t N>
void eigen_symmetric(Mat<N> a, std::array<double, N>& values, Mat<N>& v) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (std::size_t i = 0; i < N; ++i) {
      diag += a[i][i] * a[i][i];
      for (std::size_t j = i + 1; j < N; ++j) off += a[i][j] * a[i][j];
    }
    if (off <= 1e-32 * diag || off == 0) break;
    for (std::size_t p = 0; p < N; ++p)
      for (std::size_t q = p + 1; q < N; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (std::size_t k = 0; k < N; ++k) {  // a ← a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (std::size_t k = 0; k < N; ++k) {  // a ← Jᵀ a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (std::size_t k = 0; k < N; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  std::array<std::size_t, N> order{};
  for (std::size_t i = 0; i < N; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return a[i][i] < a[j][j]; });
  Mat<N> vs{};
  for (std::size_t c = 0; c < N; ++c) {
    values[c] = a[order[c]][order[c]];
    for (std::size_t r = 0; r < N; ++r) vs[r][c] = v[r][order[c]];
  }
  v = vs;
}

// Solves the N×N system m x = b by Gaussian elimination with partial pivoting; false if singular.
template <std::size_t N>
bool solve(Mat<N> m, std::array<double, N> b, std::array<double, N>& x) {
  for (std::size_t c = 0; c < N; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < N; ++r)
      if (std::abs(m[r][c]) > std::abs(m[piv][c])) piv = r;
    if (m[piv][c] == 0 || !std::isfinite(m[piv][c])) return false;
    std::swap(m[c], m[piv]);
    std::swap(b[c], b[piv]);
    for (std::size_t r = c + 1; r < N; ++r) {
      const double f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < N; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = N; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < N; ++k) s -= m[c][k] * x[k];
    x[c] = s / m[c][c];
  }
  return true;
}

void require_points(std::span<const Vec3d> points, std::size_t needed, const char* what) {
  if (points.size() < needed)
    throw ModelError(std::string(what) + ": needs at least " + std::to_string(needed) +
                     " points, got " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3d p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw ModelError(std::string(what) + ": point " + std::to_string(i) +
                       " has a non-finite coordinate (NaN or infinite)");
  }
}

Vec3d centroid(std::span<const Vec3d> points) {
  Vec3d s{};
  for (const Vec3d& p : points) s += p;
  return s / static_cast<double>(points.size());
}

// Scatter matrix Σ (x − m)(x − m)ᵀ.
Mat<3> scatter(std::span<const Vec3d> points, Vec3d m) {
  Mat<3> s{};
  for (const Vec3d& p : points) {
    const Vec3d q = p - m;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) s[i][j] += q[i] * q[j];
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < i; ++j) s[i][j] = s[j][i];
  return s;
}

Vec3d column(const Mat<3>& v, int c) {
  return {v[0][c], v[1][c], v[2][c]};
}

// Flips v so that its largest-magnitude component is positive.
Vec3d canonical_sign(Vec3d v) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[i]) > std::abs(v[k])) k = i;
  return v[k] < 0 ? -v : v;
}

// Two unit vectors completing d (unit) to an orthonormal frame.
void frame(Vec3d d, Vec3d& u, Vec3d& v) {
  const Vec3d a = std::abs(d.x) < 0.6 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  u = cross(d, a);
  u = u / length(u);
  v = cross(d, u);
}

struct Spread {
  Vec3d center;
  double scale;
};

Spread spread_of(std::span<const Vec3d> points, const char* what) {
  const Vec3d m = centroid(points);
  double s2 = 0;
  for (const Vec3d& p : points) s2 += dot(p - m, p - m);
  const double s = std::sqrt(s2 / static_cast<double>(points.size()));
  if (!(s > 0)) throw ModelError(std::string(what) + ": all points coincide");
  return {m, s};
}

// Throws when the points (about m) lie on one line: the middle scatter eigenvalue vanishes.
void require_not_collinear(const std::array<double, 3>& values, const char* what) {
  if (!(values[1] > 1e-24 * values[2]))
    throw ModelError(std::string(what) + ": the points are collinear");
}

}  // namespace

SphereFit fit_sphere(std::span<const Vec3d> points) {
  const char* what = "cga::fit_sphere";
  require_points(points, 4, what);
  const Spread sp = spread_of(points, what);
  // M = Σ r rᵀ, r = (q, −1, −½|q|²): X·S = q·a − a4 − ½|q|² a5 for S = a1 e1 + a2 e2 + a3 e3
  // + a4 e_∞ + a5 e_o, with q the points about the centroid in units of their RMS spread.
  Mat<5> m{};
  const double inv = 1 / sp.scale;
  for (const Vec3d& p : points) {
    const Vec3d q = (p - sp.center) * inv;
    const std::array<double, 5> r = {q.x, q.y, q.z, -1.0, -0.5 * dot(q, q)};
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = i; j < 5; ++j) m[i][j] += r[i] * r[j];
  }
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = 0; j < i; ++j) m[i][j] = m[j][i];
  // Minimise aᵀ M a subject to aᵀ B a = S² = 1, B = diag(1, 1, 1) ⊕ [[0, −1], [−1, 0]]
  // (e_o·e_∞ = −1): M a = η B a with the smallest η > 0. With M = Y², a = Y⁻¹ e and
  // Y B Y e = η e (B⁻¹ = B).
  std::array<double, 5> lam{};
  Mat<5> q{};
  eigen_symmetric<5>(m, lam, q);
  std::array<double, 5> a{};
  if (!(lam[0] > 1e-30 * lam[4])) {
    for (std::size_t i = 0; i < 5; ++i) a[i] = q[i][0];  // an exact fit: the null vector of M
  } else {
    Mat<5> y{}, yinv{};
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = 0; j < 5; ++j)
        for (std::size_t k = 0; k < 5; ++k) {
          y[i][j] += q[i][k] * std::sqrt(lam[k]) * q[j][k];
          yinv[i][j] += q[i][k] / std::sqrt(lam[k]) * q[j][k];
        }
    const Mat<5> b = {
        {{1, 0, 0, 0, 0}, {0, 1, 0, 0, 0}, {0, 0, 1, 0, 0}, {0, 0, 0, 0, -1}, {0, 0, 0, -1, 0}}};
    Mat<5> yb{}, c{};
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = 0; j < 5; ++j)
        for (std::size_t k = 0; k < 5; ++k) yb[i][j] += y[i][k] * b[k][j];
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = 0; j < 5; ++j)
        for (std::size_t k = 0; k < 5; ++k) c[i][j] += yb[i][k] * y[k][j];
    std::array<double, 5> eta{};
    Mat<5> e{};
    eigen_symmetric<5>(c, eta, e);
    std::size_t best = 5;
    for (std::size_t k = 0; k < 5; ++k)
      if (eta[k] > 0) {
        best = k;
        break;
      }
    if (best == 5) throw ModelError(std::string(what) + ": no real sphere fits the points");
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t k = 0; k < 5; ++k) a[i] += yinv[i][k] * e[k][best];
  }
  double norm_a = 0;
  for (double x : a) norm_a = std::max(norm_a, std::abs(x));
  if (!(std::abs(a[4]) > 1e-12 * norm_a))
    throw ModelError(
        std::string(what) +
        ": the points are coplanar: the best-fitting sphere is a plane (use fit_plane)");
  const Vec3d qc = Vec3d{a[0], a[1], a[2]} / a[4];
  const double rho2 = dot(qc, qc) - 2 * a[3] / a[4];
  if (!(rho2 > 0)) throw ModelError(std::string(what) + ": no real sphere fits the points");
  SphereFit f;
  f.center = sp.center + sp.scale * qc;
  f.radius = sp.scale * std::sqrt(rho2);
  double sum = 0, mx = 0;
  for (const Vec3d& p : points) {
    const double d = length(p - f.center) - f.radius;
    sum += d * d;
    mx = std::max(mx, std::abs(d));
  }
  f.rms = std::sqrt(sum / static_cast<double>(points.size()));
  f.max_error = mx;
  f.dual_sphere = dual_sphere(f.center, f.radius);
  return f;
}

PlaneFit fit_plane(std::span<const Vec3d> points) {
  const char* what = "cga::fit_plane";
  require_points(points, 3, what);
  const Vec3d m = centroid(points);
  std::array<double, 3> values{};
  Mat<3> vecs{};
  eigen_symmetric<3>(scatter(points, m), values, vecs);
  if (!(values[2] > 0)) throw ModelError(std::string(what) + ": all points coincide");
  require_not_collinear(values, what);
  PlaneFit f;
  f.point = m;
  f.normal = canonical_sign(column(vecs, 0));
  f.normal = f.normal / length(f.normal);
  f.distance = dot(f.normal, m);
  double sum = 0, mx = 0;
  for (const Vec3d& p : points) {
    const double d = dot(f.normal, p - m);
    sum += d * d;
    mx = std::max(mx, std::abs(d));
  }
  f.rms = std::sqrt(sum / static_cast<double>(points.size()));
  f.max_error = mx;
  f.dual_plane = dual_plane(f.normal, f.distance);
  return f;
}

namespace {

struct Axis {
  Vec3d p, d;  // point (in the plane through the origin ⊥ d) and unit direction
  double rho = 0;
  double cost = std::numeric_limits<double>::infinity();
};

// Algebraic (Kåsa) circle fit of the points projected along d, then its geometric cost.
Axis circle_along(std::span<const Vec3d> q, Vec3d d, std::size_t stride) {
  Vec3d u, v;
  frame(d, u, v);
  Mat<3> m{};
  std::array<double, 3> rhs{};
  for (std::size_t i = 0; i < q.size(); i += stride) {
    const double x = dot(q[i], u), y = dot(q[i], v), r2 = x * x + y * y;
    const std::array<double, 3> row = {x, y, 1.0};
    for (std::size_t a = 0; a < 3; ++a) {
      for (std::size_t b = 0; b < 3; ++b) m[a][b] += row[a] * row[b];
      rhs[a] -= row[a] * r2;
    }
  }
  std::array<double, 3> s{};
  Axis ax;
  ax.d = d;
  if (!solve<3>(m, rhs, s)) return ax;
  const double cx = -0.5 * s[0], cy = -0.5 * s[1], r2 = cx * cx + cy * cy - s[2];
  if (!(r2 > 0)) return ax;
  ax.p = cx * u + cy * v;
  ax.rho = std::sqrt(r2);
  double cost = 0;
  for (std::size_t i = 0; i < q.size(); i += stride) {
    const Vec3d y = q[i] - ax.p;
    const double e = length(y - dot(y, d) * d) - ax.rho;
    cost += e * e;
  }
  ax.cost = cost;
  return ax;
}

double cylinder_cost(std::span<const Vec3d> q, const Axis& a) {
  double cost = 0;
  for (const Vec3d& x : q) {
    const Vec3d y = x - a.p;
    const double e = length(y - dot(y, a.d) * a.d) - a.rho;
    cost += e * e;
  }
  return cost;
}

// Levenberg–Marquardt on r_i = |(q_i − p) − ((q_i − p)·d) d| − ρ over p (2), d (2), ρ (1).
Axis refine(std::span<const Vec3d> q, Axis a, int& iterations) {
  a.cost = cylinder_cost(q, a);
  double lambda = 1e-3;
  for (iterations = 0; iterations < 200; ++iterations) {
    Vec3d u, v;
    frame(a.d, u, v);
    Mat<5> jtj{};
    std::array<double, 5> jtr{};
    for (const Vec3d& x : q) {
      const Vec3d y = x - a.p;
      const double yd = dot(y, a.d);
      const Vec3d w = y - yd * a.d;
      const double lw = length(w);
      const double r = lw - a.rho;
      const double wu = lw > 0 ? dot(w, u) / lw : 0.0, wv = lw > 0 ? dot(w, v) / lw : 0.0;
      const std::array<double, 5> j = {-wu, -wv, -yd * wu, -yd * wv, -1.0};
      for (std::size_t i = 0; i < 5; ++i) {
        jtr[i] += j[i] * r;
        for (std::size_t k = i; k < 5; ++k) jtj[i][k] += j[i] * j[k];
      }
    }
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t k = 0; k < i; ++k) jtj[i][k] = jtj[k][i];
    bool accepted = false;
    for (int tries = 0; tries < 30 && !accepted; ++tries) {
      Mat<5> m = jtj;
      for (std::size_t i = 0; i < 5; ++i) m[i][i] += lambda * (jtj[i][i] + 1e-12);
      std::array<double, 5> neg{}, step{};
      for (std::size_t i = 0; i < 5; ++i) neg[i] = -jtr[i];
      if (!solve<5>(m, neg, step)) {
        lambda *= 10;
        continue;
      }
      Axis b = a;
      b.p = a.p + step[0] * u + step[1] * v;
      b.d = a.d + step[2] * u + step[3] * v;
      b.d = b.d / length(b.d);
      b.p = b.p - dot(b.p, b.d) * b.d;
      b.rho = a.rho + step[4];
      b.cost = cylinder_cost(q, b);
      if (b.cost <= a.cost) {
        const double gain = a.cost - b.cost;
        a = b;
        lambda = std::max(lambda / 3, 1e-12);
        accepted = true;
        double st = 0;
        for (double s : step) st = std::max(st, std::abs(s));
        if (gain <= 1e-15 * a.cost || st <= 1e-13) return a;
      } else {
        lambda *= 4;
      }
    }
    if (!accepted) return a;
  }
  return a;
}

}  // namespace

CylinderFit fit_cylinder(std::span<const Vec3d> points) {
  const char* what = "cga::fit_cylinder";
  require_points(points, 6, what);
  const Spread sp = spread_of(points, what);
  std::vector<Vec3d> q(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) q[i] = (points[i] - sp.center) / sp.scale;
  std::array<double, 3> values{};
  Mat<3> vecs{};
  eigen_symmetric<3>(scatter(q, Vec3d{}), values, vecs);
  require_not_collinear(values, what);
  // Candidate axes: the PCA axes and 256 directions spread over the hemisphere (Fibonacci
  // lattice), each scored on at most ~2000 of the points.
  const std::size_t stride = std::max<std::size_t>(1, q.size() / 2000);
  std::vector<Axis> cands;
  for (int c = 0; c < 3; ++c) cands.push_back(circle_along(q, column(vecs, c), stride));
  const int k = 256;
  const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
  for (int i = 0; i < k; ++i) {
    const double z = (i + 0.5) / k, r = std::sqrt(1 - z * z), phi = golden * i;
    cands.push_back(circle_along(q, Vec3d{r * std::cos(phi), r * std::sin(phi), z}, stride));
  }
  std::sort(cands.begin(), cands.end(),
            [](const Axis& a, const Axis& b) { return a.cost < b.cost; });
  Axis best;
  int best_iterations = 0;
  for (std::size_t i = 0; i < std::min<std::size_t>(4, cands.size()); ++i) {
    if (!std::isfinite(cands[i].cost)) break;
    int it = 0;
    const Axis a = refine(q, cands[i], it);
    if (a.cost < best.cost) {
      best = a;
      best_iterations = it;
    }
  }
  if (!std::isfinite(best.cost) || !(best.rho > 0) || best.rho > 1e6)
    throw ModelError(std::string(what) +
                     ": no finite cylinder fits the points (are they on a plane?)");
  CylinderFit f;
  f.axis_direction = canonical_sign(best.d);
  f.axis_point = sp.center + sp.scale * best.p;
  f.radius = sp.scale * best.rho;
  f.iterations = best_iterations;
  double sum = 0, mx = 0;
  for (const Vec3d& p : points) {
    const Vec3d y = p - f.axis_point;
    const double e = length(y - dot(y, f.axis_direction) * f.axis_direction) - f.radius;
    sum += e * e;
    mx = std::max(mx, std::abs(e));
  }
  f.rms = std::sqrt(sum / static_cast<double>(points.size()));
  f.max_error = mx;
  return f;
}

}  // namespace pgamesh::cga
