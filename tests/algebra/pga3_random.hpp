// Random PGA3 elements and tolerant comparison for the typed tests (float, double and, when GMP
// is available, exact rationals mpq_class where comparisons are exact).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "pgamesh/algebra/pga3.hpp"

#ifdef PGAMESH_HAVE_GMP
#include <gmpxx.h>
#endif

namespace pgamesh::test {

template <class T>
struct Num {
  static T random(std::mt19937& rng) { return std::uniform_real_distribution<T>(-1, 1)(rng); }
  static double to_double(const T& x) { return double(x); }
  /// Allowed error for values of size `scale` after a few dozen operations.
  static double tolerance(double scale) {
    return 64 * double(std::numeric_limits<T>::epsilon()) * std::max(1.0, scale);
  }
};
#ifdef PGAMESH_HAVE_GMP
template <>
struct Num<mpq_class> {
  static mpq_class random(std::mt19937& rng) {
    mpq_class q(int(rng() % 2001) - 1000, 1 + int(rng() % 97));
    q.canonicalize();
    return q;
  }
  static double to_double(const mpq_class& x) { return x.get_d(); }
  static double tolerance(double) { return 0; }
};
#endif

template <class T>
bool near(const T& got, const T& want, double scale) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::abs(double(got) - double(want)) <= Num<T>::tolerance(scale);
  } else {
    return got == want;
  }
}

/// Compares all 16 coefficients; the tolerance scales with the largest expected coefficient.
template <class T>
::testing::AssertionResult mv_near(const pga3::Multivector<T>& got,
                                   const pga3::Multivector<T>& want, double extra_scale = 1) {
  double scale = extra_scale;
  for (const T& x : want.c) scale = std::max(scale, std::abs(Num<T>::to_double(x)));
  for (int i = 0; i < 16; ++i)
    if (!near(got.c[i], want.c[i], scale))
      return ::testing::AssertionFailure()
             << pga3::kBladeNames[i] << ": got " << Num<T>::to_double(got.c[i]) << ", want "
             << Num<T>::to_double(want.c[i]);
  return ::testing::AssertionSuccess();
}

template <class T>
pga3::Plane<T> random_plane(std::mt19937& r) {
  return {Num<T>::random(r), Num<T>::random(r), Num<T>::random(r), Num<T>::random(r)};
}
template <class T>
pga3::Line<T> random_line(std::mt19937& r) {
  return {Num<T>::random(r), Num<T>::random(r), Num<T>::random(r),
          Num<T>::random(r), Num<T>::random(r), Num<T>::random(r)};
}
template <class T>
pga3::Point<T> random_point(std::mt19937& r) {
  pga3::Point<T> p;
  for (T* x : {&p.e021, &p.e013, &p.e032, &p.e123}) *x = Num<T>::random(r);  // basis order
  return p;
}
template <class T>
pga3::Motor<T> random_motor(std::mt19937& r) {
  pga3::Motor<T> m;
  for (T* x : {&m.s, &m.e01, &m.e02, &m.e03, &m.e12, &m.e31, &m.e23, &m.e0123})
    *x = Num<T>::random(r);  // in basis order, as the random elements have always been drawn
  return m;
}
template <class T>
pga3::Multivector<T> random_multivector(std::mt19937& r) {
  pga3::Multivector<T> m;
  for (T& x : m.c) x = Num<T>::random(r);
  return m;
}
template <class T>
pga3::Multivector<T> scalar_mv(const T& s) {
  pga3::Multivector<T> m;
  m.c[0] = s;
  return m;
}
template <class T>
pga3::Multivector<T> pseudoscalar_mv(const T& s) {
  pga3::Multivector<T> m;
  m.c[15] = s;
  return m;
}

// Allowed error of the float and double typed tests after a handful of products.
template <class T>
T tol() {
  return std::is_same_v<T, float> ? T(5e-5) : T(1e-12);
}

// A random vector of size about `scale` (the moment of a random line).
template <class T>
Vec3<T> rvec(std::mt19937& r, T scale = T(2)) {
  return scale * random_line<T>(r).moment();
}

}  // namespace pgamesh::test
