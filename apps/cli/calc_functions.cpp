// The algebra's own functions of `pgamesh calc`: products by name, the Hodge complement and the
// metric dual, exp/log/sqrt/pow on scalars and on (non-unit) rotors and motors, the scalar
// functions, norms. docs/calc.md, Functions.
#include "calc_functions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pgamesh::cli {

using clifford::Multivector;

bool is_scalar(const Multivector& m) {
  return m.terms.empty() || (m.terms.size() == 1 && m.terms[0].mask == 0);
}

void CallArgs::fail(const std::string& message) const {
  throw CalcFailure{column, message};
}
void CallArgs::fail_at(std::size_t i, const std::string& message) const {
  throw CalcFailure{columns[i], message};
}
double CallArgs::number(std::size_t i, std::string_view what) const {
  if (!is_scalar(values[i]))
    fail_at(i, std::string(name) + ": " + std::string(what) + " must be a number");
  return values[i][0];
}
int CallArgs::integer(std::size_t i, int max, std::string_view what) const {
  const double k = number(i, what);
  if (k != std::floor(k) || k < 0 || k > max)
    fail_at(i, std::string(what) + " must be an integer from 0 to " + std::to_string(max));
  return static_cast<int>(k);
}

namespace {

// ---- scalars ------------------------------------------------------------------------------------

// The result of a scalar function, refused when it is not a finite number.
Multivector finite(const CallArgs& a, double v) {
  if (!std::isfinite(v))
    a.fail(std::string(a.name) + ": the result is not a finite number (argument out of domain)");
  return clifford::scalar(v);
}

template <double (*F)(double)>
Multivector scalar_function(const CallArgs& a) {
  return finite(a, F(a.number(0)));
}

double sin_(double x) {
  return std::sin(x);
}
double cos_(double x) {
  return std::cos(x);
}
double tan_(double x) {
  return std::tan(x);
}
double asin_(double x) {
  return std::asin(x);
}
double acos_(double x) {
  return std::acos(x);
}
double atan_(double x) {
  return std::atan(x);
}
double sinh_(double x) {
  return std::sinh(x);
}
double cosh_(double x) {
  return std::cosh(x);
}
double tanh_(double x) {
  return std::tanh(x);
}
double abs_(double x) {
  return std::abs(x);
}

Multivector atan2_(const CallArgs& a) {
  return finite(a, std::atan2(a.number(0, "y"), a.number(1, "x")));
}

// ---- exp, log, sqrt, pow on rotors and motors ---------------------------------------------------

// M M̃ = a + b I with I the pseudoscalar: a scalar for a multiple ρ M₀ of a unit rotor or motor
// (a = ρ²), a Study number (b ≠ 0, I² = 0) for a PGA motor times a dual number. The unit part is
// U = M exp(−½ log(a + b I)), with log(a + b I) = ln a + (b/a) I when I² = 0.
struct Normalization {
  double a = 1, b = 0;  // M M̃ = a + b I
  Multivector unit;     // U, with U Ũ = 1
};

Normalization normalize_versor(const CallArgs& c, const Multivector& m) {
  const clifford::Algebra& alg = c.algebra();
  const Multivector nn = clifford::geometric(alg, m, clifford::reverse(m));
  const double scale = std::max(clifford::max_abs_coeff(m), 1e-300);
  const double tol = 1e-12 * scale * scale;
  const clifford::BladeMask i_mask = alg.pseudoscalar_mask();
  const Multivector i = clifford::pseudoscalar(alg);
  const bool i_null = clifford::scalar_part(clifford::geometric(alg, i, i)) == 0;
  Normalization n;
  n.a = clifford::scalar_part(nn);
  for (const auto& t : nn.terms) {
    if (t.mask == 0) continue;
    if (t.mask == i_mask && i_null) {
      n.b = t.coeff;
      continue;
    }
    if (std::abs(t.coeff) > tol)
      c.fail(std::string(c.name) +
             ": X ~X is not a scalar: X is not a multiple of a rotor or motor");
  }
  if (!(n.a > tol))
    c.fail(std::string(c.name) + ": X ~X = " + std::to_string(n.a) +
           " is not positive: no real logarithm");
  if (std::abs(n.b) <= tol) n.b = 0;
  // exp(−½ log(a + b I)) = a^(−½) (1 − b/(2a) I)
  Multivector inv_sqrt = clifford::scalar(1 / std::sqrt(n.a));
  if (n.b != 0) {
    const Multivector commute = clifford::geometric(alg, i, m) - clifford::geometric(alg, m, i);
    if (clifford::max_abs_coeff(commute) > 1e-12 * scale)
      c.fail(std::string(c.name) + ": X ~X is not a scalar and X does not commute with I");
    inv_sqrt = inv_sqrt + clifford::basis_blade(i_mask, -n.b / (2 * n.a * std::sqrt(n.a)));
  }
  n.unit = clifford::geometric(alg, m, inv_sqrt);
  return n;
}

// y · log(a + b I) / 2 as a multivector: the log of (M M̃)^(y/2).
Multivector half_log_norm(const CallArgs& c, const Normalization& n, double y) {
  Multivector out = clifford::scalar(0.5 * y * std::log(n.a));
  if (n.b != 0)
    out = out + clifford::basis_blade(c.algebra().pseudoscalar_mask(), 0.5 * y * n.b / n.a);
  return out;
}

// exp of a scalar plus a multiple of a null pseudoscalar: e^s (1 + t I).
Multivector exp_scalar_and_null_i(const CallArgs& c, const Multivector& x) {
  const double e = std::exp(clifford::scalar_part(x));
  const double t = x[c.algebra().pseudoscalar_mask()];
  return clifford::scalar(e) + clifford::basis_blade(c.algebra().pseudoscalar_mask(), e * t);
}

Multivector checked(const CallArgs& c, Multivector m) {
  for (const auto& t : m.terms)
    if (!std::isfinite(t.coeff))
      c.fail(std::string(c.name) + ": the result is not finite (argument out of range)");
  return m;
}

Multivector exp_(const CallArgs& c) {
  if (is_scalar(c[0])) return finite(c, std::exp(c[0][0]));
  return checked(c, clifford::exp(c.algebra(), c[0]));
}

Multivector log_(const CallArgs& c) {
  if (is_scalar(c[0])) {
    if (!(c[0][0] > 0)) c.fail("log of a number that is not positive");
    return finite(c, std::log(c[0][0]));
  }
  const Normalization n = normalize_versor(c, c[0]);
  return checked(c, half_log_norm(c, n, 1.0) + clifford::log(c.algebra(), n.unit));
}

Multivector sqrt_(const CallArgs& c) {
  if (is_scalar(c[0])) {
    if (c[0][0] < 0) c.fail("sqrt of a negative number");
    return finite(c, std::sqrt(c[0][0]));
  }
  const Normalization n = normalize_versor(c, c[0]);
  const Multivector factor = exp_scalar_and_null_i(c, half_log_norm(c, n, 0.5));
  return checked(c, clifford::geometric(c.algebra(), factor, clifford::sqrt(c.algebra(), n.unit)));
}

// X^k for an integer k by repeated squaring (k < 0: of the inverse).
Multivector integer_power(const CallArgs& c, Multivector x, double k) {
  const clifford::Algebra& alg = c.algebra();
  if (k < 0) {
    x = clifford::inverse(alg, x);
    k = -k;
  }
  Multivector result = clifford::scalar(1);
  while (k > 0) {
    const double half = std::floor(k / 2);
    if (k - 2 * half == 1) result = clifford::geometric(alg, result, x);
    k = half;
    if (k > 0) x = clifford::geometric(alg, x, x);
  }
  return checked(c, result);
}

Multivector pow_(const CallArgs& c) {
  const double y = c.number(1, "the exponent");
  if (is_scalar(c[0])) {
    const double x = c[0][0];
    if (x < 0 && y != std::floor(y)) c.fail("pow of a negative number to a non-integer power");
    if (x == 0 && y < 0) c.fail("pow: zero to a negative power");
    return finite(c, std::pow(x, y));
  }
  if (y == std::floor(y) && std::abs(y) <= 1 << 30) return integer_power(c, c[0], y);
  // M^y = (M M̃)^(y/2) exp(y log U)
  const Normalization n = normalize_versor(c, c[0]);
  const Multivector factor = exp_scalar_and_null_i(c, half_log_norm(c, n, y));
  const Multivector u = clifford::exp(c.algebra(), y * clifford::log(c.algebra(), n.unit));
  return checked(c, clifford::geometric(c.algebra(), factor, u));
}

// ---- duals --------------------------------------------------------------------------------------

Multivector hodge(const CallArgs& c) {
  return clifford::dual(c.algebra(), c[0]);
}
Multivector unhodge(const CallArgs& c) {
  return clifford::undual(c.algebra(), c[0]);
}

void require_metric_dual(const CallArgs& c) {
  const Multivector i = clifford::pseudoscalar(c.algebra());
  if (clifford::scalar_part(clifford::geometric(c.algebra(), i, i)) == 0)
    c.fail(std::string(c.name) +
           ": the metric dual X I^-1 needs an invertible pseudoscalar, and I^2 = 0 in " +
           c.alg.name + "; use !X or hodge(X), the Hodge complement");
}
Multivector dual_(const CallArgs& c) {  // X I⁻¹
  require_metric_dual(c);
  return clifford::metric_dual(c.algebra(), c[0]);
}
Multivector undual_(const CallArgs& c) {  // X I, so undual(dual(X)) = X
  require_metric_dual(c);
  return clifford::geometric(c.algebra(), c[0], clifford::pseudoscalar(c.algebra()));
}

// ---- involutions, inverse, norms ----------------------------------------------------------------

Multivector reverse_(const CallArgs& c) {
  return clifford::reverse(c[0]);
}
Multivector involute_(const CallArgs& c) {
  return clifford::involution(c[0]);
}
Multivector conjugate_(const CallArgs& c) {
  return clifford::conjugate(c[0]);
}
Multivector inverse_(const CallArgs& c) {
  if (is_scalar(c[0])) {
    if (c[0][0] == 0) c.fail("inverse of zero");
    return clifford::scalar(1.0 / c[0][0]);
  }
  return clifford::inverse(c.algebra(), c[0]);
}

// PGA (docs/conventions.md §6): ‖A‖ over the coefficients without a null factor, ‖A‖∞ over those
// with one; elsewhere sqrt|⟨A Ã⟩₀|.
double norm_of(const CallArgs& c, const Multivector& x, bool ideal) {
  const clifford::Algebra& a = c.algebra();
  if (c.alg.degenerate) {
    clifford::BladeMask null_mask = 0;
    for (int k = 0; k < a.dimension(); ++k)
      if (a.orthogonal_squares()[static_cast<std::size_t>(k)] == 0) null_mask |= 1u << k;
    double s = 0;
    for (const auto& t : x.terms)
      if (((t.mask & null_mask) != 0) == ideal) s += t.coeff * t.coeff;
    return std::sqrt(s);
  }
  if (ideal) c.fail("inorm needs a degenerate algebra (PGA); " + c.alg.name + " has no e0");
  return clifford::norm(a, x);
}
Multivector norm_(const CallArgs& c) {
  return clifford::scalar(norm_of(c, c[0], false));
}
Multivector inorm_(const CallArgs& c) {
  return clifford::scalar(norm_of(c, c[0], true));
}
Multivector normalize_(const CallArgs& c) {
  const double n = norm_of(c, c[0], false);
  if (n == 0) c.fail("normalize: the norm is zero");
  return c[0] / n;
}

// ---- products by name ---------------------------------------------------------------------------

Multivector grade_(const CallArgs& c) {
  return clifford::grade(c[0], c.integer(1, c.algebra().dimension(), "the grade"));
}
Multivector lc_(const CallArgs& c) {
  return clifford::left_contraction(c.algebra(), c[0], c[1]);
}
Multivector rc_(const CallArgs& c) {
  return clifford::right_contraction(c.algebra(), c[0], c[1]);
}
Multivector sp_(const CallArgs& c) {
  return clifford::scalar(clifford::scalar_product(c.algebra(), c[0], c[1]));
}
Multivector cross_(const CallArgs& c) {
  return clifford::commutator(c.algebra(), c[0], c[1]);
}
Multivector sandwich_(const CallArgs& c) {
  return clifford::sandwich(c.algebra(), c[0], c[1]);
}

constexpr FunctionInfo general[] = {
    {"exp", "exp(X)", "exponential (closed forms for rotors and motors, else a series)", 1, 1,
     any_model, exp_},
    {"log", "log(X)", "logarithm of a positive number or of a multiple of a rotor or motor", 1, 1,
     any_model, log_},
    {"sqrt", "sqrt(X)", "square root of a number or of a multiple of a rotor or motor", 1, 1,
     any_model, sqrt_},
    {"pow", "pow(X, y)", "X to the power y (integer y: repeated products; else exp(y log X))", 2, 2,
     any_model, pow_},
    {"sin", "sin(x)", "sine of a number", 1, 1, any_model, scalar_function<sin_>},
    {"cos", "cos(x)", "cosine of a number", 1, 1, any_model, scalar_function<cos_>},
    {"tan", "tan(x)", "tangent of a number", 1, 1, any_model, scalar_function<tan_>},
    {"asin", "asin(x)", "arc sine", 1, 1, any_model, scalar_function<asin_>},
    {"acos", "acos(x)", "arc cosine", 1, 1, any_model, scalar_function<acos_>},
    {"atan", "atan(x)", "arc tangent", 1, 1, any_model, scalar_function<atan_>},
    {"atan2", "atan2(y, x)", "angle of (x, y) in (-pi, pi]", 2, 2, any_model, atan2_},
    {"sinh", "sinh(x)", "hyperbolic sine", 1, 1, any_model, scalar_function<sinh_>},
    {"cosh", "cosh(x)", "hyperbolic cosine", 1, 1, any_model, scalar_function<cosh_>},
    {"tanh", "tanh(x)", "hyperbolic tangent", 1, 1, any_model, scalar_function<tanh_>},
    {"abs", "abs(x)", "absolute value of a number", 1, 1, any_model, scalar_function<abs_>},
    {"hodge", "hodge(X)", "Hodge complement, e_J hodge(e_J) = I (the same as !X)", 1, 1, any_model,
     hodge},
    {"unhodge", "unhodge(X)", "inverse of the Hodge complement", 1, 1, any_model, unhodge},
    {"dual", "dual(X)", "metric dual X I^-1 (not in degenerate algebras)", 1, 1, any_model, dual_},
    {"undual", "undual(X)", "X I, the inverse of dual", 1, 1, any_model, undual_},
    {"reverse", "reverse(X)", "reverse (the same as ~X)", 1, 1, any_model, reverse_},
    {"involute", "involute(X)", "grade involution", 1, 1, any_model, involute_},
    {"conjugate", "conjugate(X)", "Clifford conjugate", 1, 1, any_model, conjugate_},
    {"inverse", "inverse(X)", "inverse of a versor, ~X / (X ~X)", 1, 1, any_model, inverse_},
    {"norm", "norm(X)", "sqrt|<X ~X>| (PGA: the coefficients without e0)", 1, 1, any_model, norm_},
    {"inorm", "inorm(X)", "PGA ideal norm: the coefficients with e0", 1, 1, any_model, inorm_},
    {"normalize", "normalize(X)", "X / norm(X)", 1, 1, any_model, normalize_},
    {"grade", "grade(X, k)", "grade-k part", 2, 2, any_model, grade_},
    {"lc", "lc(A, B)", "left contraction", 2, 2, any_model, lc_},
    {"rc", "rc(A, B)", "right contraction", 2, 2, any_model, rc_},
    {"sp", "sp(A, B)", "scalar product <A B>", 2, 2, any_model, sp_},
    {"cross", "cross(A, B)", "commutator product (AB - BA)/2", 2, 2, any_model, cross_},
    {"sandwich", "sandwich(V, X)", "V X ~V", 2, 2, any_model, sandwich_},
};

}  // namespace

std::span<const FunctionInfo> general_functions() {
  return general;
}

std::vector<const FunctionInfo*> find_functions(std::string_view name) {
  std::vector<const FunctionInfo*> out;
  for (auto table : {general_functions(), model_functions()})
    for (const FunctionInfo& f : table)
      if (f.name == name) out.push_back(&f);
  return out;
}

std::string function_names_for(CalcModel m) {
  std::string out;
  for (const FunctionInfo& f : model_functions())
    if ((f.models & model_bit(m)) && out.find(std::string(f.name) + ",") == std::string::npos &&
        !(out.size() >= f.name.size() && out.substr(out.size() - f.name.size()) == f.name)) {
      if (!out.empty()) out += ", ";
      out += f.name;
    }
  return out;
}

}  // namespace pgamesh::cli
