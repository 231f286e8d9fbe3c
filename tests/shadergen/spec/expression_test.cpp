// The rule language: precedence, negation, grouping, and errors that point at a column.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadergen/expression.h"

namespace shadergen {
namespace {

const std::vector<std::string> kSymbols = {"A", "B", "C"};

bool eval(const std::string& text, std::uint32_t bits) {
  auto e = parse_expression(text, kSymbols);
  EXPECT_TRUE(e.ok()) << text << ": " << (e.ok() ? "" : e.errors().front().message);
  return e.ok() && e->evaluate(bits);
}

struct TruthCase {
  const char* text;
  std::uint32_t true_for;  // bit i set = true for the bit pattern i (3 symbols: patterns 0..7)
};

// Show the rule text in test names and messages, not the bytes of the struct.
void PrintTo(const TruthCase& c, std::ostream* os) { *os << '"' << c.text << '"'; }

class TruthTable : public ::testing::TestWithParam<TruthCase> {};

TEST_P(TruthTable, MatchesForAllAssignments) {
  for (std::uint32_t bits = 0; bits < 8; ++bits)
    EXPECT_EQ(eval(GetParam().text, bits), ((GetParam().true_for >> bits) & 1u) != 0)
        << GetParam().text << " with bits " << bits;
}

// Patterns: bit0 = A, bit1 = B, bit2 = C; true_for has bit `pattern` set when true.
INSTANTIATE_TEST_SUITE_P(Rules, TruthTable,
                         ::testing::Values(TruthCase{"A", 0b10101010}, TruthCase{"!A", 0b01010101},
                                           TruthCase{"A && B", 0b10001000}, TruthCase{"A || B", 0b11101110},
                                           // && binds tighter than ||: A || (B && C)
                                           TruthCase{"A || B && C", 0b11101010}, TruthCase{"(A || B) && C", 0b11100000},
                                           TruthCase{"!(A && B)", 0b01110111}, TruthCase{"!!A", 0b10101010},
                                           TruthCase{"true", 0xFF}, TruthCase{"false", 0x00},
                                           TruthCase{"  A&&!B  ", 0b00100010}));

struct ErrorCase {
  const char* text;
  int column;
  const char* message;
};

void PrintTo(const ErrorCase& c, std::ostream* os) { *os << '"' << c.text << '"'; }

class ExpressionErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(ExpressionErrors, PointAtTheColumn) {
  auto e = parse_expression(GetParam().text, kSymbols);
  ASSERT_FALSE(e.ok()) << GetParam().text;
  EXPECT_EQ(e.errors().front().column, GetParam().column) << e.errors().front().message;
  EXPECT_EQ(e.errors().front().message, GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(Rules, ExpressionErrors,
                         ::testing::Values(ErrorCase{"A && D", 6, "unknown name 'D' (known: A, B, C)"},
                                           ErrorCase{"", 1, "empty expression"}, ErrorCase{"(A", 3, "missing ')'"},
                                           ErrorCase{"A B", 3, "unexpected 'B'"},
                                           ErrorCase{"A & B", 3, "'&' is not an operator; use '&&' or '||'"}));

TEST(Expression, DepthLimitIsEnforced) {
  std::string deep = std::string(kMaxExpressionDepth + 1, '(') + "A" + std::string(kMaxExpressionDepth + 1, ')');
  auto e = parse_expression(deep, kSymbols);
  ASSERT_FALSE(e.ok());
  std::string shallow = std::string(10, '(') + "A" + std::string(10, ')');
  EXPECT_TRUE(parse_expression(shallow, kSymbols).ok());
}

TEST(Expression, PrintsWithNames) {
  auto e = parse_expression("!(A && B) || C", kSymbols);
  ASSERT_TRUE(e.ok());
  EXPECT_EQ(e->to_string(), "!(A && B) || C");
}

}  // namespace
}  // namespace shadergen
