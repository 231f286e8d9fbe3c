#include "cli/view_commands.h"

#include <command_line/command_line.h>

#include <charconv>
#include <cstdint>
#include <optional>
#include <string_view>

#include "cli/print_errors.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "spec/combination_text.h"
#include "spec/variants_file.h"

namespace shadergen {
namespace {

// The value of a whole argument that is a number (12, 0x0c, 0b1100; blanks around it are
// allowed), saturated at 2^32 so that a long one still reads as out of range; nullopt for
// anything else, which then goes to the features' grammar.
std::optional<std::uint64_t> raw_number(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X' || text[1] == 'b' || text[1] == 'B')) {
    base = (text[1] == 'x' || text[1] == 'X') ? 16 : 2;
    text.remove_prefix(2);
  }
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  auto [stop, error] = std::from_chars(text.data(), end, value, base);
  if (text.empty() || stop != end) return std::nullopt;
  if (error == std::errc::result_out_of_range) return std::uint64_t{1} << 32;
  if (error != std::errc{}) return std::nullopt;
  return value;
}

// explain's argument: a raw ID as a number of its own, or features in the one grammar of
// shadergen/registry.h (parse_combination), its errors worded by describe_combination_error().
std::optional<std::uint32_t> parse_raw_id(const DomainSpec& spec, const std::string& text, std::string& why) {
  if (std::optional<std::uint64_t> number = raw_number(text)) {
    if (*number < spec.raw_space()) return static_cast<std::uint32_t>(*number);
    why = "raw ID " + text + " is out of range: domain " + spec.name + " has raw IDs 0 to " +
          std::to_string(spec.raw_space() - 1);
    return std::nullopt;
  }
  const FeatureTable table(spec);
  const ParsedCombination parsed = parse_combination(table.features(), text);
  if (!parsed) {
    why = describe_combination_error(parsed, table.features());
    return std::nullopt;
  }
  return parsed.raw_id;
}

// Loads and expands the spec, then shows it; errors in the spec are printed and give 1.
template <class Show>
int load_and_show(const ViewArgs& args, std::ostream& out, std::ostream& err, Show show) {
  auto spec = load_domain(args.spec_path);
  if (!spec) return print_errors(spec.errors(), err);
  for (const Diagnostic& warning : spec->warnings) err << warning.to_string() << '\n';
  if (auto listed = read_variants_file(*spec, args.variants_path); !listed) return print_errors(listed.errors(), err);
  auto plan = expand(*spec);
  if (!plan) return print_errors(plan.errors(), err);
  return show(*spec, *plan, out);
}

}  // namespace

namespace {

void add_spec_options(CLI::App& command, ViewArgs& args) {
  command.add_option("spec", args.spec_path, "Domain spec (JSON)")->required();
  command.add_option("--variants", args.variants_path,
                     "Variants file: the raw combinations the domain builds, one per line (replaces the spec's "
                     "\"variants_file\")");
}

}  // namespace

ViewCommands add_view_commands(CLI::App& app, ViewArgs& args) {
  ViewCommands commands;
  commands.lut = app.add_subcommand(
      "lut", "Print the raw -> optimised lookup table (with a variants file: one row per listed raw ID)");
  add_spec_options(*commands.lut, args);
  commands.list = app.add_subcommand(
      "list", "List every raw and optimised permutation with its defines (with a variants file: the listed ones)");
  add_spec_options(*commands.list, args);
  commands.explain =
      app.add_subcommand("explain", "Explain what a raw ID means and which optimised ID it maps to, built or not");
  add_spec_options(*commands.explain, args);
  commands.explain->add_option("raw-id", args.raw_id, "A raw ID: 83, 0x53, or feature names such as SKY|SUN_LIGHT")
      ->required();
  return commands;
}

int run_view(const ViewCommands& commands, const ViewArgs& args, std::ostream& out, std::ostream& err) {
  if (*commands.lut)
    return load_and_show(args, out, err, [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
      o << format_lut(s, p);
      return command_line::kExitSuccess;
    });
  if (*commands.list)
    return load_and_show(args, out, err, [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
      o << format_list(s, p);
      return command_line::kExitSuccess;
    });
  return load_and_show(args, out, err, [&](const DomainSpec& s, const PermutationPlan& p, std::ostream& o) {
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
