// Graded multivectors: storage for exactly the blades of a compile-time set of grades, and the
// per-blade operations (sums, scaling, reverse, involution, conjugate, grade projection, duals).
// The products are in graded/products.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "pgamesh/algebra/graded/algebra.hpp"

namespace pgamesh::graded {

// A multivector of algebra A with the grades in G: one coefficient per blade of those grades,
// in ascending mask order (blade_list), nothing else. Zero-initialised.
template <class A, GradeMask G>
struct Multivector {
  static_assert((G & ~A::all_grades) == 0, "graded::Multivector: grade above the dimension");
  using algebra = A;
  static constexpr GradeMask grades = G;
  static constexpr const auto& blades = blade_list<A::n, G>;
  static constexpr std::size_t size = blade_list<A::n, G>.size();

  std::array<double, size> c{};

  // Storage position of blade `mask` (−1 when its grade is not stored).
  static constexpr int index_of(BladeMask mask) {
    return mask > A::full_mask ? -1 : blade_position<A::n, G>[mask];
  }
  // Coefficient of blade `mask` (0 when its grade is not stored).
  constexpr double operator[](BladeMask mask) const {
    const int i = index_of(mask);
    return i < 0 ? 0.0 : c[static_cast<std::size_t>(i)];
  }
};

// The common shapes, by grade set.
template <class A>
using Scalar = Multivector<A, 1u>;
template <class A>
using Vector = Multivector<A, 2u>;
template <class A>
using Bivector = Multivector<A, 4u>;
template <class A, int K>
using KVector = Multivector<A, GradeMask{1} << K>;
template <class A>
using Even = Multivector<A, A::even_grades>;
template <class A>
using Odd = Multivector<A, A::odd_grades>;
template <class A>
using Full = Multivector<A, A::all_grades>;

// Calls f(std::integral_constant<std::size_t, I>{}) for I = 0 … N−1, unrolled.
template <std::size_t N, class F>
constexpr void for_each_index(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::integral_constant<std::size_t, I>{}), ...);
  }
  (std::make_index_sequence<N>{});
}

// c · e_Mask, stored as a multivector of that blade's grade.
template <class A, BladeMask Mask>
constexpr KVector<A, clifford::grade_of(Mask)> basis(double c = 1.0) {
  KVector<A, clifford::grade_of(Mask)> out;
  out.c[static_cast<std::size_t>(out.index_of(Mask))] = c;
  return out;
}

// The coefficients of x on the grades in G2 (blades of x outside G2 dropped, new ones zero):
// grade projection when G2 ⊂ G, widening when G ⊂ G2.
template <GradeMask G2, class A, GradeMask G>
constexpr Multivector<A, G2> project(const Multivector<A, G>& x) {
  Multivector<A, G2> out;
  for_each_index<Multivector<A, G>::size>([&](auto i) {
    constexpr int j = Multivector<A, G2>::index_of(Multivector<A, G>::blades[i]);
    if constexpr (j >= 0) out.c[j] = x.c[i];
  });
  return out;
}

// Grade projection ⟨X⟩_k.
template <int K, class A, GradeMask G>
constexpr KVector<A, K> grade(const Multivector<A, G>& x) {
  return project<GradeMask{1} << K>(x);
}

// The scalar part ⟨X⟩_0.
template <class A, GradeMask G>
constexpr double scalar_part(const Multivector<A, G>& x) {
  if constexpr (G & 1u) return x.c[0];
  return 0.0;
}

template <class A, GradeMask GA, GradeMask GB>
constexpr Multivector<A, GA | GB> operator+(const Multivector<A, GA>& a,
                                            const Multivector<A, GB>& b) {
  Multivector<A, GA | GB> out = project<GA | GB>(a);
  for_each_index<Multivector<A, GB>::size>([&](auto i) {
    constexpr int j = Multivector<A, GA | GB>::index_of(Multivector<A, GB>::blades[i]);
    out.c[j] += b.c[i];
  });
  return out;
}

template <class A, GradeMask G>
constexpr Multivector<A, G> operator-(const Multivector<A, G>& a) {
  Multivector<A, G> out;
  for (std::size_t i = 0; i < a.size; ++i) out.c[i] = -a.c[i];
  return out;
}

template <class A, GradeMask GA, GradeMask GB>
constexpr Multivector<A, GA | GB> operator-(const Multivector<A, GA>& a,
                                            const Multivector<A, GB>& b) {
  return a + (-b);
}

template <class A, GradeMask G>
constexpr Multivector<A, G> operator*(double s, const Multivector<A, G>& a) {
  Multivector<A, G> out;
  for (std::size_t i = 0; i < a.size; ++i) out.c[i] = s * a.c[i];
  return out;
}

template <class A, GradeMask G>
constexpr Multivector<A, G> operator*(const Multivector<A, G>& a, double s) {
  return s * a;
}

template <class A, GradeMask G>
constexpr Multivector<A, G> operator/(const Multivector<A, G>& a, double s) {
  Multivector<A, G> out;
  for (std::size_t i = 0; i < a.size; ++i) out.c[i] = a.c[i] / s;
  return out;
}

// Scales each blade by sign_of_grade(grade of the blade) (a compile-time ±1 per blade).
template <auto SignOfGrade, class A, GradeMask G>
constexpr Multivector<A, G> scale_by_grade(const Multivector<A, G>& x) {
  Multivector<A, G> out;
  for_each_index<Multivector<A, G>::size>([&](auto i) {
    constexpr double s = SignOfGrade(clifford::grade_of(Multivector<A, G>::blades[i]));
    if constexpr (s > 0)
      out.c[i] = x.c[i];
    else
      out.c[i] = -x.c[i];
  });
  return out;
}

// Reverse X̃: grade k scaled by (−1)^(k(k−1)/2).
template <class A, GradeMask G>
constexpr Multivector<A, G> reverse(const Multivector<A, G>& x) {
  return scale_by_grade<clifford::reverse_sign>(x);
}

template <class A, GradeMask G>
constexpr Multivector<A, G> operator~(const Multivector<A, G>& x) {
  return reverse(x);
}

// Grade involution X̂: grade k scaled by (−1)^k.
template <class A, GradeMask G>
constexpr Multivector<A, G> involution(const Multivector<A, G>& x) {
  return scale_by_grade<clifford::involution_sign>(x);
}

// Clifford conjugate: grade k scaled by (−1)^(k(k+1)/2).
template <class A, GradeMask G>
constexpr Multivector<A, G> conjugate(const Multivector<A, G>& x) {
  return scale_by_grade<clifford::conjugate_sign>(x);
}

// e_J ↦ sign(J, n) e_(~J) for every stored blade J: the Hodge dual and undual.
template <auto Sign, class A, GradeMask G>
constexpr Multivector<A, complement_grades<A::n>(G)> complement(const Multivector<A, G>& x) {
  using Out = Multivector<A, complement_grades<A::n>(G)>;
  Out out;
  for_each_index<Multivector<A, G>::size>([&](auto i) {
    constexpr BladeMask m = Multivector<A, G>::blades[i];
    constexpr int j = Out::index_of(A::full_mask & ~m);
    constexpr double s = Sign(m, A::n);
    if constexpr (s > 0)
      out.c[j] = x.c[i];
    else
      out.c[j] = -x.c[i];
  });
  return out;
}

// Hodge (complement) dual: e_J e_J* = I (docs/conventions.md §3; metric-free, valid in degenerate
// algebras).
template <class A, GradeMask G>
constexpr auto dual(const Multivector<A, G>& x) {
  return complement<clifford::dual_sign>(x);
}

// Undual X^(−*), with X^(−*) ∧ X = I, so undual(dual(X)) = X.
template <class A, GradeMask G>
constexpr auto undual(const Multivector<A, G>& x) {
  return complement<clifford::undual_sign>(x);
}

}  // namespace pgamesh::graded
