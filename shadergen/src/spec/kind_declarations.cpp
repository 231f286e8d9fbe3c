#include "spec/kind_declarations.h"

#include <algorithm>
#include <map>
#include <set>

#include "spec/defines.h"

namespace shadergen {

namespace {

bool numeric(const RawFeature& f) { return f.valued() && !is_identifier(f.values.front()); }

// Identifier values as constants of their index: macros for value-style variants (so that
// `#if SHADING == PBR` works), `const int` for the other kinds (read as expressions). The
// spec checks that one name never stands for two indices.
void identifier_values(const std::vector<const RawFeature*>& features, KindDeclarations& out) {
  std::set<std::string> declared;
  for (const RawFeature* f : features) {
    if (!f->is_variant() || f->define_style != DefineStyle::value || numeric(*f)) continue;
    for (std::size_t i = 0; i < f->values.size(); ++i)
      if (declared.insert(f->values[i]).second)
        out.macros += "#define " + f->values[i] + " " + std::to_string(i) + "\n";
  }
  for (const RawFeature* f : features) {
    if (f->is_variant() || !f->valued() || numeric(*f)) continue;
    for (std::size_t i = 0; i < f->values.size(); ++i)
      if (declared.insert(f->values[i]).second)
        out.declarations += "const int " + f->values[i] + " = " + std::to_string(i) + ";\n";
  }
}

void specialization_constants(const std::vector<const RawFeature*>& features, KindDeclarations& out) {
  for (const RawFeature* f : features) {
    if (f->kind != FeatureKind::specialization) continue;
    out.declarations += "layout(constant_id = " + std::to_string(f->constant_id) + ") const " +
                        (f->valued() ? "int " : "bool ") + f->define + " = " +
                        (f->valued() ? std::to_string(value_number(*f, 0)) : std::string("false")) + ";\n";
  }
}

void branch_block(const DomainSpec& spec, const std::vector<const RawFeature*>& features, KindDeclarations& out) {
  if (!spec.branch_block) return;
  std::string members, readers;
  const std::string instance(kBranchBlockInstance);
  for (const RawFeature* f : features) {
    if (f->kind != FeatureKind::branch) continue;
    members += "  uint " + f->define + ";\n";
    // After the block, or the member's own declaration would expand it. The macro's name inside
    // its body is not expanded again, so it reaches the member.
    readers +=
        "#define " + f->define + " " +
        (f->valued() ? "int(" + instance + "." + f->define + ")" : "(" + instance + "." + f->define + " != 0u)") + "\n";
  }
  out.declarations += "layout(std140, set = " + std::to_string(spec.branch_block->set) +
                      ", binding = " + std::to_string(spec.branch_block->binding) + ") uniform " +
                      std::string(kBranchBlockType) + " {\n" + members + "} " + instance + ";\n" + readers;
}

// A value-style boolean is written `(1 == 1)` or `(0 == 1)`, not 1 or 0: both `#if NAME` and
// `if (NAME)` read that, as `if (NAME)` reads a specialization constant or a branch.
void value_booleans(const std::vector<const RawFeature*>& features, KindDeclarations& out) {
  for (const RawFeature* f : features)
    if (f->is_variant() && !f->valued() && f->define_style == DefineStyle::value) out.value_booleans.insert(f->define);
}

}  // namespace

std::int32_t value_number(const RawFeature& f, std::uint32_t index) {
  if (!numeric(f)) return static_cast<std::int32_t>(index);
  return static_cast<std::int32_t>(std::stoll(f.values[index]));
}

KindDeclarations kind_declarations(const DomainSpec& spec) {
  KindDeclarations out;
  std::vector<const RawFeature*> features = spec.features_in_spec_order();
  identifier_values(features, out);
  specialization_constants(features, out);
  branch_block(spec, features, out);
  value_booleans(features, out);
  return out;
}

namespace {

// Where the line after `#version` starts, and that line's number; {0, 1} without one. Only
// blank lines, comments and other directives may come before `#version`.
std::pair<std::size_t, int> after_version(std::string_view text) {
  std::size_t at = 0;
  int line = 1;
  bool in_comment = false;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    std::size_t next = end == std::string_view::npos ? text.size() : end + 1;
    std::string_view content = text.substr(at, next - at);
    std::size_t first = content.find_first_not_of(" \t\r\n");
    if (in_comment) {
      in_comment = content.find("*/") == std::string_view::npos;
    } else if (first != std::string_view::npos) {
      std::string_view trimmed = content.substr(first);
      if (trimmed.rfind("/*", 0) == 0) {
        in_comment = trimmed.find("*/", 2) == std::string_view::npos;
      } else if (trimmed.rfind('#', 0) == 0) {
        std::string_view directive = trimmed.substr(1);
        directive.remove_prefix(std::min(directive.find_first_not_of(" \t"), directive.size()));
        if (directive.rfind("version", 0) == 0) return {next, line + 1};
      } else if (trimmed.rfind("//", 0) != 0) {
        return {0, 1};  // code before any #version: the shader has none
      }
    }
    at = next;
    ++line;
  }
  return {0, 1};
}

}  // namespace

std::vector<std::string> boolean_value_defines(std::vector<std::string> defines, const KindDeclarations& kinds) {
  if (kinds.value_booleans.empty()) return defines;
  for (std::string& define : defines) {
    std::string_view name = define_name(define);
    if (!kinds.value_booleans.count(std::string(name))) continue;
    const bool on = std::string_view(define).substr(name.size()) == "=1";
    define = std::string(name) + (on ? "=(1 == 1)" : "=(0 == 1)");
  }
  return defines;
}

std::string insert_declarations(std::string_view text, std::string_view declarations) {
  if (declarations.empty()) return std::string(text);
  auto [at, next_line] = after_version(text);
  std::string out(text.substr(0, at));
  if (at > 0 && out.back() != '\n') out += '\n';
  out += declarations;
  out += "#line " + std::to_string(next_line) + "\n";
  out += text.substr(at);
  return out;
}

}  // namespace shadergen
