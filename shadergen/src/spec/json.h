// json.h - the spec's JSON reader: every value keeps the line and column it came from.
//
// The domain spec is JSON, and a rendering engineer fixing a spec wants "split_second.json:41:
// error: ..." at the value that is wrong, not "key not found". Why a reader of our own:
// - nlohmann::json 3.11 (Debian 12), which writes manifest.json and stats.json, says where a
//   syntax error is (its byte offset, and line and column in the message), but a value it has
//   parsed does not record where it came from, and a wrong value is most of what we report.
// - libjsoncpp (Debian's libjsoncpp-dev) does record where each value starts and ends
//   (Json::Value::getOffsetStart()), but it keeps an object's members in a std::map, sorted by
//   key, and document order matters to us: the top-level `defines` object is the order of the
//   `#define` lines ahead of every shader, a companion's `defines` object is the order of its
//   defines in manifest.json, and unknown keys are reported in file order. It limits nesting
//   but not the number of values, and it would be one more package for ~340 lines.
// So the reader stays ours. It is strict RFC 8259: no comments, no trailing commas, UTF-8 only
// (a leading byte order mark is skipped, as RFC 8259 allows), and a key that appears twice in
// one object is an error. It is bounded: at most kMaxJsonDepth nested containers,
// kMaxJsonValues values and kMaxJsonBytes of input, so hostile input cannot exhaust the stack
// or memory (a value takes ~100 bytes, so without the count a 1 MiB array of zeros would take
// ~100 MiB). tests/shadergen/spec/json_reader_agreement_test.cpp reads the fuzz corpus and a table
// of edge cases with this reader and with nlohmann: both accept the same documents and read
// the same values, except where our limits or a duplicate key reject a document nlohmann takes.
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
