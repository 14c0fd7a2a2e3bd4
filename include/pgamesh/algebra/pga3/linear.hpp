// The linear operations of the algebra (sum, difference, negation, scaling) for every element
// type that lists its coefficients in `members` (grades.hpp): written once, used by Plane, Line,
// Point, Motor. Sums of carriers are how magnitudes of complexes are formed (paper Thm. 4.1:
// "sum first, then take the norm").
#pragma once

#include <tuple>

namespace pgamesh::pga3 {

/// An element type whose coefficients are listed in `members`.
template <class G>
concept Element = requires {
  typename G::scalar_type;
  G::members;
};

namespace detail {
template <class G, class F>
constexpr void for_each_member(F&& f) {
  std::apply([&](auto... m) { (f(m), ...); }, G::members);
}
}  // namespace detail

/// A + B, coefficient-wise.
template <Element G>
constexpr G operator+(G a, const G& b) {
  detail::for_each_member<G>([&](auto m) { a.*m += b.*m; });
  return a;
}
/// A − B, coefficient-wise.
template <Element G>
constexpr G operator-(G a, const G& b) {
  detail::for_each_member<G>([&](auto m) { a.*m -= b.*m; });
  return a;
}
/// −A.
template <Element G>
constexpr G operator-(G a) {
  detail::for_each_member<G>([&](auto m) { a.*m = -(a.*m); });
  return a;
}
/// s A (scalar multiple).
template <Element G>
constexpr G operator*(typename G::scalar_type s, G a) {
  detail::for_each_member<G>([&](auto m) { a.*m *= s; });
  return a;
}
/// A s (scalar multiple).
template <Element G>
constexpr G operator*(G a, typename G::scalar_type s) {
  return s * a;
}
/// A / s.
template <Element G>
constexpr G operator/(G a, typename G::scalar_type s) {
  detail::for_each_member<G>([&](auto m) { a.*m /= s; });
  return a;
}
/// A += B.
template <Element G>
constexpr G& operator+=(G& a, const G& b) {
  return a = a + b;
}
/// A −= B.
template <Element G>
constexpr G& operator-=(G& a, const G& b) {
  return a = a - b;
}
/// Coefficient-wise equality (exact; use a tolerance for computed values).
template <Element G>
constexpr bool operator==(const G& a, const G& b) {
  bool same = true;
  detail::for_each_member<G>([&](auto m) { same = same && a.*m == b.*m; });
  return same;
}

}  // namespace pgamesh::pga3
