// A multivector of the general Clifford engine: a sorted sparse list of (blade, coefficient).
// Blades absent from the list are zero, so R(9,6) elements with few non-zero coefficients stay
// small; products skip zeros by construction. The multivector does not know its algebra: the
// metric products take the algebra (clifford::Algebra) as their first argument.
#pragma once

#include <vector>

#include "pgamesh/algebra/clifford/blade.hpp"

namespace pgamesh::clifford {

struct Term {
  BladeMask mask;
  double coeff;
};

struct Multivector {
  std::vector<Term> terms;  // strictly ascending masks, no exact zeros

  // Coefficient of the basis blade `mask` (0 when absent).
  double operator[](BladeMask mask) const;
  bool is_zero() const { return terms.empty(); }
};

// The scalar s (the empty multivector when s == 0).
Multivector scalar(double s);

// c times the basis blade `mask`.
Multivector basis_blade(BladeMask mask, double c = 1.0);

// Builds a multivector from terms in any order; equal masks are summed, exact zeros dropped.
Multivector from_terms(std::vector<Term> terms);

Multivector operator+(const Multivector& a, const Multivector& b);
Multivector operator-(const Multivector& a, const Multivector& b);
Multivector operator-(const Multivector& a);
Multivector operator*(double s, const Multivector& a);
Multivector operator*(const Multivector& a, double s);
Multivector operator/(const Multivector& a, double s);

// Grade projection ⟨A⟩_k.
Multivector grade(const Multivector& a, int k);

// The scalar part ⟨A⟩_0.
double scalar_part(const Multivector& a);

// Largest |coefficient| (0 for zero).
double max_abs_coeff(const Multivector& a);

// Bitmask of the grades present (bit k set <=> ⟨A⟩_k ≠ 0).
unsigned grades_present(const Multivector& a);

// Drops coefficients with |c| <= eps (rounding residue after cancellations).
Multivector pruned(const Multivector& a, double eps);

// Reverse Ã (factors in reverse order): grade k scaled by (−1)^(k(k−1)/2).
Multivector reverse(const Multivector& a);

// Grade involution Â: grade k scaled by (−1)^k.
Multivector involution(const Multivector& a);

// Clifford conjugate (reverse of the involution): grade k scaled by (−1)^(k(k+1)/2).
Multivector conjugate(const Multivector& a);

}  // namespace pgamesh::clifford
