// suggest.h - "did you mean ...?" for a misspelt subcommand or option.
#pragma once

#include <CLI/CLI.hpp>

#include "base/closest_name.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadergen {

// A misspelt subcommand or long option in `args` (without the program name), said with the name
// meant when one is close ("unknown subcommand 'biuld'; did you mean 'build'?"); nullopt when
// every name is one of `app`'s. CLI11's own message for these ("The following arguments were not
// expected") names no cure.
std::optional<std::string> misspelt_name(CLI::App& app, const std::vector<std::string>& args);

}  // namespace shadergen
