// Shared by the pgad tests: the largest coefficient difference, and the general engine's exp and
// log in R(d,0,1), which route to pgad's closed forms, against pgad itself.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "pgamesh/algebra/clifford.hpp"
#include "pgamesh/algebra/pgad.hpp"

namespace pgamesh::test {

// max |a_i − b_i| over the 2^(D+1) coefficients.
template <int D>
double max_diff(const pgad::Multivector<D>& a, const pgad::Multivector<D>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size; ++i) m = std::max(m, std::abs(a.c[i] - b.c[i]));
  return m;
}

// clifford::exp(b) against pgad::exp(b) to 1e-12, and clifford::log of that motor against b to
// `log_tolerance`, coefficient by coefficient; `alg` is R(D,0,1).
template <int D>
void expect_engine_exp_log_match_pgad(const clifford::Algebra& alg, const pgad::Multivector<D>& b,
                                      double log_tolerance, const char* name) {
  std::vector<clifford::Term> t;
  for (clifford::BladeMask i = 0; i < b.size; ++i) t.push_back({i, b.c[i]});
  const auto gm = clifford::exp(alg, clifford::from_terms(t));
  const auto m = pgad::exp(b);
  for (clifford::BladeMask i = 0; i < m.size; ++i) EXPECT_NEAR(gm[i], m.c[i], 1e-12) << name;
  const auto gl = clifford::log(alg, gm);
  for (clifford::BladeMask i = 0; i < b.size; ++i)
    EXPECT_NEAR(gl[i], b.c[i], log_tolerance) << name;
}

}  // namespace pgamesh::test
