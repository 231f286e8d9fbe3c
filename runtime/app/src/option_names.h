#pragma once
// The names tilelight's flags spell their choices with, and the renderer values they stand for:
// the CLI parses each flag through one of these tables (cli.cpp), and the report spells the
// values back through the same table, so a name is written once.

#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tilelight::app {

template <typename T>
using OptionNames = std::vector<std::pair<std::string, T>>;

const OptionNames<std::uint32_t>& msaa_names();  // "auto" is 0, RendererOptions::msaa's automatic choice
const OptionNames<IndexPath>& path_names();
const OptionNames<bool>& permutation_names();  // RendererOptions::raw_permutations
const OptionNames<Baselines>& baseline_names();
const OptionNames<LightPass>& light_pass_names();
const OptionNames<LightKinds>& light_kinds_names();
const OptionNames<LocalLightPass>& local_light_pass_names();
const OptionNames<bool>& on_off_names();  // "on" true, "off" false

// The name of `value` in `names`. Precondition: it has one (every enumerator has).
template <typename T>
const std::string& name_of(const OptionNames<T>& names, T value) {
  for (const auto& [name, v] : names) {
    if (v == value) return name;
  }
  return names.front().first;  // unreachable while the tables cover their enums
}

}  // namespace tilelight::app
