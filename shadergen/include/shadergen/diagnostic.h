// shadergen/diagnostic.h - the library's one error model.
//
// Every fallible library call returns Result<T>: either the value or a non-empty list of
// diagnostics. A diagnostic carries where the problem is (file, line, column when known) and,
// for shader compilation, which permutations it occurs in. The CLI prints them as
// `file:line: error: message` and exits non-zero; nothing in the library prints or exits.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace shadergen {

enum class Severity { error, warning, note };

struct Diagnostic {
  Severity severity = Severity::error;
  std::string file;     // empty when the problem is not tied to a file
  int line = 0;         // 1-based; 0 = unknown
  int column = 0;       // 1-based; 0 = unknown
  std::string message;  // one line, no trailing period needed

  // "file:line:column: error: message", dropping the parts that are unknown.
  std::string to_string() const;
};

Diagnostic make_error(std::string file, int line, std::string message);
Diagnostic make_error(std::string message);

using Diagnostics = std::vector<Diagnostic>;

// A value or the diagnostics explaining why there is none. Precondition for value(): ok().
template <class T>
class Result {
 public:
  Result(T value) : state_(std::move(value)) {}
  Result(Diagnostic error) : state_(Diagnostics{std::move(error)}) {}
  Result(Diagnostics errors) : state_(std::move(errors)) { assert(!std::get<1>(state_).empty()); }

  bool ok() const { return state_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & { return std::get<0>(state_); }
  const T& value() const& { return std::get<0>(state_); }
  T&& value() && { return std::get<0>(std::move(state_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  const Diagnostics& errors() const { return std::get<1>(state_); }
  Diagnostics&& take_errors() && { return std::get<1>(std::move(state_)); }

 private:
  std::variant<T, Diagnostics> state_;
};

// Result for operations with no value.
struct Ok {};
using Status = Result<Ok>;

}  // namespace shadergen
