#include "shadergen/expression.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace shadergen {

using Node = Expression::Node;

bool Expression::evaluate(std::uint32_t bits) const {
  struct Eval {
    static bool run(const Node& n, std::uint32_t bits) {
      switch (n.kind) {
        case Node::Kind::constant: return n.constant;
        case Node::Kind::symbol: return (bits >> n.symbol) & 1u;
        case Node::Kind::comparison: {
          std::uint32_t index = (bits >> n.symbol) & ((1u << n.width) - 1u);
          return index < n.accepted.size() && n.accepted[index];
        }
        case Node::Kind::negation: return !run(*n.left, bits);
        case Node::Kind::conjunction: return run(*n.left, bits) && run(*n.right, bits);
        case Node::Kind::disjunction: return run(*n.left, bits) || run(*n.right, bits);
      }
      return false;
    }
  };
  return root_ && Eval::run(*root_, bits);
}

std::uint32_t Expression::symbol_mask() const {
  struct Walk {
    static std::uint32_t run(const Node& n) {
      switch (n.kind) {
        case Node::Kind::constant: return 0;
        case Node::Kind::symbol: return 1u << n.symbol;
        case Node::Kind::comparison:
          return static_cast<std::uint32_t>(((std::uint64_t{1} << n.width) - 1u) << n.symbol);
        case Node::Kind::negation: return run(*n.left);
        case Node::Kind::conjunction:
        case Node::Kind::disjunction: return run(*n.left) | run(*n.right);
      }
      return 0;
    }
  };
  return root_ ? Walk::run(*root_) : 0;
}

std::string Expression::to_string() const {
  struct Print {
    static int precedence(const Node& n) {
      switch (n.kind) {
        case Node::Kind::disjunction: return 1;
        case Node::Kind::conjunction: return 2;
        default: return 3;
      }
    }
    static std::string run(const Node& n, int outer) {
      std::string text;
      switch (n.kind) {
        case Node::Kind::constant: text = n.constant ? "true" : "false"; break;
        case Node::Kind::symbol: text = n.text; break;
        // A comparison binds tighter than '!', so "!(A == 1)" keeps its parentheses.
        case Node::Kind::comparison: text = outer == 3 ? "(" + n.text + ")" : n.text; break;
        case Node::Kind::negation: text = std::string("!").append(run(*n.left, 3)); break;
        case Node::Kind::conjunction: text = run(*n.left, 2) + " && " + run(*n.right, 2); break;
        case Node::Kind::disjunction: text = run(*n.left, 1) + " || " + run(*n.right, 1); break;
      }
      return precedence(n) < outer ? "(" + text + ")" : text;
    }
  };
  return root_ ? Print::run(*root_, 0) : "";
}

namespace {

class ExpressionParser {
 public:
  ExpressionParser(std::string_view text, std::span<const ExpressionSymbol> symbols) : text_(text), symbols_(symbols) {}

  Result<Expression> run() {
    if (text_.size() > kMaxExpressionLength) {
      pos_ = kMaxExpressionLength;
      return fail("rule is " + std::to_string(text_.size()) + " characters long; the limit is " +
                  std::to_string(kMaxExpressionLength));
    }
    auto root = parse_or(0);
    if (!root) return error_;
    skip_space();
    if (pos_ < text_.size()) {
      if (peek_operator("&") || peek_operator("|"))
        return fail(std::string("'").append(1, text_[pos_]).append("' is not an operator; use '&&' or '||'"));
      return fail(std::string("unexpected '").append(1, text_[pos_]).append("'"));
    }
    return Expression(std::move(root));
  }

 private:
  using NodePtr = std::shared_ptr<const Node>;

  Diagnostic fail(std::string message) {
    error_ = Diagnostic{Severity::error, {}, 0, static_cast<int>(pos_) + 1, std::move(message)};
    return error_;
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool peek_operator(std::string_view op) {
    skip_space();
    return text_.substr(pos_, op.size()) == op;
  }
  bool take_operator(std::string_view op) {
    if (!peek_operator(op)) return false;
    pos_ += op.size();
    return true;
  }

  static NodePtr binary(Node::Kind kind, NodePtr left, NodePtr right) {
    auto node = std::make_shared<Node>();
    node->kind = kind;
    node->left = std::move(left);
    node->right = std::move(right);
    return node;
  }

  NodePtr parse_or(int depth) {
    NodePtr left = parse_and(depth);
    while (left && take_operator("||")) {
      NodePtr right = parse_and(depth);
      if (!right) return nullptr;
      left = binary(Node::Kind::disjunction, left, right);
    }
    return left;
  }

  NodePtr parse_and(int depth) {
    NodePtr left = parse_unary(depth);
    while (left && take_operator("&&")) {
      NodePtr right = parse_unary(depth);
      if (!right) return nullptr;
      left = binary(Node::Kind::conjunction, left, right);
    }
    return left;
  }

  NodePtr parse_unary(int depth) {
    if (depth >= kMaxExpressionDepth) {
      fail("expression nested deeper than " + std::to_string(kMaxExpressionDepth) + " levels");
      return nullptr;
    }
    skip_space();
    if (pos_ >= text_.size()) {
      fail(text_.empty() || pos_ == 0 ? "empty expression" : "expression ends where an operand was expected");
      return nullptr;
    }
    if (take_operator("!")) {
      NodePtr operand = parse_unary(depth + 1);
      if (!operand) return nullptr;
      auto node = std::make_shared<Node>();
      node->kind = Node::Kind::negation;
      node->left = std::move(operand);
      return node;
    }
    if (take_operator("(")) {
      NodePtr inner = parse_or(depth + 1);
      if (!inner) return nullptr;
      if (!take_operator(")")) {
        fail("missing ')'");
        return nullptr;
      }
      return inner;
    }
    return parse_name();
  }

  NodePtr parse_name() {
    std::size_t start = pos_;
    auto is_name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    if (!(std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) {
      fail("expected a feature name, '!' or '(' but found '" + std::string(1, text_[pos_]) + "'");
      return nullptr;
    }
    while (pos_ < text_.size() && is_name_char(text_[pos_])) ++pos_;
    std::string_view name = text_.substr(start, pos_ - start);
    auto node = std::make_shared<Node>();
    if (name == "true" || name == "false") {
      node->kind = Node::Kind::constant;
      node->constant = name == "true";
      return node;
    }
    for (const ExpressionSymbol& symbol : symbols_) {
      if (symbol.name != name) continue;
      std::size_t after_name = pos_;
      std::string op = take_comparison();
      if (op.empty() && symbol.values.empty()) {
        node->kind = Node::Kind::symbol;
        node->symbol = symbol.bit;
        node->text = symbol.name;
        return node;
      }
      if (op.empty()) {
        pos_ = after_name;
        fail("'" + symbol.name + "' has values (" + join_values(symbol) + "); compare it, e.g. " + symbol.name +
             " == " + symbol.values.front());
        return nullptr;
      }
      return parse_comparison(symbol, op, start);
    }
    pos_ = start;
    std::string known;
    for (const ExpressionSymbol& symbol : symbols_) known += (known.empty() ? "" : ", ") + symbol.name;
    fail("unknown name '" + std::string(name) + "' (known: " + known + ")");
    return nullptr;
  }

  // The comparison operator at the cursor, taken; empty when there is none.
  std::string take_comparison() {
    for (std::string_view op : {"==", "!=", "<=", ">=", "<", ">"})
      if (take_operator(op)) return std::string(op);
    return {};
  }

  static std::string join_values(const ExpressionSymbol& symbol) {
    std::string text;
    for (const std::string& v : symbol.values) text += (text.empty() ? "" : ", ") + v;
    return text;
  }

  static bool is_integer(std::string_view text) {
    std::size_t digits = !text.empty() && text[0] == '-' ? 1 : 0;
    return text.size() > digits && text.size() <= digits + 9 &&
           std::all_of(text.begin() + static_cast<std::ptrdiff_t>(digits), text.end(),
                       [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  }

  static bool holds(std::string_view op, long long a, long long b) {
    if (op == "==") return a == b;
    if (op == "!=") return a != b;
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    return a >= b;
  }

  // "NAME OP VALUE" once NAME and OP are read: checks VALUE against the symbol's values and
  // works out which value indices satisfy it.
  NodePtr parse_comparison(const ExpressionSymbol& symbol, const std::string& op, std::size_t start) {
    skip_space();
    std::size_t value_start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
                                   (pos_ == value_start && text_[pos_] == '-')))
      ++pos_;
    std::string value(text_.substr(value_start, pos_ - value_start));
    if (value.empty()) {
      fail("expected a value after '" + op + "'");
      return nullptr;
    }
    bool number = is_integer(value);
    if (symbol.values.empty()) {
      pos_ = start;
      fail("'" + symbol.name + "' is a boolean feature; it cannot be compared with " +
           (number ? "a number" : "a value") + " (write " + symbol.name + " or !" + symbol.name + ")");
      return nullptr;
    }
    bool ordered = op != "==" && op != "!=";
    bool numeric_values = std::all_of(symbol.values.begin(), symbol.values.end(), is_integer);
    if (ordered && !(number && numeric_values)) {
      pos_ = value_start;
      fail("'" + op + "' needs integer values; " + symbol.name + " has values (" + join_values(symbol) + ") and " +
           value + " is compared; use '==' or '!='");
      return nullptr;
    }
    auto found = std::find(symbol.values.begin(), symbol.values.end(), value);
    if (!ordered && found == symbol.values.end()) {
      pos_ = value_start;
      fail("'" + symbol.name + "' has no value " + value + " (values: " + join_values(symbol) + ")");
      return nullptr;
    }
    auto node = std::make_shared<Node>();
    node->kind = Node::Kind::comparison;
    node->symbol = symbol.bit;
    node->width = symbol.width;
    node->text = symbol.name + " " + op + " " + value;
    for (const std::string& candidate : symbol.values)
      node->accepted.push_back(ordered ? holds(op, std::stoll(candidate), std::stoll(value))
                                       : (candidate == value) == (op == "=="));
    return node;
  }

  std::string_view text_;
  std::span<const ExpressionSymbol> symbols_;
  std::size_t pos_ = 0;
  Diagnostic error_;
};

}  // namespace

Result<Expression> parse_expression(std::string_view text, std::span<const ExpressionSymbol> symbols) {
  return ExpressionParser(text, symbols).run();
}

Result<Expression> parse_expression(std::string_view text, std::span<const std::string> symbols) {
  std::vector<ExpressionSymbol> booleans;
  for (std::size_t i = 0; i < symbols.size(); ++i)
    booleans.push_back({symbols[i], static_cast<std::uint32_t>(i), 1, {}});
  return parse_expression(text, booleans);
}

}  // namespace shadergen
