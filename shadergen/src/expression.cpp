#include "shadergen/expression.h"

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
                case Node::Kind::negation: return !run(*n.left, bits);
                case Node::Kind::conjunction: return run(*n.left, bits) && run(*n.right, bits);
                case Node::Kind::disjunction: return run(*n.left, bits) || run(*n.right, bits);
            }
            return false;
        }
    };
    return root_ && Eval::run(*root_, bits);
}

std::string Expression::to_string(std::span<const std::string> symbols) const {
    struct Print {
        static int precedence(const Node& n) {
            switch (n.kind) {
                case Node::Kind::disjunction: return 1;
                case Node::Kind::conjunction: return 2;
                default: return 3;
            }
        }
        static std::string run(const Node& n, std::span<const std::string> symbols, int outer) {
            std::string text;
            switch (n.kind) {
                case Node::Kind::constant: text = n.constant ? "true" : "false"; break;
                case Node::Kind::symbol: text = n.symbol < symbols.size() ? symbols[n.symbol] : "?"; break;
                case Node::Kind::negation: text = "!" + run(*n.left, symbols, 3); break;
                case Node::Kind::conjunction:
                    text = run(*n.left, symbols, 2) + " && " + run(*n.right, symbols, 2);
                    break;
                case Node::Kind::disjunction:
                    text = run(*n.left, symbols, 1) + " || " + run(*n.right, symbols, 1);
                    break;
            }
            return precedence(n) < outer ? "(" + text + ")" : text;
        }
    };
    return root_ ? Print::run(*root_, symbols, 0) : "";
}

namespace {

class ExpressionParser {
public:
    ExpressionParser(std::string_view text, std::span<const std::string> symbols)
        : text_(text), symbols_(symbols) {}

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
                return fail("'" + std::string(1, text_[pos_]) + "' is not an operator; use '&&' or '||'");
            return fail("unexpected '" + std::string(1, text_[pos_]) + "'");
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
        for (std::size_t i = 0; i < symbols_.size(); ++i) {
            if (symbols_[i] == name) {
                node->kind = Node::Kind::symbol;
                node->symbol = static_cast<std::uint32_t>(i);
                return node;
            }
        }
        pos_ = start;
        std::string known;
        for (const std::string& symbol : symbols_) known += (known.empty() ? "" : ", ") + symbol;
        fail("unknown name '" + std::string(name) + "' (known: " + known + ")");
        return nullptr;
    }

    std::string_view text_;
    std::span<const std::string> symbols_;
    std::size_t pos_ = 0;
    Diagnostic error_;
};

}  // namespace

Result<Expression> parse_expression(std::string_view text, std::span<const std::string> symbols) {
    return ExpressionParser(text, symbols).run();
}

}  // namespace shadergen
