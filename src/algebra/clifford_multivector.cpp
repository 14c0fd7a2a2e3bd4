// Sparse multivector storage and the metric-free linear operations (sums, grades, involutions).
#include <algorithm>
#include <cmath>

#include "pgamesh/algebra/clifford/multivector.hpp"

namespace pgamesh::clifford {

double Multivector::operator[](BladeMask mask) const {
  const auto it = std::lower_bound(terms.begin(), terms.end(), mask,
                                   [](const Term& t, BladeMask m) { return t.mask < m; });
  return (it != terms.end() && it->mask == mask) ? it->coeff : 0.0;
}

Multivector scalar(double s) {
  return basis_blade(0, s);
}

Multivector basis_blade(BladeMask mask, double c) {
  Multivector m;
  if (c != 0) m.terms.push_back({mask, c});
  return m;
}

Multivector from_terms(std::vector<Term> terms) {
  std::stable_sort(terms.begin(), terms.end(),
                   [](const Term& a, const Term& b) { return a.mask < b.mask; });
  Multivector out;
  for (const Term& t : terms) {
    if (!out.terms.empty() && out.terms.back().mask == t.mask)
      out.terms.back().coeff += t.coeff;
    else
      out.terms.push_back(t);
  }
  std::erase_if(out.terms, [](const Term& t) { return t.coeff == 0; });
  return out;
}

namespace {
// Merge of two sorted term lists with coefficients a + sb·b.
Multivector merge(const Multivector& a, const Multivector& b, double sb) {
  Multivector out;
  out.terms.reserve(a.terms.size() + b.terms.size());
  auto i = a.terms.begin(), j = b.terms.begin();
  while (i != a.terms.end() || j != b.terms.end()) {
    if (j == b.terms.end() || (i != a.terms.end() && i->mask < j->mask)) {
      out.terms.push_back(*i++);
    } else if (i == a.terms.end() || j->mask < i->mask) {
      out.terms.push_back({j->mask, sb * j->coeff});
      ++j;
    } else {
      const double c = i->coeff + sb * j->coeff;
      if (c != 0) out.terms.push_back({i->mask, c});
      ++i;
      ++j;
    }
  }
  return out;
}

// Scales grade k by sign(k).
template <class SignOfGrade>
Multivector scale_grades(const Multivector& a, SignOfGrade sign) {
  Multivector out = a;
  for (Term& t : out.terms) t.coeff *= sign(grade_of(t.mask));
  return out;
}
}  // namespace

Multivector operator+(const Multivector& a, const Multivector& b) {
  return merge(a, b, 1.0);
}
Multivector operator-(const Multivector& a, const Multivector& b) {
  return merge(a, b, -1.0);
}
Multivector operator-(const Multivector& a) {
  return -1.0 * a;
}

Multivector operator*(double s, const Multivector& a) {
  if (s == 0) return {};
  Multivector out = a;
  for (Term& t : out.terms) t.coeff *= s;
  std::erase_if(out.terms, [](const Term& t) { return t.coeff == 0; });  // underflow
  return out;
}
Multivector operator*(const Multivector& a, double s) {
  return s * a;
}
Multivector operator/(const Multivector& a, double s) {
  Multivector out = a;
  for (Term& t : out.terms) t.coeff /= s;
  return out;
}

Multivector grade(const Multivector& a, int k) {
  Multivector out;
  for (const Term& t : a.terms)
    if (grade_of(t.mask) == k) out.terms.push_back(t);
  return out;
}

double scalar_part(const Multivector& a) {
  return a[0];
}

double max_abs_coeff(const Multivector& a) {
  double m = 0;
  for (const Term& t : a.terms) m = std::max(m, std::abs(t.coeff));
  return m;
}

unsigned grades_present(const Multivector& a) {
  unsigned g = 0;
  for (const Term& t : a.terms) g |= 1u << grade_of(t.mask);
  return g;
}

Multivector pruned(const Multivector& a, double eps) {
  Multivector out = a;
  std::erase_if(out.terms, [eps](const Term& t) { return std::abs(t.coeff) <= eps; });
  return out;
}

Multivector reverse(const Multivector& a) {
  return scale_grades(a, reverse_sign);
}
Multivector involution(const Multivector& a) {
  return scale_grades(a, involution_sign);
}
Multivector conjugate(const Multivector& a) {
  return scale_grades(a, conjugate_sign);
}

}  // namespace pgamesh::clifford
