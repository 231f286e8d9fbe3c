// json.h - a small JSON reader that remembers where every value came from, and a writer with
// deterministic output.
//
// The domain spec is JSON, and a rendering engineer fixing a spec wants "split_second.json:41:
// error: ..." rather than "key not found". Debian's JSON libraries do not report value
// positions, so the reader is our own. It is strict RFC 8259 (no comments, no trailing commas)
// and bounded: at most kMaxJsonDepth nested containers, kMaxJsonValues values and kMaxJsonBytes
// of input, so hostile input cannot exhaust the stack or memory (a value takes ~100 bytes, so
// without the count a 1 MiB array of zeros would take ~100 MiB).
#pragma once

#include <cstddef>
#include <cstdint>
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

// Writes JSON with two-space indentation, keys in insertion order, "\n" line ends.
class Writer {
 public:
  void begin_object();
  void end_object();
  void begin_array();
  void end_array();
  void key(std::string_view name);
  void value(std::string_view text);
  void value(const char* text) { value(std::string_view(text)); }
  void value(std::int64_t number);
  void value(std::uint32_t number) { value(static_cast<std::int64_t>(number)); }
  void value(int number) { value(static_cast<std::int64_t>(number)); }
  void value(double number);
  void value(bool flag);
  void null();
  // Arrays of scalars are written on one line; this keeps manifests readable.
  void inline_string_array(const std::vector<std::string>& items);

  std::string take();

 private:
  void before_value();
  void newline();

  std::string out_;
  std::vector<bool> first_in_container_;
  bool after_key_ = false;
};

std::string quote(std::string_view text);

}  // namespace shadergen::json
