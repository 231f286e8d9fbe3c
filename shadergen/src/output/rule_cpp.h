// rule_cpp.h - a spec rule as C++: the generated is_possible() tests the "impossible" rules
// themselves, so that it holds for every raw ID, also in a domain whose variants file leaves
// most raw IDs out of the tables.
#pragma once

#include <string>
#include <string_view>

#include "shadergen/domain.h"

namespace shadergen {

// `rule` (over `spec`'s raw features) as a C++ boolean expression over the members of a
// generated Features value called `object`: a boolean feature is `object.NAME`, a comparison
// lists the value indices it accepts. Parenthesised as a whole. Precondition: `rule` was parsed
// against spec.raw_symbols(), so every symbol is the first bit of one of spec.raw_features.
std::string rule_as_cpp(const Expression& rule, const DomainSpec& spec, std::string_view object);

}  // namespace shadergen
