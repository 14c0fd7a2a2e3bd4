// Tokenizer, recursive-descent parser and statement splitter of `pgamesh calc`.
#include "calc_syntax.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>

namespace pgamesh::cli {

namespace {

bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool is_ident(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// A number starting at s[i]: digits, an optional fraction and an exponent (only when digits
// follow the 'e'). "2e12" is refused as ambiguous: 2·e12 or 2·10¹²?
Token number_token(std::string_view s, std::size_t i) {
  const std::size_t col = i + 1;
  std::size_t j = i;
  while (j < s.size() && is_digit(s[j])) ++j;
  if (j < s.size() && s[j] == '.') {
    ++j;
    while (j < s.size() && is_digit(s[j])) ++j;
  }
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    std::size_t k = j + 1;
    if (s[j] == 'e' && k < s.size() && is_digit(s[k]))
      fail_at(col, "ambiguous '" + std::string(s.substr(i, k + 1 - i)) +
                       "...': write 2*e12 for a blade, 2E12 or 2e+12 for a power of ten");
    if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
    if (k < s.size() && is_digit(s[k])) {
      while (k < s.size() && is_digit(s[k])) ++k;
      j = k;
    }
  }
  const std::string text(s.substr(i, j - i));
  double v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
    fail_at(col, "number '" + text + "' out of range");
  if (j < s.size() && is_ident(s[j]))
    fail_at(j + 1, "a number must be followed by an operator (write 2*e12, not 2e12)");
  return {Tok::number, col, text, v};
}

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : toks_(std::move(tokens)) {}

  Expr expression_to_end() {
    Expr e = sum();
    if (peek().kind != Tok::end) fail_at(peek().column, "unexpected '" + peek().text + "'");
    return e;
  }

 private:
  const Token& peek() const { return toks_[pos_]; }
  const Token& next() { return toks_[pos_++]; }
  bool peek_op(std::string_view ops) const {
    return peek().kind == Tok::op && ops.find(peek().text[0]) != std::string_view::npos;
  }

  // A chain of operands joined by the operators in `ops`, each operand parsed by `operand`.
  template <class Operand>
  Expr chain(std::string_view ops, Operand operand) {
    Expr first = (this->*operand)();
    if (!peek_op(ops)) return first;
    Expr c;
    c.kind = Expr::Kind::chain;
    c.column = first.column;
    c.args.push_back(std::move(first));
    while (peek_op(ops)) {
      const Token& op = next();
      c.ops.push_back(op.text[0]);
      c.op_columns.push_back(op.column);
      c.args.push_back((this->*operand)());
    }
    return c;
  }

  // sum := product (('+' | '-') product)*
  Expr sum() { return chain("+-", &Parser::product); }
  // product := wedge (('*' | '/') wedge)*
  Expr product() { return chain("*/", &Parser::wedge); }
  // wedge := unary (('^' | '&' | '|') unary)*   (outer, join, inner: bind tighter than *)
  Expr wedge() { return chain("^&|", &Parser::unary); }

  // unary := ('-' | '+' | '~' | '!') unary | primary
  Expr unary() {
    if (++depth_ > calc_max_depth) fail_at(peek().column, "expression nested too deeply");
    Expr e;
    if (peek_op("-+~!")) {
      const Token& op = next();
      e.kind = Expr::Kind::unary;
      e.column = op.column;
      e.text = op.text;
      e.args.push_back(unary());
    } else {
      e = primary();
    }
    --depth_;
    return e;
  }

  Expr primary() {
    const Token t = next();
    Expr e;
    e.column = t.column;
    switch (t.kind) {
      case Tok::number:
        e.kind = Expr::Kind::number;
        e.number = t.number;
        e.text = t.text;
        return e;
      case Tok::lparen: {
        e = sum();
        if (peek().kind != Tok::rparen) fail_at(peek().column, "expected ')'");
        next();
        e.column = t.column;  // errors about the group point at its '('
        return e;
      }
      case Tok::ident:
        e.text = t.text;
        if (peek().kind != Tok::lparen) {
          e.kind = Expr::Kind::name;
          return e;
        }
        e.kind = Expr::Kind::call;
        next();  // '('
        if (peek().kind != Tok::rparen) {
          for (;;) {
            e.args.push_back(sum());
            if (peek().kind != Tok::comma) break;
            next();
          }
        }
        if (peek().kind != Tok::rparen) fail_at(peek().column, "expected ')' or ','");
        next();
        return e;
      case Tok::end:
        fail_at(t.column, "unexpected end of expression");
      default:
        fail_at(t.column, "unexpected '" + t.text + "'");
    }
  }

  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
};

}  // namespace

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const std::size_t col = i + 1;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
    } else if (is_digit(c) || (c == '.' && i + 1 < s.size() && is_digit(s[i + 1]))) {
      out.push_back(number_token(s, i));
      i += out.back().text.size();
    } else if (is_ident_start(c)) {
      std::size_t j = i;
      while (j < s.size() && is_ident(s[j])) ++j;
      out.push_back({Tok::ident, col, std::string(s.substr(i, j - i))});
      i = j;
    } else if (std::string_view("+-*/^&|~!").find(c) != std::string_view::npos) {
      out.push_back({Tok::op, col, std::string(1, c)});
      ++i;
    } else if (c == '(' || c == ')' || c == ',' || c == '=') {
      const Tok kind = c == '('   ? Tok::lparen
                       : c == ')' ? Tok::rparen
                       : c == ',' ? Tok::comma
                                  : Tok::equals;
      out.push_back({kind, col, std::string(1, c)});
      ++i;
    } else {
      fail_at(col, std::string("unexpected character '") + c + "'");
    }
  }
  out.push_back({Tok::end, s.size() + 1, ""});
  return out;
}

ParsedStatement parse_statement(std::string_view statement) {
  std::vector<Token> toks = tokenize(statement);
  ParsedStatement out;
  if (toks.size() >= 2 && toks[0].kind == Tok::ident && toks[0].text == "let") {
    if (toks[1].kind != Tok::ident) fail_at(toks[1].column, "expected a name after 'let'");
    if (toks[2].kind != Tok::equals)
      fail_at(toks[2].column, "expected '=' after 'let " + toks[1].text + "'");
    out.let_name = toks[1].text;
    out.let_column = toks[1].column;
    toks.erase(toks.begin(), toks.begin() + 3);
  }
  out.expr = Parser(std::move(toks)).expression_to_end();
  return out;
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
