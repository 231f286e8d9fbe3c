#include "cli/view_commands.h"

#include <command_line/command_line.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include "cli/print_errors.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace shadergen {
namespace {

std::string value_names(const RawFeature& feature) {
  std::string text;
  for (const std::string& v : feature.values) text += (text.empty() ? "" : ", ") + v;
  return "(" + text + ")";
}

// A raw ID as a number (12, 0x0c, 0b1100) or feature names joined by '|', '+' or ','.
std::optional<std::uint32_t> parse_raw_id(const DomainSpec& spec, const std::string& text, std::string& why) {
  try {
    std::size_t used = 0;
    int base = 10;
    std::string digits = text;
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0)
      base = 16, digits = text.substr(2);
    else if (text.rfind("0b", 0) == 0)
      base = 2, digits = text.substr(2);
    if (base != 10 || (!digits.empty() && std::isdigit(static_cast<unsigned char>(digits[0])))) {
      unsigned long value = std::stoul(digits, &used, base);
      if (used != digits.size()) throw std::invalid_argument("trailing characters");
      if (value >= spec.raw_count()) {
        why = "raw ID " + text + " is out of range: domain " + spec.name + " has raw IDs 0 to " +
              std::to_string(spec.raw_count() - 1);
        return std::nullopt;
      }
      return static_cast<std::uint32_t>(value);
    }
  } catch (const std::exception&) {
    why = "\"" + text + "\" is not a raw ID (a number or feature names joined by '|')";
    return std::nullopt;
  }
  std::uint32_t id = 0;
  std::string name;
  // A boolean feature by name, or a valued one as NAME=VALUE.
  auto flush = [&]() -> bool {
    if (name.empty()) return true;
    std::string feature_name = name.substr(0, name.find('='));
    std::string value = feature_name.size() < name.size() ? name.substr(feature_name.size() + 1) : std::string();
    auto found = std::find_if(spec.raw_features.begin(), spec.raw_features.end(),
                              [&](const RawFeature& f) { return f.name == feature_name || f.define == feature_name; });
    if (found == spec.raw_features.end()) {
      why = "unknown raw feature \"" + feature_name + "\" (known: ";
      for (std::size_t i = 0; i < spec.raw_features.size(); ++i) why += (i ? ", " : "") + spec.raw_features[i].name;
      why += ")";
      return false;
    }
    auto index = std::find(found->values.begin(), found->values.end(), value);
    if (found->valued() && index == found->values.end()) {
      why = "\"" + name + "\": " + found->name + " has values " + value_names(*found) + "; write " + found->name +
            "=<value>";
      return false;
    }
    id |= found->valued() ? static_cast<std::uint32_t>(index - found->values.begin()) << found->bit : 1u << found->bit;
    name.clear();
    return true;
  };
  for (char c : text) {
    if (c == '|' || c == '+' || c == ',') {
      if (!flush()) return std::nullopt;
    } else if (c != ' ') {
      name += c;
    }
  }
  if (!flush()) return std::nullopt;
  return id;
}

// Loads and expands the spec, then shows it; errors in the spec are printed and give 1.
template <class Show>
int load_and_show(const std::string& spec_path, std::ostream& out, std::ostream& err, Show show) {
  auto spec = load_domain(spec_path);
  if (!spec) return print_errors(spec.errors(), err);
  auto plan = expand(*spec);
  if (!plan) return print_errors(plan.errors(), err);
  return show(*spec, *plan, out);
}

}  // namespace

ViewCommands add_view_commands(CLI::App& app, ViewArgs& args) {
  ViewCommands commands;
  commands.lut = app.add_subcommand("lut", "Print the raw -> optimised lookup table");
  commands.lut->add_option("spec", args.spec_path, "Domain spec (JSON)")->required();
  commands.list = app.add_subcommand("list", "List every raw and optimised permutation with its defines");
  commands.list->add_option("spec", args.spec_path, "Domain spec (JSON)")->required();
  commands.explain = app.add_subcommand("explain", "Explain what a raw ID means and which optimised ID it maps to");
  commands.explain->add_option("spec", args.spec_path, "Domain spec (JSON)")->required();
  commands.explain->add_option("raw-id", args.raw_id, "A raw ID: 83, 0x53, or names such as SKY|SUN_LIGHT")->required();
  return commands;
}

int run_view(const ViewCommands& commands, const ViewArgs& args, std::ostream& out, std::ostream& err) {
  if (*commands.lut)
    return load_and_show(args.spec_path, out, err, [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
      o << format_lut(s, p);
      return command_line::kExitSuccess;
    });
  if (*commands.list)
    return load_and_show(args.spec_path, out, err, [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
      o << format_list(s, p);
      return command_line::kExitSuccess;
    });
  return load_and_show(args.spec_path, out, err, [&](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
    std::string why;
    auto id = parse_raw_id(s, args.raw_id, why);
    if (!id) {
      err << "shadergen: error: " << why << '\n';
      return command_line::kExitUsage;
    }
    o << format_explanation(s, p, *id);
    return command_line::kExitSuccess;
  });
}

}  // namespace shadergen
