// The syntax of `pgamesh calc` (docs/calc.md): statements, tokens and the expression tree.
// Parsing knows nothing about algebras: names are resolved and functions called by the evaluator
// (calc_eval.hpp). Errors are thrown as CalcFailure with the 1-based column of the offending token.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pgamesh::cli {

// An error at a column of the statement (1-based). Thrown by the parser and the evaluator.
struct CalcFailure {
  std::size_t column = 0;
  std::string message;
};

[[noreturn]] inline void fail_at(std::size_t column, std::string message) {
  throw CalcFailure{column, std::move(message)};
}

// Nesting deeper than this (parentheses, unary operators, calls) is refused.
inline constexpr std::size_t calc_max_depth = 200;

enum class Tok { number, ident, op, lparen, rparen, comma, equals, end };

struct Token {
  Tok kind;
  std::size_t column;  // 1-based
  std::string text;
  double number = 0;
};

// Splits one statement into tokens (the last is Tok::end). Throws CalcFailure.
std::vector<Token> tokenize(std::string_view statement);

// The expression tree. A chain holds operands joined by left-associative binary operators of one
// precedence level (a + b - c), so long flat sums are evaluated in a loop, not by recursion.
struct Expr {
  enum class Kind { number, name, unary, chain, call };
  Kind kind = Kind::number;
  std::size_t column = 1;
  std::string text;        // name, function name, or unary operator
  double number = 0;       // Kind::number
  std::vector<Expr> args;  // unary: 1 operand; chain: the operands; call: the arguments
  std::vector<char> ops;   // chain: ops[k] joins args[k] and args[k + 1]
  std::vector<std::size_t> op_columns;  // chain: column of ops[k]
};

// A parsed statement: `let NAME = EXPR` (name set) or `EXPR`.
struct ParsedStatement {
  std::string let_name;  // empty for an expression statement
  std::size_t let_column = 0;
  Expr expr;
};

// Parses one statement. Throws CalcFailure for a syntax error or nesting deeper than
// calc_max_depth.
ParsedStatement parse_statement(std::string_view statement);

// Splits a script into statements at ';' and newlines; each with its 1-based line and the column
// where it starts. Comments run from '#' to the end of the line.
struct Statement {
  std::string text;
  std::size_t line = 1, column = 1;
};
std::vector<Statement> split_statements(std::string_view script);

}  // namespace pgamesh::cli
