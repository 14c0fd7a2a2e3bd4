// Products of the general engine. Every bilinear product is one kernel over pairs of terms with a
// filter on the pair of blades; metric products run in the orthogonal basis (algebra.hpp).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "pgamesh/algebra/clifford/closed_forms.hpp"
#include "pgamesh/algebra/clifford/products.hpp"
#include "pgamesh/algebra/pgad.hpp"

namespace pgamesh::clifford {

namespace {

constexpr std::size_t small_size = std::size_t{1} << Algebra::small_generators;
constexpr int dense_generators = 16;

// Non-zero terms of at most 2^small_generators blades, on the stack.
struct SmallTerms {
  std::array<Term, small_size> t;
  std::size_t size = 0;
  std::span<const Term> span() const { return {t.data(), size}; }
};

// n ≤ small_generators: the 2^n coefficients on the stack and the touched blades as one 64-bit
// set, read back in ascending mask order without sorting.
struct SmallAccumulator {
  std::array<double, small_size> c;
  std::uint64_t touched = 0;
  explicit SmallAccumulator(int n) { std::fill_n(c.data(), std::size_t{1} << n, 0.0); }
  void add(BladeMask m, double v) {
    c[m] += v;
    touched |= std::uint64_t{1} << m;
  }
  SmallTerms terms() const {
    SmallTerms out;
    for (std::uint64_t rest = touched; rest != 0; rest &= rest - 1) {
      const auto m = static_cast<BladeMask>(std::countr_zero(rest));
      if (c[m] != 0) out.t[out.size++] = {m, c[m]};
    }
    return out;
  }
  Multivector take() const {
    const SmallTerms t = terms();
    Multivector out;
    out.terms.assign(t.t.begin(), t.t.begin() + static_cast<std::ptrdiff_t>(t.size));
    return out;
  }
};

// n ≤ dense_generators: a per-thread scratch array of 2^n coefficients and a bitset of the
// touched blades (read back in ascending order word by word); both are cleared on the way out,
// so products allocate only their result.
class DenseAccumulator {
 public:
  explicit DenseAccumulator(int n) {
    const std::size_t size = std::size_t{1} << n;
    Scratch& s = scratch();
    if (s.buffer.size() < size) {
      s.buffer.assign(size, 0.0);
      s.bits.assign((size + 63) / 64, 0);
    }
    buffer_ = s.buffer.data();
    bits_ = s.bits.data();
    words_ = (size + 63) / 64;
  }
  DenseAccumulator(const DenseAccumulator&) = delete;
  DenseAccumulator& operator=(const DenseAccumulator&) = delete;
  ~DenseAccumulator() { clear(); }
  void add(BladeMask m, double v) {
    buffer_[m] += v;
    bits_[m >> 6] |= std::uint64_t{1} << (m & 63);
  }
  Multivector take() {
    std::size_t count = 0;
    for (std::size_t w = 0; w < words_; ++w)
      for (std::uint64_t rest = bits_[w]; rest != 0; rest &= rest - 1) ++count;
    Multivector out;
    out.terms.reserve(count);
    for (std::size_t w = 0; w < words_; ++w)
      for (std::uint64_t rest = bits_[w]; rest != 0; rest &= rest - 1) {
        const auto m =
            static_cast<BladeMask>(w * 64 + static_cast<std::size_t>(std::countr_zero(rest)));
        if (buffer_[m] != 0) out.terms.push_back({m, buffer_[m]});
      }
    clear();
    return out;
  }

 private:
  void clear() {
    for (std::size_t w = 0; w < words_; ++w) {
      for (std::uint64_t rest = bits_[w]; rest != 0; rest &= rest - 1)
        buffer_[w * 64 + static_cast<std::size_t>(std::countr_zero(rest))] = 0;
      bits_[w] = 0;
    }
  }
  struct Scratch {
    std::vector<double> buffer;
    std::vector<std::uint64_t> bits;
  };
  static Scratch& scratch() {
    thread_local Scratch s;
    return s;
  }
  double* buffer_ = nullptr;
  std::uint64_t* bits_ = nullptr;
  std::size_t words_ = 0;
};

// More generators: terms are collected and merged by sorting.
struct ListAccumulator {
  std::vector<Term> list;
  void add(BladeMask m, double v) { list.push_back({m, v}); }
  Multivector take() { return from_terms(std::move(list)); }
};

// Runs fill(accumulator) with the accumulator that suits n generators and returns the sum.
template <class Fill>
Multivector accumulate_with(int n, Fill fill) {
  if (n <= Algebra::small_generators) {
    SmallAccumulator acc(n);
    fill(acc);
    return acc.take();
  }
  if (n <= dense_generators) {
    DenseAccumulator acc(n);
    fill(acc);
    return acc.take();
  }
  ListAccumulator acc;
  fill(acc);
  return acc.take();
}

// Adds Σ over term pairs (a, b) with keep(a, b) of factor(a, b) · c_a c_b e_(a^b) to acc.
template <class Acc, class Keep, class Factor>
void accumulate_pairs(Acc& acc, std::span<const Term> x, std::span<const Term> y, Keep keep,
                      Factor factor) {
  for (const Term& a : x) {
    const BladeMask am = a.mask;
    const double ac = a.coeff;
    for (const Term& b : y) {
      if (!keep(am, b.mask)) continue;
      const double f = factor(am, b.mask);
      if (f != 0) acc.add(am ^ b.mask, f * ac * b.coeff);
    }
  }
}

template <class Keep, class Factor>
Multivector bilinear(int n, const Multivector& x, const Multivector& y, Keep keep, Factor factor) {
  if (x.terms.empty() || y.terms.empty()) return {};
  return accumulate_with(n,
                         [&](auto& acc) { accumulate_pairs(acc, x.terms, y.terms, keep, factor); });
}

// Σ c_t · image(t.mask) for a small algebra: a change of basis through the cached blade images.
template <class Image>
SmallAccumulator change_basis_small(int n, std::span<const Term> x, Image image) {
  SmallAccumulator acc(n);
  for (const Term& t : x)
    for (const Term& e : image(t.mask)) acc.add(e.mask, t.coeff * e.coeff);
  return acc;
}

// A metric product: the kernel in the orthogonal basis, mapped back to the user's basis.
template <class Keep>
Multivector metric_product(const Algebra& alg, const Multivector& x, const Multivector& y,
                           Keep keep) {
  if (alg.dimension() <= Algebra::small_generators) {
    const double* table = alg.product_table().data();
    const int n = alg.dimension();
    auto factor = [table, n](BladeMask a, BladeMask b) { return table[(a << n) | b]; };
    if (alg.is_diagonal()) return bilinear(n, x, y, keep, factor);
    auto to = [&alg](BladeMask m) { return alg.orthogonal_image(m); };
    auto from = [&alg](BladeMask m) { return alg.user_image(m); };
    const SmallTerms xo = change_basis_small(n, x.terms, to).terms();
    const SmallTerms yo = change_basis_small(n, y.terms, to).terms();
    SmallAccumulator product(n);
    accumulate_pairs(product, xo.span(), yo.span(), keep, factor);
    return change_basis_small(n, product.terms().span(), from).take();
  }
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

// d when the algebra is PGA R(d,0,1) with e0 first (Algebra::signature(d,0,1), the pgaN
// presets): then its blade masks are those of pgad::Multivector<d>. 0 otherwise.
int pga_dimension(const Algebra& alg) {
  if (!alg.is_diagonal()) return 0;
  const auto& s = alg.orthogonal_squares();
  if (s[0] != 0) return 0;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k] != 1) return 0;
  return alg.dimension() - 1;
}

// f applied to A through pgad::Multivector<D> (same blade masks, see pga_dimension).
template <int D, class F>
Multivector through_pgad(const Multivector& a, F f) {
  pgad::Multivector<D> p{};
  for (const Term& t : a.terms) p.c[t.mask] = t.coeff;
  const pgad::Multivector<D> r = f(p);
  Multivector out;
  for (BladeMask m = 0; m < r.size; ++m)
    if (r.c[m] != 0) out.terms.push_back({m, r.c[m]});
  return out;
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
  if (a.terms.empty() || b.terms.empty()) return {};
  if (grades_present(b) == (1u << 1)) {
    // A ∧ v for a vector v: visit only the generators j ∉ a (the pairs that survive), with the
    // sign (−1)^(factors of a above j) of e_a e_j — the same terms in the same order as below.
    std::array<double, Algebra::max_generators> v{};
    BladeMask present = 0;
    for (const Term& t : b.terms) {
      v[static_cast<std::size_t>(std::countr_zero(t.mask))] = t.coeff;
      present |= t.mask;
    }
    return accumulate_with(alg.dimension(), [&](auto& acc) {
      for (const Term& x : a.terms) {
        const BladeMask above = parity_above(x.mask);
        for (BladeMask rest = present & ~x.mask; rest != 0; rest &= rest - 1) {
          const BladeMask bit = rest & (~rest + 1);
          const double sign = (above & bit) ? -1.0 : 1.0;
          acc.add(x.mask | bit,
                  sign * x.coeff * v[static_cast<std::size_t>(std::countr_zero(bit))]);
        }
      }
    });
  }
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
  if (alg.dimension() > Algebra::small_generators || v.terms.empty() || x.terms.empty())
    return geometric(alg, geometric(alg, v, x), reverse(v));
  // Small algebras: both products on stack arrays in the orthogonal basis, with no intermediate
  // multivector and one change of basis each way.
  const double* table = alg.product_table().data();
  const int n = alg.dimension();
  auto factor = [table, n](BladeMask a, BladeMask b) { return table[(a << n) | b]; };
  auto to = [&alg](BladeMask m) { return alg.orthogonal_image(m); };
  auto copy = [](std::span<const Term> t) {
    SmallTerms out;
    for (const Term& e : t) out.t[out.size++] = e;
    return out;
  };
  const SmallTerms vo =
      alg.is_diagonal() ? copy(v.terms) : change_basis_small(n, v.terms, to).terms();
  const SmallTerms xo =
      alg.is_diagonal() ? copy(x.terms) : change_basis_small(n, x.terms, to).terms();
  SmallTerms vr = vo;  // reverse Ṽ, grade by grade (the change of basis keeps grades)
  for (std::size_t i = 0; i < vr.size; ++i) vr.t[i].coeff *= reverse_sign(grade_of(vr.t[i].mask));
  SmallAccumulator vx(n), vxv(n);
  accumulate_pairs(vx, vo.span(), xo.span(), keep_all, factor);
  accumulate_pairs(vxv, vx.terms().span(), vr.span(), keep_all, factor);
  if (alg.is_diagonal()) return vxv.take();
  return change_basis_small(n, vxv.terms().span(),
                            [&alg](BladeMask m) { return alg.user_image(m); })
      .take();
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
  // R(d,0,1), 4 ≤ d ≤ 7: pgad's closed form in the angle sums (commuting rotations, isoclinic or
  // not, and a translation).
  if (only_grades(b, 1u << 2, max_abs_coeff(b))) {
    auto pgad_exp = [](const auto& x) { return pgad::exp(x); };
    switch (pga_dimension(alg)) {
      case 4:
        return es * through_pgad<4>(b, pgad_exp);
      case 5:
        return es * through_pgad<5>(b, pgad_exp);
      case 6:
        return es * through_pgad<6>(b, pgad_exp);
      case 7:
        return es * through_pgad<7>(b, pgad_exp);
      default:
        break;
    }
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
  if (only_grades(a, 0b101010101u, scale)) {  // R(d,0,1), 4 ≤ d ≤ 7: pgad::log
    auto pgad_log = [](const auto& x) { return pgad::log(x); };
    switch (pga_dimension(alg)) {
      case 4:
        return through_pgad<4>(a, pgad_log);
      case 5:
        return through_pgad<5>(a, pgad_log);
      case 6:
        return through_pgad<6>(a, pgad_log);
      case 7:
        return through_pgad<7>(a, pgad_log);
      default:
        break;
    }
  }
  throw std::domain_error(
      "log: defined here for rotors and motors s + B with B^2 a scalar, for R(3,0,1) motors and "
      "for R(d,0,1) motors with 4 <= d <= 7");
}

Multivector sqrt(const Algebra& alg, const Multivector& a) {
  return exp(alg, 0.5 * log(alg, a));
}

}  // namespace pgamesh::clifford
