// cpp_names.h - the names a spec gives that become C++ names in the generated registry: feature
// names (members of Features, raw_bit:: constants, <NAME>_value, to_<NAME>), their values
// (enumerators) and optimised bit names (optimised_bit:: constants). A name that is a C++
// keyword, a reserved identifier, or one the generated code already uses would make a header
// that fails to compile far from the spec (or, worse, compiles with another meaning), so the
// spec loader refuses it where it is written.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shadergen {

struct RawFeature;

// A valued feature's value as an enumerator: an identifier as written, an integer with a
// leading underscore (2 -> _2, -1 -> _m1). Precondition: `value` is an identifier or an
// integer's decimal text, as the spec reader accepts.
std::string enumerator_name(std::string_view value);

// Why identifier `name` cannot be a C++ name of the generated code at all: a C++20 keyword or
// alternative token ("and", "not"), or reserved to the implementation (a leading underscore
// and a capital letter, or a double underscore anywhere); "" when it can. Precondition:
// `name` is an identifier.
std::string cpp_identifier_problem(std::string_view name);

// Why identifier `name` cannot be a raw feature's name: cpp_identifier_problem(), or a name the
// generated namespace declares itself (Features, RawId, registry, kRawBits, ...); "" when it can.
std::string feature_name_problem(std::string_view name);

// A name of the spec that clashes with a name the generated code derives from another one.
struct NameClash {
  std::size_t feature = 0;  // index into the features given
  std::size_t value = 0;    // kind == value: index into that feature's values
  enum class Kind { name, value } kind = Kind::name;
  std::string message;
};

// The clashes between `features` (in spec order, names already free of the problems above):
// two values of one feature that become the same enumerator ("-1" and "_m1"), and a feature
// name that is another valued feature's <NAME>_value, to_<NAME>, <NAME>_shift or <NAME>_mask.
// Each clash is reported once, on the later of the two (the value, or the feature).
std::vector<NameClash> generated_name_clashes(const std::vector<RawFeature>& features);

}  // namespace shadergen
