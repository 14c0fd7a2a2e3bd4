// Tokenizer, recursive-descent evaluator and printer of `pgamesh calc`.
#include "calc_eval.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace pgamesh::cli {

using clifford::BladeMask;
using clifford::Multivector;

std::optional<CalcAlgebra> calc_algebra(std::string_view name) {
  auto alg = clifford::make_algebra(name);
  if (!alg) return std::nullopt;
  CalcAlgebra c{std::string(name), std::move(*alg)};
  const auto& sq = c.algebra.orthogonal_squares();
  c.degenerate = c.algebra.is_diagonal() && std::count(sq.begin(), sq.end(), 0.0) > 0;
  const int n = c.algebra.dimension();
  if (c.algebra.is_diagonal() && sq[0] == 0 && std::count(sq.begin(), sq.end(), 0.0) == 1 &&
      std::count(sq.begin(), sq.end(), 1.0) == n - 1) {
    c.model = PointModel::pga;  // R(d,0,1) with e0 first
    c.point_dimension = n - 1;
  } else if (name == "cga3" || name == "cga") {
    c.model = PointModel::cga;
    c.point_dimension = 3;
  } else if (name == "dpga") {
    c.model = PointModel::dpga;
    c.point_dimension = 3;
  } else if (name == "dcga") {
    c.model = PointModel::dcga;
    c.point_dimension = 3;
  } else if (name == "qcga") {
    c.model = PointModel::qcga;
    c.point_dimension = 3;
  }
  return c;
}

namespace {

constexpr std::size_t max_depth = 200;

struct Failure {
  std::size_t column;
  std::string message;
};

enum class Tok { number, ident, op, lparen, rparen, comma, equals, end };

struct Token {
  Tok kind;
  std::size_t column;  // 1-based
  std::string text;
  double number = 0;
};

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  auto is_ident_start = [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
  };
  auto is_ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < s.size()) {
    const char c = s[i];
    const std::size_t col = i + 1;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < s.size() &&
                std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      std::size_t j = i;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      if (j < s.size() && s[j] == '.') {
        ++j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      }
      if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {  // exponent only when digits follow
        std::size_t k = j + 1;
        if (s[j] == 'e' && k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])))
          throw Failure{col, "ambiguous '" + std::string(s.substr(i, k + 1 - i)) +
                                 "...': write 2*e12 for a blade, 2E12 or 2e+12 for a power of ten"};
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        if (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) {
          while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
          j = k;
        }
      }
      const std::string text(s.substr(i, j - i));
      double v = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        throw Failure{col, "number '" + text + "' out of range"};
      if (j < s.size() && is_ident(s[j]))
        throw Failure{j + 1, "a number must be followed by an operator (write 2*e12, not 2e12)"};
      out.push_back({Tok::number, col, text, v});
      i = j;
    } else if (is_ident_start(c)) {
      std::size_t j = i;
      while (j < s.size() && is_ident(s[j])) ++j;
      out.push_back({Tok::ident, col, std::string(s.substr(i, j - i))});
      i = j;
    } else if (std::string_view("+-*/^&|~!").find(c) != std::string_view::npos) {
      out.push_back({Tok::op, col, std::string(1, c)});
      ++i;
    } else if (c == '(') {
      out.push_back({Tok::lparen, col, "("});
      ++i;
    } else if (c == ')') {
      out.push_back({Tok::rparen, col, ")"});
      ++i;
    } else if (c == ',') {
      out.push_back({Tok::comma, col, ","});
      ++i;
    } else if (c == '=') {
      out.push_back({Tok::equals, col, "="});
      ++i;
    } else {
      throw Failure{col, std::string("unexpected character '") + c + "'"};
    }
  }
  out.push_back({Tok::end, s.size() + 1, ""});
  return out;
}

bool is_scalar(const Multivector& m) {
  return m.terms.empty() || (m.terms.size() == 1 && m.terms[0].mask == 0);
}

const std::vector<std::string>& function_names() {
  static const std::vector<std::string> names = {
      "exp",   "log",   "sqrt",     "dual",      "undual", "reverse", "inverse", "norm", "inorm",
      "grade", "point", "involute", "conjugate", "lc",     "rc",      "sp",      "cross"};
  return names;
}

class Parser {
 public:
  Parser(const CalcAlgebra& alg, const std::map<std::string, Multivector>& names,
         std::vector<Token> tokens)
      : alg_(alg), names_(names), toks_(std::move(tokens)) {}

  Multivector expression_to_end() {
    Multivector v = sum();
    if (peek().kind != Tok::end) fail(peek().column, "unexpected '" + peek().text + "'");
    return v;
  }

 private:
  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_++]; }
  bool peek_op(char c) const { return peek().kind == Tok::op && peek().text[0] == c; }
  [[noreturn]] static void fail(std::size_t column, std::string message) {
    throw Failure{column, std::move(message)};
  }
  const clifford::Algebra& A() const { return alg_.algebra; }

  // sum := product (('+' | '-') product)*
  Multivector sum() {
    Multivector v = product();
    while (peek_op('+') || peek_op('-')) {
      const bool plus = next().text[0] == '+';
      Multivector r = product();
      v = plus ? v + r : v - r;
    }
    return v;
  }

  // product := outer (('*' | '/') outer)*
  Multivector product() {
    Multivector v = wedge();
    while (peek_op('*') || peek_op('/')) {
      const Token& op = next();
      const std::size_t col = peek().column;
      Multivector r = wedge();
      if (op.text[0] == '*') {
        v = clifford::geometric(A(), v, r);
      } else if (is_scalar(r)) {
        if (r[0] == 0) fail(col, "division by zero");
        v = v / r[0];
      } else {
        v = clifford::geometric(A(), v,
                                apply(op.column, [&] { return clifford::inverse(A(), r); }));
      }
    }
    return v;
  }

  // wedge := unary (('^' | '&' | '|') unary)*   (outer, join, inner: bind tighter than *)
  Multivector wedge() {
    Multivector v = unary();
    while (peek_op('^') || peek_op('&') || peek_op('|')) {
      const char op = next().text[0];
      Multivector r = unary();
      if (op == '^') v = clifford::outer(A(), v, r);
      if (op == '&') v = clifford::regressive(A(), v, r);
      if (op == '|') v = clifford::inner(A(), v, r);
    }
    return v;
  }

  // unary := ('-' | '+' | '~' | '!') unary | primary
  Multivector unary() {
    if (++depth_ > max_depth) fail(peek().column, "expression nested too deeply");
    Multivector v;
    if (peek_op('-')) {
      next();
      v = -unary();
    } else if (peek_op('+')) {
      next();
      v = unary();
    } else if (peek_op('~')) {
      next();
      v = clifford::reverse(unary());
    } else if (peek_op('!')) {
      next();
      v = clifford::dual(A(), unary());
    } else {
      v = primary();
    }
    --depth_;
    return v;
  }

  template <class F>
  Multivector apply(std::size_t column, F f) {
    try {
      return f();
    } catch (const std::exception& e) {
      fail(column, e.what());
    }
  }

  Multivector primary() {
    const Token t = next();
    switch (t.kind) {
      case Tok::number:
        return clifford::scalar(t.number);
      case Tok::lparen: {
        Multivector v = sum();
        if (peek().kind != Tok::rparen) fail(peek().column, "expected ')'");
        next();
        return v;
      }
      case Tok::ident:
        if (peek().kind == Tok::lparen) return call(t);
        if (t.text == "pi") return clifford::scalar(M_PI);
        if (auto it = names_.find(t.text); it != names_.end()) return it->second;
        if (auto b = A().parse_blade(t.text)) return clifford::basis_blade(b->first, b->second);
        if (std::find(function_names().begin(), function_names().end(), t.text) !=
            function_names().end())
          fail(t.column, "function '" + t.text + "' needs its arguments in parentheses");
        fail(t.column, "unknown blade '" + t.text + "' in algebra " + alg_.name);
      case Tok::end:
        fail(t.column, "unexpected end of expression");
      default:
        fail(t.column, "unexpected '" + t.text + "'");
    }
  }

  double scalar_arg(const Multivector& m, std::size_t column, const std::string& what) {
    if (!is_scalar(m)) fail(column, what + " must be a number");
    return m[0];
  }

  Multivector call(const Token& f) {
    next();  // '('
    std::vector<Multivector> args;
    std::vector<std::size_t> cols;
    if (peek().kind != Tok::rparen) {
      for (;;) {
        cols.push_back(peek().column);
        args.push_back(sum());
        if (peek().kind == Tok::comma) {
          next();
          continue;
        }
        break;
      }
    }
    if (peek().kind != Tok::rparen) fail(peek().column, "expected ')' or ','");
    next();
    const std::string& name = f.text;
    auto arity = [&](std::size_t n) {
      if (args.size() != n)
        fail(f.column, name + "() takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") +
                           ", got " + std::to_string(args.size()));
    };
    const clifford::Algebra& a = A();
    if (name == "point") return point(f, args, cols);
    if (name == "grade") {
      arity(2);
      const double k = scalar_arg(args[1], cols[1], "the grade");
      if (k != std::floor(k) || k < 0 || k > a.dimension())
        fail(cols[1], "the grade must be an integer from 0 to " + std::to_string(a.dimension()));
      return clifford::grade(args[0], static_cast<int>(k));
    }
    if (name == "lc" || name == "rc" || name == "sp" || name == "cross") {
      arity(2);
      if (name == "lc") return clifford::left_contraction(a, args[0], args[1]);
      if (name == "rc") return clifford::right_contraction(a, args[0], args[1]);
      if (name == "sp") return clifford::scalar(clifford::scalar_product(a, args[0], args[1]));
      return clifford::commutator(a, args[0], args[1]);
    }
    arity(1);
    const Multivector& x = args[0];
    if (name == "exp") return apply(f.column, [&] { return clifford::exp(a, x); });
    if (name == "log") return apply(f.column, [&] { return clifford::log(a, x); });
    if (name == "sqrt") {
      if (is_scalar(x)) {
        if (x[0] < 0) fail(f.column, "sqrt of a negative number");
        return clifford::scalar(std::sqrt(x[0]));
      }
      return apply(f.column, [&] { return clifford::sqrt(a, x); });
    }
    if (name == "dual") return clifford::dual(a, x);
    if (name == "undual") return clifford::undual(a, x);
    if (name == "reverse") return clifford::reverse(x);
    if (name == "involute") return clifford::involution(x);
    if (name == "conjugate") return clifford::conjugate(x);
    if (name == "inverse") {
      if (is_scalar(x)) {
        if (x[0] == 0) fail(f.column, "inverse of zero");
        return clifford::scalar(1.0 / x[0]);
      }
      return apply(f.column, [&] { return clifford::inverse(a, x); });
    }
    if (name == "norm" || name == "inorm") {
      if (alg_.degenerate) {  // ERRATA §0.1: coefficients without / with a null factor
        BladeMask null_mask = 0;
        for (int k = 0; k < a.dimension(); ++k)
          if (a.orthogonal_squares()[static_cast<std::size_t>(k)] == 0) null_mask |= 1u << k;
        double s = 0;
        for (const auto& t : x.terms)
          if (((t.mask & null_mask) != 0) == (name == "inorm")) s += t.coeff * t.coeff;
        return clifford::scalar(std::sqrt(s));
      }
      if (name == "inorm")
        fail(f.column, "inorm needs a degenerate algebra (PGA); " + alg_.name + " has no e0");
      return clifford::scalar(clifford::norm(a, x));
    }
    fail(f.column, "unknown function '" + name + "'");
  }

  Multivector gen(const char* name) const {
    const auto b = A().parse_blade(name);
    return clifford::basis_blade(b->first, b->second);
  }

  Multivector point(const Token& f, const std::vector<Multivector>& args,
                    const std::vector<std::size_t>& cols) {
    if (alg_.model == PointModel::none)
      fail(f.column, "point() is not defined in algebra " + alg_.name +
                         " (it is for pgaN, cga3, dpga, dcga, qcga and p,0,1)");
    if (static_cast<int>(args.size()) != alg_.point_dimension)
      fail(f.column, "point() takes " + std::to_string(alg_.point_dimension) +
                         " coordinates in algebra " + alg_.name + ", got " +
                         std::to_string(args.size()));
    std::vector<double> x;
    for (std::size_t i = 0; i < args.size(); ++i)
      x.push_back(scalar_arg(args[i], cols[i], "a coordinate"));
    const clifford::Algebra& a = A();
    double x2 = 0;
    for (double xi : x) x2 += xi * xi;
    switch (alg_.model) {
      case PointModel::pga: {  // (e0 + Σ x_i e_i)*, ERRATA §0.1
        Multivector v = clifford::basis_blade(1);
        for (std::size_t i = 0; i < x.size(); ++i) v = v + clifford::basis_blade(2u << i, x[i]);
        return clifford::dual(a, v);
      }
      case PointModel::cga:  // x + ½ x² e∞ + e_o, ERRATA §0.3
        return gen("eo") + x[0] * gen("e1") + x[1] * gen("e2") + x[2] * gen("e3") +
               (0.5 * x2) * gen("ei");
      case PointModel::dpga:  // x w0 + y w1 + z w2 + w3, ERRATA §0.4
        return x[0] * gen("w0") + x[1] * gen("w1") + x[2] * gen("w2") + gen("w3");
      case PointModel::dcga: {  // the outer product of the two CGA points (Easter–Hitzer)
        const Multivector p1 = gen("eo1") + x[0] * gen("e1") + x[1] * gen("e2") + x[2] * gen("e3") +
                               (0.5 * x2) * gen("ei1");
        const Multivector p2 = gen("eo2") + x[0] * gen("e4") + x[1] * gen("e5") + x[2] * gen("e6") +
                               (0.5 * x2) * gen("ei2");
        return clifford::outer(a, p1, p2);
      }
      case PointModel::qcga:  // ERRATA §5 (Breuils et al. 2018)
        return x[0] * gen("e1") + x[1] * gen("e2") + x[2] * gen("e3") +
               (0.5 * x[0] * x[0]) * gen("ei1") + (0.5 * x[1] * x[1]) * gen("ei2") +
               (0.5 * x[2] * x[2]) * gen("ei3") + (x[0] * x[1]) * gen("ei4") +
               (x[0] * x[2]) * gen("ei5") + (x[1] * x[2]) * gen("ei6") + gen("eo1") + gen("eo2") +
               gen("eo3");
      case PointModel::none:
        break;
    }
    fail(f.column, "point() is not defined here");
  }

  const CalcAlgebra& alg_;
  const std::map<std::string, Multivector>& names_;
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
};

std::string number(double v) {
  if (v == 0) return "0";  // also −0
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

CalcResult Calculator::run(std::string_view statement) {
  try {
    std::vector<Token> toks = tokenize(statement);
    if (toks.size() >= 2 && toks[0].kind == Tok::ident && toks[0].text == "let") {
      if (toks[1].kind != Tok::ident)
        return {std::nullopt, CalcError{toks[1].column, "expected a name after 'let'"}};
      const Token name = toks[1];
      if (toks[2].kind != Tok::equals)
        return {std::nullopt,
                CalcError{toks[2].column, "expected '=' after 'let " + name.text + "'"}};
      if (alg_.algebra.parse_blade(name.text) || name.text == "pi" || name.text == "let" ||
          std::find(function_names().begin(), function_names().end(), name.text) !=
              function_names().end())
        return {
            std::nullopt,
            CalcError{name.column, "'" + name.text + "' is a blade, constant or function name"}};
      toks.erase(toks.begin(), toks.begin() + 3);
      Parser p(alg_, names_, std::move(toks));
      names_[name.text] = p.expression_to_end();
      return {};
    }
    Parser p(alg_, names_, std::move(toks));
    return {p.expression_to_end(), std::nullopt};
  } catch (const Failure& f) {
    return {std::nullopt, CalcError{f.column, f.message}};
  } catch (const std::exception& e) {  // e.g. std::bad_alloc: reported, never escapes
    return {std::nullopt, CalcError{1, e.what()}};
  }
}

namespace {
std::vector<clifford::Term> display_terms(const clifford::Algebra& a, const Multivector& m) {
  std::vector<clifford::Term> t = m.terms;
  std::stable_sort(t.begin(), t.end(), [&a](const clifford::Term& x, const clifford::Term& y) {
    return a.display_before(x.mask, y.mask);
  });
  return t;
}
}  // namespace

std::string Calculator::format(const Multivector& m) const {
  std::string out;
  for (const auto& t : display_terms(alg_.algebra, m)) {
    const auto [name, sign] = alg_.algebra.blade_name(t.mask);
    double c = sign * t.coeff;
    const bool negative = std::signbit(c);
    if (out.empty()) {
      if (negative) out += "-";
    } else {
      out += negative ? " - " : " + ";
    }
    c = std::abs(c);
    if (t.mask == 0) {
      out += number(c);
    } else {
      if (c != 1) out += number(c) + " ";
      out += name;
    }
  }
  return out.empty() ? "0" : out;
}

std::string Calculator::format_json(const Multivector& m) const {
  std::string out = "{";
  bool first = true;
  for (const auto& t : display_terms(alg_.algebra, m)) {
    const auto [name, sign] = alg_.algebra.blade_name(t.mask);
    const double c = sign * t.coeff;
    out += (first ? "\"" : ", \"") + name + "\": " + (std::isfinite(c) ? number(c) : "null");
    first = false;
  }
  return out + "}";
}

std::vector<Statement> split_statements(std::string_view script) {
  std::vector<Statement> out;
  std::size_t line = 1, col = 1;
  Statement cur{"", 1, 1};
  bool comment = false;
  auto flush = [&] {
    if (cur.text.find_first_not_of(" \t\r") != std::string::npos) out.push_back(cur);
  };
  for (char c : script) {
    if (c == '\n' || (c == ';' && !comment)) {
      flush();
      if (c == '\n') {
        ++line;
        col = 1;
        comment = false;
      } else {
        ++col;
      }
      cur = Statement{"", line, col};
      continue;
    }
    if (c == '#') comment = true;
    if (!comment) cur.text += c;
    ++col;
  }
  flush();
  return out;
}

}  // namespace pgamesh::cli
