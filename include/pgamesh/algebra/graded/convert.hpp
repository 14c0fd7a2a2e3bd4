// Conversions between graded multivectors and the general engine's (clifford::Multivector), and a
// printer that names blades as the engine does. Both use the same blade masks (graded/algebra.hpp).
#pragma once

#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "pgamesh/algebra/clifford/algebra.hpp"
#include "pgamesh/algebra/graded/multivector.hpp"

namespace pgamesh::graded {

// The general engine's algebra with the same signature, generator order and names.
template <class A>
clifford::Algebra runtime_algebra() {
  return clifford::Algebra::signature(A::p, A::q, A::r);
}

// X as a general-engine multivector (zero coefficients dropped).
template <class A, GradeMask G>
clifford::Multivector to_clifford(const Multivector<A, G>& x) {
  clifford::Multivector out;
  for (std::size_t i = 0; i < x.size; ++i)
    if (x.c[i] != 0) out.terms.push_back({x.blades[i], x.c[i]});
  return out;  // blades ascend in both storages
}

// A general-engine multivector as M = Multivector<A, G>. Throws std::invalid_argument when it
// has a non-zero coefficient on a blade that M does not store (a grade outside G or a blade
// beyond A's generators): dropping it silently would change the value.
template <class M>
M from_clifford(const clifford::Multivector& x) {
  M out;
  for (const clifford::Term& t : x.terms) {
    const int i = M::index_of(t.mask);
    if (i < 0) {
      if (t.coeff == 0) continue;
      throw std::invalid_argument("graded::from_clifford: blade mask " + std::to_string(t.mask) +
                                  " is not stored in the target grade set");
    }
    out.c[static_cast<std::size_t>(i)] = t.coeff;
  }
  return out;
}

// "0.5 + 2 e12 - 1 e0123": non-zero coefficients with the engine's blade names (printing order
// of clifford::Algebra::signature), "0" for zero.
template <class A, GradeMask G>
std::string to_string(const Multivector<A, G>& x) {
  const clifford::Algebra alg = runtime_algebra<A>();
  std::ostringstream s;
  s.precision(17);
  bool any = false;
  for (const auto& [name, coeff] : alg.named_coefficients(to_clifford(x))) {
    if (any)
      s << (coeff < 0 ? " - " : " + ");
    else if (coeff < 0)
      s << '-';
    s << std::abs(coeff);
    if (name != "1") s << ' ' << name;
    any = true;
  }
  if (!any) s << '0';
  return s.str();
}

template <class A, GradeMask G>
std::ostream& operator<<(std::ostream& os, const Multivector<A, G>& x) {
  return os << to_string(x);
}

}  // namespace pgamesh::graded
