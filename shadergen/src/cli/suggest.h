// suggest.h - "did you mean ...?" for a misspelt subcommand or option.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadergen {

// The entry of `known` closest to `given`: within two edits (insertions, deletions,
// substitutions, or two neighbours swapped), or one being the other with letters added at the
// end ("--output" for "--out"). nullopt when none is that close or two are equally close.
std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& known);

// A misspelt subcommand or long option in `args` (without the program name), said with the name
// meant when one is close ("unknown subcommand 'biuld'; did you mean 'build'?"); nullopt when
// every name is one of `app`'s. CLI11's own message for these ("The following arguments were not
// expected") names no cure.
std::optional<std::string> misspelt_name(CLI::App& app, const std::vector<std::string>& args);

}  // namespace shadergen
