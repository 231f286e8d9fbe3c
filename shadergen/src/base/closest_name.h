// closest_name.h - "did you mean ...?": the known name closest to a misspelt one, for the CLI's
// subcommands and options and for the spec's defines alike.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadergen {

// The entry of `known` closest to `given`: within two edits (insertions, deletions,
// substitutions, or two neighbours swapped), or one being the other with letters added at the
// end ("--output" for "--out"). nullopt when none is that close or two are equally close.
std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& known);

}  // namespace shadergen
