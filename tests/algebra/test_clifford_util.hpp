// Helpers shared by the clifford tests: random multivectors and golden blade dictionaries.
#pragma once

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "pgamesh/algebra/clifford.hpp"
#include "support/golden.hpp"

namespace pgamesh::test {

// A random multivector with `count` random blades of grade ≤ max_grade, coefficients in [−1, 1].
inline clifford::Multivector random_mv(const clifford::Algebra& alg, std::mt19937_64& rng,
                                       int count, int max_grade) {
  std::uniform_real_distribution<double> coeff(-1.0, 1.0);
  std::uniform_int_distribution<int> gen(0, alg.dimension() - 1);
  std::uniform_int_distribution<int> gr(0, max_grade);
  std::vector<clifford::Term> terms;
  for (int i = 0; i < count; ++i) {
    const int g = gr(rng);
    clifford::BladeMask m = 0;
    while (clifford::grade_of(m) < g) m |= clifford::BladeMask{1} << gen(rng);
    terms.push_back({m, coeff(rng)});
  }
  return clifford::from_terms(terms);
}

// A random vector (all generators).
inline clifford::Multivector random_vector(const clifford::Algebra& alg, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coeff(-1.0, 1.0);
  std::vector<clifford::Term> terms;
  for (int i = 0; i < alg.dimension(); ++i)
    terms.push_back({clifford::BladeMask{1} << i, coeff(rng)});
  return clifford::from_terms(terms);
}

// |a − b| small against the size of both.
inline ::testing::AssertionResult mv_near(const clifford::Multivector& a,
                                          const clifford::Multivector& b, double rel = 1e-12) {
  const clifford::Multivector d = a - b;
  const double scale = std::max({clifford::max_abs_coeff(a), clifford::max_abs_coeff(b), 1.0});
  for (const auto& t : d.terms)
    if (std::abs(t.coeff) > rel * scale)
      return ::testing::AssertionFailure() << "blade mask " << t.mask << " differs by " << t.coeff
                                           << " (a = " << a[t.mask] << ", b = " << b[t.mask] << ")";
  return ::testing::AssertionSuccess();
}

// A golden blade dictionary as a multivector of `alg` (names parsed by the algebra; `rename`
// maps golden generator names to the algebra's, e.g. einf → ei, w0* → w0s).
inline clifford::Multivector from_golden(const clifford::Algebra& alg, const json& dict) {
  clifford::Multivector out;
  for (auto it = dict.begin(); it != dict.end(); ++it) {
    std::string key;
    for (char ch : it.key()) key += (ch == '*') ? 's' : ch;  // DPGA's w0* is w0s here
    const auto blade = alg.parse_blade(key);
    if (!blade) throw std::runtime_error("golden blade '" + it.key() + "' not in algebra");
    out = out + clifford::basis_blade(blade->first, blade->second * it.value().get<double>());
  }
  return out;
}

// Compares with the golden rule (scale = largest |expected| of the dictionary).
inline ::testing::AssertionResult near_golden(const clifford::Algebra& alg,
                                              const clifford::Multivector& got,
                                              const json& expected, Tolerance t) {
  const clifford::Multivector want = from_golden(alg, expected);
  const double scale = clifford::max_abs_coeff(want);
  const clifford::Multivector d = got - want;
  for (const auto& term : d.terms)
    if (std::abs(term.coeff) > t.abs + t.rel * scale)
      return ::testing::AssertionFailure()
             << "blade " << alg.blade_name(term.mask).first << ": got " << got[term.mask]
             << ", expected " << want[term.mask];
  return ::testing::AssertionSuccess();
}

}  // namespace pgamesh::test
