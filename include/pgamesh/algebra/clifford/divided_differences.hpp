// Divided differences f[x_0], f[x_0, x_1], …, f[x_0, …, x_n] of an analytic scalar function at
// ascending nodes, which may coincide or nearly coincide: the coefficients of the Newton form
// f(Y) = Σ_n f[x_0 … x_n] Π_(i<n) (Y − x_i) of a function of a commuting element Y whose
// eigenvalues are the nodes (repeated nodes = Hermite conditions, for nilpotent parts of Y).
#pragma once

#include <cstddef>
#include <vector>

namespace pgamesh::clifford {

// `value(x)` gives f(x); `taylor(c, count)` the Taylor coefficients a_0 … a_(count−1) of f about
// c; `cluster_width(c)` the spread of nodes around c over which 30 more Taylor terms than the
// order reach round-off. A run of nodes x_i … x_j within that spread has
// f[x_i … x_j] = Σ_(m≥j−i) a_m h_(m−(j−i))(x_i − c, …, x_j − c) (h_k: complete homogeneous
// symmetric polynomials, c the run's midpoint), exact for coincident nodes (derivatives) and
// free of the cancellation of difference quotients; wider runs use the quotient recurrence
// f[x_i … x_j] = (f[x_(i+1) … x_j] − f[x_i … x_(j−1)]) / (x_j − x_i).
// `branch[i]` selects one of several functions per node (value(x, b), taylor(c, count, b),
// cluster_width(c, b)), e.g. branches of a logarithm; runs mixing branches use the quotients.
template <class Value, class Taylor, class Width>
std::vector<double> divided_differences(const std::vector<double>& x,
                                        const std::vector<int>& branch, Value value, Taylor taylor,
                                        Width cluster_width) {
  const std::size_t n = x.size();
  constexpr int extra_terms = 30;
  // table[i][j − i] = f[x_i … x_j]
  std::vector<std::vector<double>> table(n);
  for (std::size_t i = 0; i < n; ++i) table[i] = {value(x[i], branch[i])};
  for (std::size_t len = 1; len < n; ++len) {
    for (std::size_t i = 0; i + len < n; ++i) {
      const std::size_t j = i + len;
      const double centre = 0.5 * (x[i] + x[j]);
      bool one_branch = true;
      for (std::size_t t = i; t < j; ++t) one_branch = one_branch && branch[t] == branch[j];
      double dd;
      if (one_branch && x[j] - x[i] <= cluster_width(centre, branch[j])) {
        const int count = static_cast<int>(len) + extra_terms + 1;
        const std::vector<double> a = taylor(centre, count, branch[j]);
        std::vector<double> h(static_cast<std::size_t>(extra_terms) + 1, 0.0);
        h[0] = 1;  // h_k over the empty set of variables; then add x_i … x_j one by one
        for (std::size_t t = i; t <= j; ++t)
          for (std::size_t k = 1; k < h.size(); ++k) h[k] += (x[t] - centre) * h[k - 1];
        dd = 0;
        for (std::size_t k = 0; k < h.size(); ++k) dd += a[len + k] * h[k];
      } else {
        dd = (table[i + 1][len - 1] - table[i][len - 1]) / (x[j] - x[i]);
      }
      table[i].push_back(dd);
    }
  }
  return table[0];
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
