// DPGA R(4,4) quadrics on the graded engine (docs/models-quadrics.md §2; Breuils eqs. 31–38,
// 57–59, 72–73).
#include "pgamesh/models/dpga.hpp"

#include <cmath>

#include "pgamesh/algebra/clifford/products.hpp"
#include "quadric_blades.hpp"

namespace pgamesh::dpga {

namespace {

void check_index(int i, int hi, const char* who) {
  if (i < 0 || i > hi) throw ModelError(std::string(who) + ": index out of range");
}

// W^k (eq. 57) in the order of the coefficients a … j.
const std::array<Bivector, 10>& reciprocal_operators() {
  static const std::array<Bivector, 10> ops = [] {
    auto op = [](int s, int t, double c) { return c * (w_star(s) ^ w(t)); };
    return std::array<Bivector, 10>{op(0, 0, 1), op(1, 1, 1), op(2, 2, 1), op(1, 0, 2),
                                    op(2, 0, 2), op(2, 1, 2), op(3, 0, 2), op(3, 1, 2),
                                    op(3, 2, 2), op(3, 3, 1)};
  }();
  return ops;
}

}  // namespace

const clifford::Algebra& algebra() {
  static const clifford::Algebra a = *clifford::make_algebra("dpga");
  return a;
}

Vector w(int i) {
  check_index(i, 3, "dpga::w");
  Vector v;
  v.c[static_cast<std::size_t>(i)] = 0.5;
  v.c[static_cast<std::size_t>(4 + i)] = 0.5;
  return v;
}

Vector w_star(int i) {
  check_index(i, 3, "dpga::w_star");
  Vector v;
  v.c[static_cast<std::size_t>(i)] = 0.5;
  v.c[static_cast<std::size_t>(4 + i)] = -0.5;
  return v;
}

Vector point(const Vec3d& p, double weight) {
  Vector v;
  const double x[4] = {p[0], p[1], p[2], weight};
  for (std::size_t k = 0; k < 4; ++k) {
    v.c[k] = 0.5 * x[k];
    v.c[4 + k] = 0.5 * x[k];
  }
  return v;
}

Vector dual_point(const Vec3d& p, double weight) {
  Vector v;
  const double x[4] = {p[0], p[1], p[2], weight};
  for (std::size_t k = 0; k < 4; ++k) {
    v.c[k] = 0.5 * x[k];
    v.c[4 + k] = -0.5 * x[k];
  }
  return v;
}

Bivector quadric(const Quadric& q) {
  const auto& k = q.k;
  auto diag = [](int s, double c) { return (4 * c) * (w_star(s) ^ w(s)); };
  auto sym = [](int s, int t, double c) {
    return (2 * c) * ((w_star(s) ^ w(t)) + (w_star(t) ^ w(s)));
  };
  return diag(0, k[0]) + diag(1, k[1]) + diag(2, k[2]) + diag(3, k[9]) + sym(0, 1, k[3]) +
         sym(0, 2, k[4]) + sym(1, 2, k[5]) + sym(0, 3, k[6]) + sym(1, 3, k[7]) + sym(2, 3, k[8]);
}

Quadric coefficients(const Bivector& q) {
  Quadric out;
  const auto& ops = reciprocal_operators();
  for (std::size_t n = 0; n < 10; ++n) out.k[n] = graded::scalar_product(ops[n], q);
  return out;
}

double value(const Bivector& q, const Vec3d& p) {
  return graded::scalar_product(graded::left_contraction(point(p), q), dual_point(p));
}

std::array<double, 4> polar_plane(const Bivector& q, const Vec3d& p) {
  // Q ⌊ p* is a vector; its w_k* coefficient is 2 (Q ⌊ p*)·w_k (w_k·w_k* = ½).
  const auto plane = graded::grade<1>(q | dual_point(p));
  std::array<double, 4> out{};
  for (int k = 0; k < 4; ++k)
    out[static_cast<std::size_t>(k)] = 2 * graded::scalar_product(plane, w(k));
  return out;
}

Even rotor(int i, int j, double theta) {
  check_index(i, 2, "dpga::rotor");
  check_index(j, 2, "dpga::rotor");
  if (i == j) throw ModelError("dpga::rotor: needs two different axes");
  const double c = std::cos(theta / 2), s = std::sin(theta / 2);
  graded::Vector<Algebra> fi, fj, gi, gj;
  fi.c[static_cast<std::size_t>(i)] = 1;
  fj.c[static_cast<std::size_t>(j)] = 1;
  gi.c[static_cast<std::size_t>(4 + i)] = 1;
  gj.c[static_cast<std::size_t>(4 + j)] = 1;
  graded::Scalar<Algebra> cs;
  cs.c[0] = c;
  const Even r1 = graded::project<Algebra::even_grades>(cs - s * (fi ^ fj));
  const Even r2 = graded::project<Algebra::even_grades>(cs + s * (gi ^ gj));
  return graded::project<Algebra::even_grades>(r1 * r2);
}

Even shear(int i, int j, double s) {
  check_index(i, 3, "dpga::shear");
  check_index(j, 3, "dpga::shear");
  if (i == j) throw ModelError("dpga::shear: needs two different indices");
  graded::Scalar<Algebra> one;
  one.c[0] = 1;
  return graded::project<Algebra::even_grades>(one + s * (w(i) ^ w_star(j)));
}

Bivector transform(const Even& r, const Bivector& q) {
  return graded::sandwich(r, q);
}

Bivector rotate(const Bivector& q, int i, int j, double theta) {
  return transform(rotor(i, j, theta), q);
}

clifford::Multivector to_null_basis_terms(const clifford::Multivector& x) {
  const clifford::Algebra& a = algebra();
  clifford::Multivector out;
  for (const clifford::Term& t : x.terms) {
    clifford::Multivector acc = clifford::scalar(t.coeff);
    for (int b = 0; b < 8; ++b) {
      if (!(t.mask >> b & 1u)) continue;
      const int i = b % 4;
      const double sign = b < 4 ? 1.0 : -1.0;  // f_i = w_i + w_i*, f_(4+i) = w_i − w_i*
      const clifford::Multivector img =
          clifford::basis_blade(clifford::BladeMask{1} << i) +
          clifford::basis_blade(clifford::BladeMask{1} << (4 + i), sign);
      acc = clifford::outer(a, acc, img);
    }
    out = out + acc;
  }
  return clifford::pruned(out, 1e-15 * clifford::max_abs_coeff(out));
}

std::vector<std::pair<std::string, double>> nonzero_blades_of(const clifford::Multivector& x) {
  return quadric::detail::named_terms(x, generator_names);
}

}  // namespace pgamesh::dpga
