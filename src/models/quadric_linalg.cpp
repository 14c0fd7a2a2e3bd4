// Cyclic Jacobi eigen-solver for small symmetric matrices (docs/models-quadrics.md §6, §7).
#include "quadric_linalg.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pgamesh::quadric::detail {

SymmetricEigen symmetric_eigen(const std::vector<double>& in, std::size_t n) {
  std::vector<double> a(in);
  for (std::size_t r = 0; r < n; ++r)  // symmetrise
    for (std::size_t c = r + 1; c < n; ++c)
      a[r * n + c] = a[c * n + r] = 0.5 * (a[r * n + c] + a[c * n + r]);
  std::vector<double> v(n * n, 0.0);
  for (std::size_t r = 0; r < n; ++r) v[r * n + r] = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, diag = 0;
    for (std::size_t r = 0; r < n; ++r) {
      diag += a[r * n + r] * a[r * n + r];
      for (std::size_t c = r + 1; c < n; ++c) off += a[r * n + c] * a[r * n + c];
    }
    if (off == 0 || off <= 1e-36 * diag) break;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q) {
        const double apq = a[p * n + q];
        if (apq == 0) continue;
        const double tau = (a[q * n + q] - a[p * n + p]) / (2 * apq);
        const double t = (tau >= 0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1 + tau * tau));
        const double c = 1 / std::sqrt(1 + t * t), s = t * c;
        for (std::size_t k = 0; k < n; ++k) {  // columns p, q
          const double akp = a[k * n + p], akq = a[k * n + q];
          a[k * n + p] = c * akp - s * akq;
          a[k * n + q] = s * akp + c * akq;
        }
        for (std::size_t k = 0; k < n; ++k) {  // rows p, q
          const double apk = a[p * n + k], aqk = a[q * n + k];
          a[p * n + k] = c * apk - s * aqk;
          a[q * n + k] = s * apk + c * aqk;
        }
        a[p * n + q] = a[q * n + p] = 0;
        for (std::size_t k = 0; k < n; ++k) {  // eigenvectors as columns of v
          const double vkp = v[k * n + p], vkq = v[k * n + q];
          v[k * n + p] = c * vkp - s * vkq;
          v[k * n + q] = s * vkp + c * vkq;
        }
      }
    }
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return a[x * n + x] < a[y * n + y]; });
  SymmetricEigen out;
  out.values.resize(n);
  out.vectors.resize(n * n);
  for (std::size_t k = 0; k < n; ++k) {
    out.values[k] = a[order[k] * n + order[k]];
    for (std::size_t r = 0; r < n; ++r) out.vectors[k * n + r] = v[r * n + order[k]];
  }
  return out;
}

}  // namespace pgamesh::quadric::detail
