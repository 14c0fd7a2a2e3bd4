// Divided differences f[x_0], f[x_0, x_1], …, f[x_0, …, x_n] of an analytic scalar function at
// ascending nodes, which may coincide or nearly coincide: the coefficients of the Newton form
// f(Y) = Σ_n f[x_0 … x_n] Π_(i<n) (Y − x_i) of a function of a commuting element Y whose
// eigenvalues are the nodes (repeated nodes = Hermite conditions, for nilpotent parts of Y).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pgamesh::clifford {

namespace detail {
// Taylor terms beyond the order that a run of nodes of spread `spread` needs, when 30 reach
// round-off over `width`: the k-th term carries h_k ~ (spread / width)^k times what it carries
// at the full width, so the terms fall faster by that ratio. A run of coincident nodes needs none
// (h_k = 0 for k ≥ 1: the divided difference is the Taylor coefficient f^(n)/n!).
inline int taylor_terms_beyond_order(double spread, double width) {
  constexpr int at_full_width = 30;
  if (spread <= 0) return 0;
  if (spread >= width) return at_full_width;
  constexpr double log_round_off = -36.04;  // ln 2^−52
  const double terms =
      at_full_width / (1 + at_full_width * std::log(spread / width) / log_round_off);
  return static_cast<int>(std::ceil(terms));
}
}  // namespace detail

// Divided differences of K functions at once, sharing the Taylor coefficients (which may come
// from one computation for all of them). `value(x, b)` gives the K values f_q(x);
// `taylor(c, count, b)` the K lists of Taylor coefficients a_0 … a_(count−1) of f_q about c;
// `cluster_width(c, b)` the spread of nodes around c over which 30 more Taylor terms than the
// order reach round-off. A run of nodes x_i … x_j within that spread has
// f[x_i … x_j] = Σ_(m≥j−i) a_m h_(m−(j−i))(x_i − c, …, x_j − c) (h_k: complete homogeneous
// symmetric polynomials, c the run's midpoint), exact for coincident nodes (derivatives) and
// free of the cancellation of difference quotients; wider runs use the quotient recurrence
// f[x_i … x_j] = (f[x_(i+1) … x_j] − f[x_i … x_(j−1)]) / (x_j − x_i).
// `branch[i]` selects one of several functions per node, e.g. branches of a logarithm; runs
// mixing branches use the quotients. Result[q] = the divided differences of f_q.
template <std::size_t K, class Value, class Taylor, class Width>
std::array<std::vector<double>, K> divided_differences_of(const std::vector<double>& x,
                                                          const std::vector<int>& branch,
                                                          Value value, Taylor taylor,
                                                          Width cluster_width) {
  const std::size_t n = x.size();
  // table[i][j − i][q] = f_q[x_i … x_j]
  std::vector<std::vector<std::array<double, K>>> table(n);
  for (std::size_t i = 0; i < n; ++i) table[i] = {value(x[i], branch[i])};
  for (std::size_t len = 1; len < n; ++len) {
    for (std::size_t i = 0; i + len < n; ++i) {
      const std::size_t j = i + len;
      const double centre = 0.5 * (x[i] + x[j]);
      bool one_branch = true;
      for (std::size_t t = i; t < j; ++t) one_branch = one_branch && branch[t] == branch[j];
      std::array<double, K> dd{};
      const double width = one_branch ? cluster_width(centre, branch[j]) : 0.0;
      if (one_branch && x[j] - x[i] <= width) {
        const int extra_terms = detail::taylor_terms_beyond_order(x[j] - x[i], width);
        const int count = static_cast<int>(len) + extra_terms + 1;
        const std::array<std::vector<double>, K> a = taylor(centre, count, branch[j]);
        std::vector<double> h(static_cast<std::size_t>(extra_terms) + 1, 0.0);
        h[0] = 1;  // h_k over the empty set of variables; then add x_i … x_j one by one
        for (std::size_t t = i; t <= j; ++t)
          for (std::size_t k = 1; k < h.size(); ++k) h[k] += (x[t] - centre) * h[k - 1];
        for (std::size_t q = 0; q < K; ++q)
          for (std::size_t k = 0; k < h.size(); ++k) dd[q] += a[q][len + k] * h[k];
      } else {
        for (std::size_t q = 0; q < K; ++q)
          dd[q] = (table[i + 1][len - 1][q] - table[i][len - 1][q]) / (x[j] - x[i]);
      }
      table[i].push_back(dd);
    }
  }
  std::array<std::vector<double>, K> result;
  for (std::size_t q = 0; q < K; ++q)
    for (const std::array<double, K>& d : table[0]) result[q].push_back(d[q]);
  return result;
}

// One function per node, selected by `branch[i]`: value(x, b), taylor(c, count, b),
// cluster_width(c, b) for a scalar function.
template <class Value, class Taylor, class Width>
std::vector<double> divided_differences(const std::vector<double>& x,
                                        const std::vector<int>& branch, Value value, Taylor taylor,
                                        Width cluster_width) {
  return divided_differences_of<1>(
      x, branch, [&value](double y, int b) { return std::array<double, 1>{value(y, b)}; },
      [&taylor](double c, int count, int b) {
        return std::array<std::vector<double>, 1>{taylor(c, count, b)};
      },
      cluster_width)[0];
}

// One function for every node.
template <class Value, class Taylor, class Width>
std::vector<double> divided_differences(const std::vector<double>& x, Value value, Taylor taylor,
                                        Width cluster_width) {
  return divided_differences(
      x, std::vector<int>(x.size(), 0), [&value](double y, int) { return value(y); },
      [&taylor](double c, int count, int) { return taylor(c, count); },
      [&cluster_width](double c, int) { return cluster_width(c); });
}

}  // namespace pgamesh::clifford
