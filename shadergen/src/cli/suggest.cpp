#include "cli/suggest.h"

#include <algorithm>

namespace shadergen {
std::optional<std::string> misspelt_name(CLI::App& app, const std::vector<std::string>& args) {
  if (args.empty() || args[0].empty() || args[0][0] == '-') return std::nullopt;
  std::vector<std::string> subcommands;
  CLI::App* chosen = nullptr;
  for (CLI::App* sub : app.get_subcommands({})) {
    subcommands.push_back(sub->get_name());
    if (sub->get_name() == args[0]) chosen = sub;
  }
  if (!chosen) {
    auto meant = closest_name(args[0], subcommands);
    std::string known;
    for (const std::string& name : subcommands) known += (known.empty() ? "" : ", ") + name;
    return "unknown subcommand '" + args[0] + "'" +
           (meant ? "; did you mean '" + *meant + "'?" : " (subcommands: " + known + ")");
  }
  std::vector<std::string> options{"--help"};
  for (const CLI::Option* option : chosen->get_options({}))
    for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--") break;  // everything after is positional
    if (args[i].rfind("--", 0) != 0) continue;
    std::string name = args[i].substr(0, args[i].find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    auto meant = closest_name(name, options);
    return "unknown option '" + name + "' for '" + args[0] + "'" +
           (meant ? "; did you mean '" + *meant + "'?" : std::string());
  }
  return std::nullopt;
}

}  // namespace shadergen
