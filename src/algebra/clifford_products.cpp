// Products of the general engine. Every bilinear product is one kernel over pairs of terms with a
// filter on the pair of blades; metric products run in the orthogonal basis (algebra.hpp).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/products.hpp"

namespace pgamesh::clifford {

namespace {

// Sums products into blades. Up to 2^16 blades a dense scratch array indexed by mask is used (only
// touched entries are visited afterwards); beyond that, terms are collected and merged by sorting.
class Accumulator {
 public:
  explicit Accumulator(int n) : dense_(n <= 16) {
    if (!dense_) return;
    const std::size_t size = std::size_t{1} << n;
    Scratch& s = scratch();
    if (s.buffer.size() < size) {
      s.buffer.assign(size, 0.0);
      s.seen.assign(size, 0);
    }
    s.touched.clear();
    buffer_ = s.buffer.data();
    seen_ = s.seen.data();
    touched_ = &s.touched;
  }
  void add(BladeMask m, double c) {
    if (!dense_) {
      list_.push_back({m, c});
      return;
    }
    if (!seen_[m]) {
      seen_[m] = 1;
      touched_->push_back(m);
    }
    buffer_[m] += c;
  }
  Multivector take() {
    if (!dense_) return from_terms(std::move(list_));
    auto& t = *touched_;
    std::sort(t.begin(), t.end());
    Multivector out;
    out.terms.reserve(t.size());
    for (BladeMask m : t) {
      if (buffer_[m] != 0) out.terms.push_back({m, buffer_[m]});
      buffer_[m] = 0;
      seen_[m] = 0;
    }
    t.clear();
    return out;
  }

 private:
  // Per-thread scratch, so products allocate only their result.
  struct Scratch {
    std::vector<double> buffer;
    std::vector<unsigned char> seen;
    std::vector<BladeMask> touched;
  };
  static Scratch& scratch() {
    thread_local Scratch s;
    return s;
  }
  bool dense_;
  double* buffer_ = nullptr;
  unsigned char* seen_ = nullptr;
  std::vector<BladeMask>* touched_ = nullptr;
  std::vector<Term> list_;
};

// Σ over term pairs (a, b) with keep(a, b) of factor(a, b) · c_a c_b e_(a^b).
template <class Keep, class Factor>
Multivector bilinear(int n, const Multivector& x, const Multivector& y, Keep keep, Factor factor) {
  if (x.terms.empty() || y.terms.empty()) return {};
  Accumulator acc(n);
  for (const Term& a : x.terms)
    for (const Term& b : y.terms) {
      if (!keep(a.mask, b.mask)) continue;
      const double f = factor(a.mask, b.mask);
      if (f != 0) acc.add(a.mask ^ b.mask, f * a.coeff * b.coeff);
    }
  return acc.take();
}

// A metric product: the kernel in the orthogonal basis, mapped back to the user's basis.
template <class Keep>
Multivector metric_product(const Algebra& alg, const Multivector& x, const Multivector& y,
                           Keep keep) {
  auto factor = [&alg](BladeMask a, BladeMask b) { return alg.product_factor(a, b); };
  if (alg.is_diagonal()) return bilinear(alg.dimension(), x, y, keep, factor);
  return alg.from_orthogonal(
      bilinear(alg.dimension(), alg.to_orthogonal(x), alg.to_orthogonal(y), keep, factor));
}

constexpr auto keep_all = [](BladeMask, BladeMask) { return true; };
constexpr auto keep_left_in_right = [](BladeMask a, BladeMask b) { return (a & ~b) == 0; };
constexpr auto keep_right_in_left = [](BladeMask a, BladeMask b) { return (b & ~a) == 0; };

// Applies a metric-free per-blade map e_J ↦ sign(J) e_(~J).
template <class Sign>
Multivector complement(const Algebra& alg, const Multivector& a, Sign sign) {
  std::vector<Term> out;
  out.reserve(a.terms.size());
  const BladeMask all = alg.pseudoscalar_mask();
  for (const Term& t : a.terms) out.push_back({all & ~t.mask, sign(t.mask) * t.coeff});
  return from_terms(std::move(out));
}

// True when every coefficient of a outside the grades in `allowed` is negligible against `scale`.
bool only_grades(const Multivector& a, unsigned allowed, double scale) {
  for (const Term& t : a.terms)
    if (!(allowed >> grade_of(t.mask) & 1) && std::abs(t.coeff) > 1e-12 * scale) return false;
  return true;
}

bool is_pga3(const Algebra& alg) {
  if (alg.dimension() != 4) return false;
  const auto& s = alg.orthogonal_squares();
  return alg.is_diagonal() && s[0] == 0 && s[1] == 1 && s[2] == 1 && s[3] == 1;
}

}  // namespace

Multivector geometric(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return metric_product(alg, a, b, keep_all);
}

Multivector outer(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return bilinear(
      alg.dimension(), a, b, [](BladeMask x, BladeMask y) { return (x & y) == 0; }, reorder_sign);
}

Multivector left_contraction(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return metric_product(alg, a, b, keep_left_in_right);
}

Multivector right_contraction(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return metric_product(alg, a, b, keep_right_in_left);
}

double scalar_product(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return scalar_part(metric_product(alg, a, b, [](BladeMask x, BladeMask y) { return x == y; }));
}

Multivector inner(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return metric_product(alg, a, b,
                        [](BladeMask x, BladeMask y) { return (x & ~y) == 0 || (y & ~x) == 0; });
}

Multivector commutator(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return 0.5 * (geometric(alg, a, b) - geometric(alg, b, a));
}

Multivector dual(const Algebra& alg, const Multivector& a) {
  const int n = alg.dimension();
  return complement(alg, a, [n](BladeMask m) { return dual_sign(m, n); });
}

Multivector undual(const Algebra& alg, const Multivector& a) {
  const int n = alg.dimension();
  return complement(alg, a, [n](BladeMask m) { return undual_sign(m, n); });
}

Multivector regressive(const Algebra& alg, const Multivector& a, const Multivector& b) {
  return undual(alg, outer(alg, dual(alg, a), dual(alg, b)));
}

Multivector pseudoscalar(const Algebra& alg) {
  return basis_blade(alg.pseudoscalar_mask());
}

Multivector metric_dual(const Algebra& alg, const Multivector& a) {
  return geometric(alg, a, inverse(alg, pseudoscalar(alg)));
}

double norm_squared(const Algebra& alg, const Multivector& a) {
  return scalar_product(alg, a, reverse(a));
}

double norm(const Algebra& alg, const Multivector& a) {
  return std::sqrt(std::abs(norm_squared(alg, a)));
}

Multivector inverse(const Algebra& alg, const Multivector& a) {
  const Multivector r = reverse(a);
  const Multivector aa = geometric(alg, a, r);
  const double s = scalar_part(aa);
  const double scale = std::max(max_abs_coeff(aa), 1e-300);
  if (s == 0 || !only_grades(aa, 1u, scale))
    throw std::domain_error("inverse: A ~A is not a non-zero scalar (not a versor)");
  return r / s;
}

Multivector sandwich(const Algebra& alg, const Multivector& v, const Multivector& x) {
  return geometric(alg, geometric(alg, v, x), reverse(v));
}

Multivector exp(const Algebra& alg, const Multivector& a) {
  const double s0 = scalar_part(a);
  const Multivector b = a - scalar(s0);  // the scalar part commutes: exp(s + B) = e^s exp(B)
  const double es = std::exp(s0);
  if (b.is_zero()) return scalar(es);
  const Multivector b2 = geometric(alg, b, b);
  for (const Term& t : b2.terms)
    if (!std::isfinite(t.coeff)) throw std::domain_error("exp: the argument is not finite");
  const double scale = std::max(max_abs_coeff(b2), 1e-300);
  if (only_grades(b2, 1u, scale)) {
    const SimpleExp e = simple_exp(scalar_part(b2));
    return es * (scalar(e.c0) + e.cB * b);
  }
  const BladeMask i_mask = alg.pseudoscalar_mask();
  if (is_pga3(alg) && only_grades(b, 1u << 2, max_abs_coeff(b)) &&
      only_grades(b2, 1u | (1u << 4), scale)) {
    const StudyExp e = study_exp(scalar_part(b2), b2[i_mask]);
    const Multivector ib = geometric(alg, pseudoscalar(alg), b);
    return es * (scalar(e.c0) + basis_blade(i_mask, e.cI) + e.cL * b + e.cIL * ib);
  }
  // Scaling and squaring: exp(B) = exp(B / 2^k)^(2^k) with |B / 2^k| ≤ ½, Taylor to round-off.
  int k = 0;
  double size = 0;
  for (const Term& t : b.terms) size += std::abs(t.coeff);
  if (!std::isfinite(size)) throw std::domain_error("exp: the argument is not finite");
  while (size > 0.5) {
    size /= 2;
    ++k;
  }
  const Multivector small = b / std::ldexp(1.0, k);
  Multivector sum = scalar(1.0), term = scalar(1.0);
  for (int i = 1; i <= 30; ++i) {
    term = geometric(alg, term, small) / i;
    sum = sum + term;
    if (max_abs_coeff(term) <= 1e-17 * max_abs_coeff(sum)) break;
  }
  for (int i = 0; i < k; ++i) sum = geometric(alg, sum, sum);
  return es * sum;
}

Multivector log(const Algebra& alg, const Multivector& a) {
  const double scale = std::max(max_abs_coeff(a), 1e-300);
  const double s = scalar_part(a);
  const Multivector b = grade(a, 2);
  if (only_grades(a, 1u | (1u << 2), scale)) {
    const Multivector b2 = geometric(alg, b, b);
    if (only_grades(b2, 1u, std::max(max_abs_coeff(b2), 1e-300)))
      return simple_log(s, scalar_part(b2)) * b;
  }
  if (is_pga3(alg) && only_grades(a, 1u | (1u << 2) | (1u << 4), scale)) {
    double e2 = 0;  // Euclidean (e0-free) part of the bivector: sin ψ of the motor
    for (const Term& t : b.terms)
      if (!(t.mask & 1u)) e2 += t.coeff * t.coeff;
    const StudyLog l = study_log(s, std::sqrt(e2), a[alg.pseudoscalar_mask()]);
    return l.cL * b + l.cIL * geometric(alg, pseudoscalar(alg), b);
  }
  throw std::domain_error(
      "log: defined here for rotors and motors s + B with B^2 a scalar, and for R(3,0,1) motors");
}

Multivector sqrt(const Algebra& alg, const Multivector& a) {
  return exp(alg, 0.5 * log(alg, a));
}

}  // namespace pgamesh::clifford
