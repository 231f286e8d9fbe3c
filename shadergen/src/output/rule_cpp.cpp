#include "output/rule_cpp.h"

namespace shadergen {
namespace {

using Node = Expression::Node;

class RuleWriter {
 public:
  RuleWriter(const DomainSpec& spec, std::string_view object) : spec_(spec), object_(object) {}

  std::string run(const Node& n) const {
    switch (n.kind) {
      case Node::Kind::constant: return n.constant ? "true" : "false";
      case Node::Kind::symbol: return member(n.symbol);
      case Node::Kind::comparison: return comparison(n);
      case Node::Kind::negation: return "!" + run(*n.left);
      case Node::Kind::conjunction: return "(" + run(*n.left) + " && " + run(*n.right) + ")";
      case Node::Kind::disjunction: return "(" + run(*n.left) + " || " + run(*n.right) + ")";
    }
    return "false";
  }

 private:
  // The feature whose field starts at `bit`: the parser resolved each name to it.
  std::string member(std::uint32_t bit) const {
    for (const RawFeature& f : spec_.raw_features)
      if (f.bit == bit) return std::string(object_) + "." + f.name;
    return "false";  // unreachable for a rule parsed against the spec's symbols
  }

  // A comparison was worked out at parse time into the value indices it accepts, so the C++
  // tests the index (the enum's underlying value), never the value's text or order.
  std::string comparison(const Node& n) const {
    const std::string index = "static_cast<std::uint32_t>(" + member(n.symbol) + ")";
    std::string text;
    for (std::size_t i = 0; i < n.accepted.size(); ++i) {
      if (!n.accepted[i]) continue;
      text += (text.empty() ? "" : " || ") + index + " == " + std::to_string(i) + "u";
    }
    return text.empty() ? "false" : "(" + text + ")";
  }

  const DomainSpec& spec_;
  std::string_view object_;
};

}  // namespace

std::string rule_as_cpp(const Expression& rule, const DomainSpec& spec, std::string_view object) {
  if (!rule.root()) return "false";
  const std::string text = RuleWriter(spec, object).run(*rule.root());
  return text.front() == '(' ? text : "(" + text + ")";
}

}  // namespace shadergen
