// shadergen/expression.h - the boolean rule language of domain specs.
//
// Grammar:  expr := or;  or := and ('||' and)*;  and := unary ('&&' unary)*;
//           unary := '!' unary | '(' expr ')' | NAME | 'true' | 'false'
// NAME is a feature name ([A-Za-z_][A-Za-z0-9_]*) resolved against a symbol table at parse
// time, so an unknown name is an error that points at its column, not a silent false.
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

class Expression {
public:
    // Evaluates the rule for a set of bits (bit i set = symbol i true).
    bool evaluate(std::uint32_t bits) const;
    // The rule as written, normalised spacing, for explanations.
    std::string to_string(std::span<const std::string> symbols) const;

    struct Node;

    Expression() = default;
    explicit Expression(std::shared_ptr<const Node> root) : root_(std::move(root)) {}
    bool empty() const { return root_ == nullptr; }

private:
    std::shared_ptr<const Node> root_;
};

struct Expression::Node {
    enum class Kind { constant, symbol, negation, conjunction, disjunction } kind;
    bool constant = false;
    std::uint32_t symbol = 0;  // bit index
    std::shared_ptr<const Node> left, right;
};

// Maximum nesting of parentheses and negations; deeper input is rejected (bounded recursion).
inline constexpr int kMaxExpressionDepth = 64;
// Maximum length of a rule's text. Bounds the tree (a chain of '&&' is a left-deep tree that
// evaluation and destruction walk recursively) and the cost of expanding a domain.
inline constexpr std::size_t kMaxExpressionLength = 1024;

// Parses `text`. `symbols[i]` names bit i. On error the diagnostic's column is 1-based within
// `text` and its message says what is wrong; the caller adds the file and line.
Result<Expression> parse_expression(std::string_view text, std::span<const std::string> symbols);

}  // namespace shadergen
