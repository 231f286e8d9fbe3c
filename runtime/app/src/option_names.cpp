#include "option_names.h"

namespace tilelight::app {

const OptionNames<std::uint32_t>& msaa_names() {
  static const OptionNames<std::uint32_t> names{{"auto", 0}, {"1", 1}, {"2", 2}, {"4", 4}, {"8", 8}, {"16", 16}};
  return names;
}

const OptionNames<IndexPath>& path_names() {
  static const OptionNames<IndexPath> names{{"cpu", IndexPath::cpu}, {"gpu", IndexPath::gpu}};
  return names;
}

const OptionNames<bool>& permutation_names() {
  static const OptionNames<bool> names{{"optimised", false}, {"raw", true}};
  return names;
}

const OptionNames<Baselines>& baseline_names() {
  static const OptionNames<Baselines> names = [] {
    OptionNames<Baselines> all;
    for (const Baselines b :
         {Baselines::none, Baselines::naive, Baselines::dynamic, Baselines::both, Baselines::floor, Baselines::all}) {
      all.emplace_back(to_string(b), b);
    }
    return all;
  }();
  return names;
}

const OptionNames<LightPass>& light_pass_names() {
  static const OptionNames<LightPass> names{{to_string(LightPass::raster), LightPass::raster},
                                            {to_string(LightPass::compute), LightPass::compute}};
  return names;
}

const OptionNames<LightKinds>& light_kinds_names() {
  static const OptionNames<LightKinds> names{{to_string(LightKinds::variant), LightKinds::variant},
                                             {to_string(LightKinds::specialization), LightKinds::specialization},
                                             {to_string(LightKinds::branch), LightKinds::branch}};
  return names;
}

const OptionNames<LocalLightPass>& local_light_pass_names() {
  static const OptionNames<LocalLightPass> names{{to_string(LocalLightPass::volumes), LocalLightPass::volumes},
                                                 {to_string(LocalLightPass::fullscreen), LocalLightPass::fullscreen}};
  return names;
}

const OptionNames<bool>& on_off_names() {
  static const OptionNames<bool> names{{"on", true}, {"off", false}};
  return names;
}

}  // namespace tilelight::app
