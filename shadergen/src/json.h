// json.h - a small JSON reader that remembers where every value came from. (manifest.json and
// stats.json are written with nlohmann::ordered_json.)
//
// The domain spec is JSON, and a rendering engineer fixing a spec wants "split_second.json:41:
// error: ..." rather than "key not found". Debian's JSON libraries do not report value
// positions, so the reader is our own. It is strict RFC 8259 (no comments, no trailing commas)
// and bounded: at most kMaxJsonDepth nested containers, kMaxJsonValues values and kMaxJsonBytes
// of input, so hostile input cannot exhaust the stack or memory (a value takes ~100 bytes, so
// without the count a 1 MiB array of zeros would take ~100 MiB).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadergen/diagnostic.h"

namespace shadergen::json {

inline constexpr int kMaxJsonDepth = 32;
inline constexpr std::size_t kMaxJsonBytes = 1u << 20;  // 1 MiB
inline constexpr std::size_t kMaxJsonValues = 65536;    // a real spec has a few hundred

enum class Type { null, boolean, number, string, array, object };

const char* type_name(Type type);

// A struct rather than std::pair<std::string, Value>: Clang with libstdc++ rejects the pair
// while Value is still incomplete (it instantiates the pair inside Value's own definition).
struct Member;

struct Value {
  Type type = Type::null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<Value> array;
  std::vector<Member> object;  // in document order; duplicate keys are rejected
  int line = 0;                // where the value starts, 1-based
  int column = 0;

  // Precondition: type == Type::object. Returns nullptr when the key is absent.
  const Value* find(std::string_view key) const;
};

struct Member {
  std::string first;  // the key
  Value second;
};

// Parses `text`; diagnostics name `file` and the line and column at fault.
Result<Value> parse(std::string_view text, const std::string& file);

}  // namespace shadergen::json
