#include "local_light_bench_plan.h"

#include "sweep/sweep_options.h"
#include "tilelight/scene/local_light_placement.h"
#include "tilelight/vulkan/error.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

namespace tilelight::local_light_bench {
namespace {

LocalLightPass pass_named(const std::string& name) {
  return name == "fullscreen" ? LocalLightPass::fullscreen : LocalLightPass::volumes;
}

ShadowMode shadow_mode_named(const std::string& name) {
  if (name == "cached") return ShadowMode::cached;
  return name == "rebuilt" ? ShadowMode::rebuilt : ShadowMode::off;
}

// The row of `rows` measured with `lights` lights, `shadows` and `pass`, or nullptr.
const BenchRow* find_row(const std::vector<BenchRow>& rows, std::uint32_t lights, ShadowMode shadows,
                         LocalLightPass pass) {
  for (const BenchRow& row : rows) {
    const BenchConfiguration& c = row.configuration;
    if (c.lights == lights && c.shadows == shadows && c.renderer.local_light_pass == pass) return &row;
  }
  return nullptr;
}

// "off", or the lights with maps and their faces ("21 (46 faces)"), with the lights left
// unshadowed by the pool's cap.
std::string maps_cell(const BenchRow* row) {
  if (row == nullptr || row->configuration.shadows == ShadowMode::off) return "off";
  const LocalLightShadowPool& p = row->pool;
  std::string cell = fmt::format("{} ({} faces)", p.maps, p.faces);
  if (p.unshadowed > 0) cell += fmt::format(", {} over the cap", p.unshadowed);
  return cell;
}

std::string ms_cell(const BenchRow* row, double BenchRow::*field) {
  return row != nullptr ? fmt::format("{:.1f}", row->*field) : "—";
}

std::string ratio_cell(const BenchRow* slow, const BenchRow* fast, double BenchRow::*field) {
  if (slow == nullptr || fast == nullptr || fast->*field <= 0) return "—";
  return fmt::format("{:.2f}×", slow->*field / fast->*field);
}

}  // namespace

const char* to_string(ShadowMode mode) {
  switch (mode) {
    case ShadowMode::off: return "off";
    case ShadowMode::cached: return "cached";
    case ShadowMode::rebuilt: return "rebuilt";
  }
  return "?";
}

bool parse_bench_options(int argc, const char* const* argv, BenchOptions& options, int& exit_code, std::ostream& out,
                         std::ostream& err) {
  CLI::App cli(
      "tilelight_local_light_bench: the procedural scene's local lights (tilelight --lights N) drawn as\n"
      "light volumes and as full-screen passes, at several light counts, measured side by side in one\n"
      "process (medians over --frames after one warm-up frame, configurations measured round-robin).\n"
      "Prints a markdown table; writes DIR/results.json and DIR/local_lights.png.",
      "tilelight_local_light_bench");
  cli.add_option("--lights", options.lights, "light counts, each a run (tilelight --lights)")
      ->delimiter(',')
      ->check(CLI::Range(1u, kMaxDemoLights))
      ->capture_default_str();
  std::vector<std::string> passes{"volumes", "fullscreen"};
  cli.add_option("--passes", passes, "local-light passes: volumes, fullscreen (tilelight --local-light-pass)")
      ->delimiter(',')
      ->check(CLI::IsMember({"volumes", "fullscreen"}))
      ->capture_default_str();
  std::vector<std::string> shadows{"off", "cached", "rebuilt"};
  cli.add_option("--shadows", shadows,
                 "local-light shadows: off, cached (static maps rendered once), rebuilt (every frame)")
      ->delimiter(',')
      ->check(CLI::IsMember({"off", "cached", "rebuilt"}))
      ->capture_default_str();
  std::string size = "720p";
  CLI::Option* size_option =
      cli.add_option("--size", size, "frame size: 720p, 1080p, 1440p or WxH")->capture_default_str();
  cli.add_option("--camera", options.camera, "the procedural scene's camera (tilelight --list-cameras)")
      ->capture_default_str();
  std::string msaa = "auto";
  cli.add_option("--msaa", msaa, "G-buffer samples: auto, 1, 2, 4, 8, 16")
      ->check(CLI::IsMember({"auto", "1", "2", "4", "8", "16"}))
      ->capture_default_str();
  std::string light_pass = "compute";
  cli.add_option("--light-pass", light_pass, "the global light pass: raster, compute (tilelight --light-pass)")
      ->check(CLI::IsMember({"raster", "compute"}))
      ->capture_default_str();
  CLI::Option* frames = cli.add_option("--frames", options.frames, "timed frames per configuration")
                            ->check(CLI::Range(1u, 10000u))
                            ->capture_default_str();
  cli.add_option("--device", options.device, "as tilelight --device: an index or a name substring (default lavapipe)");
  cli.add_option("--out", options.out, "output folder")->capture_default_str();
  bool quick = false;
  cli.add_flag("--quick", quick,
               "2 and 4 lights, shadows off and rebuilt, at 96x54, one frame: proves the benchmark runs");
  try {
    cli.parse(argc, argv);
    if (quick) {
      if (cli.count("--lights") == 0) options.lights = {2, 4};
      if (cli.count("--shadows") == 0) shadows = {"off", "rebuilt"};
      if (size_option->count() == 0) size = "96x54";
      if (frames->count() == 0) options.frames = 1;
    }
    const sweep::FrameSize parsed = sweep::parse_frame_size(size);
    options.width = parsed.width;
    options.height = parsed.height;
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help or the error; usage errors exit 2 like tilelight's, whatever CLI11's code.
    exit_code = cli.exit(e, out, err) == 0 ? 0 : 2;
    return false;
  } catch (const Error& e) {
    err << "tilelight_local_light_bench: error: " << e.what() << "\nRun with --help for more information.\n";
    exit_code = 2;
    return false;
  }
  options.passes.clear();
  for (const std::string& p : passes) options.passes.push_back(pass_named(p));
  options.shadows.clear();
  for (const std::string& m : shadows) options.shadows.push_back(shadow_mode_named(m));
  options.msaa = msaa == "auto" ? 0 : static_cast<std::uint32_t>(std::stoul(msaa));
  options.light_pass = light_pass == "raster" ? LightPass::raster : LightPass::compute;
  return true;
}

std::vector<BenchConfiguration> bench_configurations(const BenchOptions& options) {
  std::vector<BenchConfiguration> configurations;
  for (const std::uint32_t lights : options.lights) {
    for (const ShadowMode shadows : options.shadows) {
      for (const LocalLightPass pass : options.passes) {
        BenchConfiguration c;
        c.lights = lights;
        c.shadows = shadows;
        c.renderer.local_light_shadows = shadows != ShadowMode::off;
        c.renderer.local_light_shadow_cache = shadows != ShadowMode::rebuilt;
        c.renderer.width = options.width;
        c.renderer.height = options.height;
        c.renderer.camera = options.camera;
        c.renderer.msaa = options.msaa;
        c.renderer.light_pass = options.light_pass;
        c.renderer.local_light_pass = pass;
        c.renderer.baselines = Baselines::none;
        configurations.push_back(std::move(c));
      }
    }
  }
  return configurations;
}

std::string markdown_table(const BenchOptions& options, const std::vector<BenchRow>& rows) {
  const LocalLightPass first = options.passes.front();
  const bool two = options.passes.size() > 1;
  const LocalLightPass second = two ? options.passes[1] : first;
  std::string table = fmt::format(
      "| lights | shadows | maps | shadow maps (ms) | {0} local lights (ms) | {1} local lights (ms) | {1} / {0} | {0} "
      "whole frame (ms) | {1} whole frame (ms) | {1} / {0}, whole frame | pixels differ |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n",
      to_string(first), to_string(second));
  for (const std::uint32_t lights : options.lights) {
    for (const ShadowMode shadows : options.shadows) {
      const BenchRow* a = find_row(rows, lights, shadows, first);
      const BenchRow* b = two ? find_row(rows, lights, shadows, second) : nullptr;
      table +=
          fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", lights, to_string(shadows),
                      maps_cell(a), ms_cell(a, &BenchRow::shadow_maps_ms), ms_cell(a, &BenchRow::local_lights_ms),
                      ms_cell(b, &BenchRow::local_lights_ms), ratio_cell(b, a, &BenchRow::local_lights_ms),
                      ms_cell(a, &BenchRow::frame_ms), ms_cell(b, &BenchRow::frame_ms),
                      ratio_cell(b, a, &BenchRow::frame_ms), b != nullptr ? std::to_string(b->pixels_different) : "—");
    }
  }
  return table;
}

}  // namespace tilelight::local_light_bench
