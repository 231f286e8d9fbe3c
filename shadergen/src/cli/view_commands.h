// view_commands.h - `shadergen lut`, `list` and `explain`: views of a spec and its
// permutations, printed without building anything.
#pragma once

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>

namespace shadergen {

struct ViewArgs {
  std::string spec_path;
  std::string variants_path;  // --variants: replaces the spec's "variants_file"
  std::string raw_id;         // explain's argument, as typed
};

struct ViewCommands {
  CLI::App* lut = nullptr;
  CLI::App* list = nullptr;
  CLI::App* explain = nullptr;
};

// Adds the three subcommands to `app`; a parse fills `args`.
ViewCommands add_view_commands(CLI::App& app, ViewArgs& args);

// Runs whichever of `commands` was parsed. Precondition: one of them was.
int run_view(const ViewCommands& commands, const ViewArgs& args, std::ostream& out, std::ostream& err);

}  // namespace shadergen
