// shadergen/expression.h - the boolean rule language of domain specs.
//
// Grammar:  expr := or;  or := and ('||' and)*;  and := unary ('&&' unary)*;
//           unary := '!' unary | '(' expr ')' | NAME [CMP VALUE] | 'true' | 'false'
//           CMP := '==' | '!=' | '<' | '<=' | '>' | '>='
// NAME is a feature name ([A-Za-z_][A-Za-z0-9_]*) resolved against a symbol table at parse
// time, so an unknown name is an error that points at its column, not a silent false. A
// boolean symbol stands alone; a valued one (with a list of values) is compared with one of
// its values (an integer or an identifier), and only integer values have an order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen {

// One name a rule may use: a boolean (one bit) or a valued feature (a field of `width` bits
// from `bit` holding the index of one of `values`).
struct ExpressionSymbol {
  std::string name;
  std::uint32_t bit = 0;
  std::uint32_t width = 1;
  std::vector<std::string> values;  // empty: boolean
};

class Expression {
 public:
  // Evaluates the rule for a set of bits (bit i set = symbol i true).
  bool evaluate(std::uint32_t bits) const;
  // The rule as written, normalised spacing, for explanations.
  std::string to_string() const;
  // The bits of every symbol the rule names (a valued symbol: its whole field).
  std::uint32_t symbol_mask() const;

  struct Node;

  Expression() = default;
  explicit Expression(std::shared_ptr<const Node> root) : root_(std::move(root)) {}
  bool empty() const { return root_ == nullptr; }
  // The parsed tree (nullptr when empty), for a translation into another language (the
  // generated C++'s is_possible()).
  const Node* root() const { return root_.get(); }

 private:
  std::shared_ptr<const Node> root_;
};

struct Expression::Node {
  enum class Kind { constant, symbol, comparison, negation, conjunction, disjunction } kind;
  bool constant = false;
  std::uint32_t symbol = 0;  // first bit of the symbol's field
  std::uint32_t width = 1;   // comparison: bits of the field
  // comparison: accepted[i] says whether value index i satisfies it, worked out once at
  // parse time; an index past the end (a field holding no value) is false.
  std::vector<bool> accepted;
  std::string text;  // symbol: its name; comparison: "NAME OP VALUE"
  std::shared_ptr<const Node> left, right;
};

// Maximum nesting of parentheses and negations; deeper input is rejected (bounded recursion).
inline constexpr int kMaxExpressionDepth = 64;
// Maximum length of a rule's text. Bounds the tree (a chain of '&&' is a left-deep tree that
// evaluation and destruction walk recursively) and the cost of expanding a domain.
inline constexpr std::size_t kMaxExpressionLength = 1024;

// Parses `text`. On error the diagnostic's column is 1-based within `text` and its message
// says what is wrong; the caller adds the file and line.
Result<Expression> parse_expression(std::string_view text, std::span<const ExpressionSymbol> symbols);
// The same where every symbol is boolean: `symbols[i]` names bit i.
Result<Expression> parse_expression(std::string_view text, std::span<const std::string> symbols);

}  // namespace shadergen
