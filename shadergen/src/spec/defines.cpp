#include "spec/defines.h"

#include <algorithm>
#include <cctype>

namespace shadergen {

namespace {
constexpr std::size_t kMaxDefineValueLength = 1024;
}

bool is_identifier(std::string_view text) {
  if (text.empty() || text.size() > 64) return false;
  if (!(std::isalpha(static_cast<unsigned char>(text[0])) || text[0] == '_')) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string_view define_name(std::string_view define) { return define.substr(0, define.find('=')); }

std::string define_line(std::string_view define) {
  std::size_t equals = define.find('=');
  if (equals == std::string_view::npos) return "#define " + std::string(define) + " 1\n";
  return "#define " + std::string(define.substr(0, equals)) + " " + std::string(define.substr(equals + 1)) + "\n";
}

std::string define_name_problem(std::string_view name) {
  if (!is_identifier(name))
    return std::string("\"").append(name).append("\" is not an identifier ([A-Za-z_][A-Za-z0-9_]*, at most 64)");
  // GLSL reserves these for the implementation; glslang rejects them in a #define.
  if (name.rfind("GL_", 0) == 0 || name.find("__") != std::string_view::npos)
    return std::string("\"").append(name).append("\" is reserved by GLSL (a GL_ prefix or a double underscore)");
  return {};
}

std::string define_value_problem(std::string_view value) {
  if (value.size() > kMaxDefineValueLength)
    return "the value is " + std::to_string(value.size()) + " characters long; the limit is " +
           std::to_string(kMaxDefineValueLength);
  bool control = std::any_of(value.begin(), value.end(),
                             [](char c) { return std::iscntrl(static_cast<unsigned char>(c)) && c != '\t'; });
  if (control) return "the value holds a line break or another control character; it must fit on the #define line";
  return {};
}

Result<std::string> parse_define_argument(std::string_view argument) {
  std::string_view name = define_name(argument);
  bool has_value = name.size() < argument.size();
  std::string_view value = has_value ? argument.substr(name.size() + 1) : std::string_view("1");
  std::string problem = define_name_problem(name);
  if (problem.empty()) problem = define_value_problem(value);
  if (!problem.empty()) return make_error("--define " + std::string(argument) + ": " + problem);
  return std::string(name) + "=" + std::string(value);
}

std::vector<std::string> override_defines(std::vector<std::string> base, const std::vector<std::string>& overrides) {
  for (const std::string& define : overrides) {
    auto same_name = [&](const std::string& d) { return define_name(d) == define_name(define); };
    auto found = std::find_if(base.begin(), base.end(), same_name);
    if (found != base.end())
      *found = define;
    else
      base.push_back(define);
  }
  return base;
}

}  // namespace shadergen
