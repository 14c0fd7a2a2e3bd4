#include "mesh/topology/exact_predicates.hpp"

#include <cmath>
#include <cstddef>

namespace pgamesh::detail {

namespace {

// A nonoverlapping expansion: components of increasing magnitude whose exact sum is the value
// (Shewchuk 1997, §2); zero components are never stored, so the sign is that of the last one.
// 192 components hold the largest value formed here, the 3×3 determinant of two-component
// differences (3 × 2 × 2 × 16).
struct Expansion {
  static constexpr std::size_t capacity = 192;
  double c[capacity];  // c[0, n) only; the rest is never read
  std::size_t n = 0;

  int sign() const { return n == 0 ? 0 : (c[n - 1] > 0 ? 1 : (c[n - 1] < 0 ? -1 : 0)); }
};

// x + y = a + b exactly, x = fl(a + b) (Two-Sum, Theorem 7).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

// x + y = a × b exactly (Two-Product; the fused multiply-add gives the rounding error).
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

// h := h + b (Grow-Expansion, Theorem 10), in place (component i is read before slot ≤ i is
// written), zero components dropped.
void expansion_grow(Expansion& h, double b) {
  double q = b;
  std::size_t m = 0;
  for (std::size_t i = 0; i < h.n; ++i) {
    double sum = 0, error = 0;
    two_sum(q, h.c[i], sum, error);
    if (error != 0) h.c[m++] = error;
    q = sum;
  }
  if (q != 0) h.c[m++] = q;
  h.n = m;
}

// h := h + f.
void expansion_add(Expansion& h, const Expansion& f) {
  for (std::size_t i = 0; i < f.n; ++i) expansion_grow(h, f.c[i]);
}

void expansion_negate(Expansion& e) {
  for (std::size_t i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
}

// e × b (Scale-Expansion, Theorem 19, with Two-Sum for its Fast-Two-Sum), zeros dropped.
Expansion expansion_scale(const Expansion& e, double b) {
  Expansion h;
  if (e.n == 0 || b == 0) return h;
  double q = 0, low = 0;
  two_product(e.c[0], b, q, low);
  if (low != 0) h.c[h.n++] = low;
  for (std::size_t i = 1; i < e.n; ++i) {
    double product = 0, product_low = 0, sum = 0, error = 0;
    two_product(e.c[i], b, product, product_low);
    two_sum(q, product_low, sum, error);
    if (error != 0) h.c[h.n++] = error;
    two_sum(product, sum, q, error);
    if (error != 0) h.c[h.n++] = error;
  }
  if (q != 0) h.c[h.n++] = q;
  return h;
}

Expansion expansion_multiply(const Expansion& e, const Expansion& f) {
  Expansion h;
  for (std::size_t i = 0; i < f.n; ++i) expansion_add(h, expansion_scale(e, f.c[i]));
  return h;
}

// a − b exactly, as an expansion of at most two components.
Expansion exact_difference(double a, double b) {
  Expansion h;
  double x = 0, y = 0;
  two_sum(a, -b, x, y);
  if (y != 0) h.c[h.n++] = y;
  if (x != 0) h.c[h.n++] = x;
  return h;
}

// Shewchuk's error bounds for the rounded determinants (stage A), ε = 2^-53.
constexpr double half_ulp_of_one = 0x1p-53;
constexpr double orient2d_bound = (3.0 + 16.0 * half_ulp_of_one) * half_ulp_of_one;
constexpr double orient3d_bound = (7.0 + 56.0 * half_ulp_of_one) * half_ulp_of_one;
// Below this permanent, products may be subnormal and the bound no longer holds: exact path.
constexpr double smallest_filtered_permanent = 1e-280;

int determinant_sign(double x) {
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
  const Expansion ux = exact_difference(bx, ax), uy = exact_difference(by, ay);
  const Expansion vx = exact_difference(cx, ax), vy = exact_difference(cy, ay);
  Expansion det = expansion_multiply(ux, vy);
  Expansion right = expansion_multiply(uy, vx);
  expansion_negate(right);
  expansion_add(det, right);
  return det.sign();
}

int orient3d_exact(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  Expansion u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = exact_difference(b[k], a[k]);
    v[k] = exact_difference(c[k], a[k]);
    w[k] = exact_difference(d[k], a[k]);
  }
  // (u × v) · w, each component of the cross product a 2×2 minor.
  Expansion det;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Expansion minor = expansion_multiply(u[i], v[j]);
    Expansion right = expansion_multiply(u[j], v[i]);
    expansion_negate(right);
    expansion_add(minor, right);
    expansion_add(det, expansion_multiply(minor, w[k]));
  }
  return det.sign();
}

}  // namespace

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (bx - ax) * (cy - ay);
  const double right = (by - ay) * (cx - ax);
  const double det = left - right;
  const double permanent = std::abs(left) + std::abs(right);
  const double bound = orient2d_bound * permanent;
  if ((det > bound || -det > bound) && permanent > smallest_filtered_permanent)
    return determinant_sign(det);
  if (permanent == 0) return 0;  // both products exactly 0: so is the determinant
  return orient2d_exact(ax, ay, bx, by, cx, cy);
}

int orient3d(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  // Shewchuk's orient3d, det[a − d, b − d, c − d]: positive when d lies below the plane of the
  // counter-clockwise a, b, c, the opposite of det[b − a, c − a, d − a]; hence the minus.
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  const double bound = orient3d_bound * permanent;
  if ((det > bound || -det > bound) && permanent > smallest_filtered_permanent)
    return -determinant_sign(det);
  return orient3d_exact(a, b, c, d);
}

int orient2d_without(int drop, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  return orient2d(a[i], a[j], b[i], b[j], c[i], c[j]);
}

bool collinear(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return orient2d_without(0, a, b, c) == 0 && orient2d_without(1, a, b, c) == 0 &&
         orient2d_without(2, a, b, c) == 0;
}

}  // namespace pgamesh::detail
