#include "sweep_options.h"

#include "tilelight/vulkan/error.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>

namespace tilelight::sweep {
namespace {

bool parse_positive(std::string_view text, std::uint32_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value > 0;
}

}  // namespace

FrameSize parse_frame_size(const std::string& text) {
  if (text == "720p") return {1280, 720, text};
  if (text == "1080p") return {1920, 1080, text};
  if (text == "1440p") return {2560, 1440, text};
  const std::size_t x = text.find('x');
  FrameSize size{0, 0, text};
  if (x != std::string::npos && parse_positive(std::string_view(text).substr(0, x), size.width) &&
      parse_positive(std::string_view(text).substr(x + 1), size.height)) {
    return size;
  }
  throw Error("--sizes " + text + ": expected 720p, 1080p, 1440p or <width>x<height>");
}

bool parse_sweep_options(int argc, const char* const* argv, SweepOptions& options, int& exit_code, std::ostream& out,
                         std::ostream& err) {
  CLI::App cli(
      "tilelight_sweep: every design choice of the tile-classified light pass measured side by side\n"
      "in one process (medians over --frames after one warm-up frame); writes DIR/results.json,\n"
      "one PNG chart per comparison, and markdown tables on stdout.",
      "tilelight_sweep");
  std::vector<std::string> sizes{"720p", "1080p", "1440p"};
  cli.add_option("--frames", options.frames, "timed frames per configuration")
      ->check(CLI::Range(1u, 10000u))
      ->capture_default_str();
  cli.add_option("--out", options.out, "output folder")->capture_default_str();
  cli.add_option("--sizes", sizes, "frame sizes: 720p, 1080p, 1440p or WxH; the first is the comparisons' size")
      ->delimiter(',')
      ->capture_default_str();
  std::vector<std::string> msaa{"auto", "1"};
  options.cameras = {"default", "low", "street", "closeup", "shadow", "sky"};
  CLI::Option* cameras =
      cli.add_option("--cameras", options.cameras,
                     "cameras of the baseline comparison (tilelight --list-cameras; gltf:N for a --scene file's, eye "
                     "for --eye's)")
          ->delimiter(',')
          ->capture_default_str();
  CLI::Option* scene = cli.add_option("--scene", options.scene,
                                      "a glTF 2.0 file (.gltf, .glb) to measure instead of the procedural scene");
  cli.add_option("--scene-index", options.scene_index, "which scene of the --scene file")->needs(scene);
  app::add_camera_options(cli, options.view);
  cli.add_option("--msaa", msaa, "G-buffer sample counts of the baseline comparison: auto, 1, 2, 4, 8, 16")
      ->delimiter(',')
      ->check(CLI::IsMember({"auto", "1", "2", "4", "8", "16"}))
      ->capture_default_str();
  std::vector<std::string> paths{"cpu"};
  cli.add_option("--path", paths,
                 "index builds of the baseline comparison: cpu (host patching), gpu (compute); each view measured "
                 "with each")
      ->delimiter(',')
      ->check(CLI::IsMember({"cpu", "gpu"}))
      ->capture_default_str();
  std::string baselines = "both";
  cli.add_option("--baselines", baselines,
                 "full-frame passes of the baseline comparison: both (naive, dynamic) or all (and the floor pass; "
                 "its table adds the whole frames and per-frame ratios)")
      ->check(CLI::IsMember({"both", "all"}))
      ->capture_default_str();
  cli.add_option("--light-passes", options.light_passes,
                 "light-pass kinds of the baseline comparison: raster, compute (each view measured with each)")
      ->delimiter(',')
      ->check(CLI::IsMember({"raster", "compute"}))
      ->capture_default_str();
  std::vector<std::string> culls{"on"};
  cli.add_option("--cull", culls,
                 "batch culling in the baseline comparison: on, off (tilelight --no-cull); each view measured with "
                 "each")
      ->delimiter(',')
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  cli.add_option("--only", options.only,
                 "run only these comparisons: permutations, tile_size, index_path, coalescing, primitive, "
                 "resolution, stages, baselines, kinds (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember({"permutations", "tile_size", "index_path", "coalescing", "primitive", "resolution",
                             "stages", "baselines", "kinds"}));
  cli.add_option("--device", options.device,
                 "Vulkan device: auto (a discrete GPU, else an integrated one, else lavapipe), an index or a name "
                 "substring (default: lavapipe)");
  cli.add_option("--update-doc", options.update_doc,
                 "markdown file whose <!-- sweep:ID --> sections get the new tables (docs/results.md)");
  cli.add_flag("--quick", options.quick, "smoke run: sizes 64x36,96x54 and 1 frame (overrides --sizes, --frames)");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help or the error; usage errors exit 2 like tilelight's, whatever CLI11's code.
    exit_code = cli.exit(e, out, err) == 0 ? 0 : 2;
    return false;
  }
  if (!options.scene.empty() && cameras->count() == 0) options.cameras = {"default"};
  if (!options.view.eye.empty()) {
    if (cameras->count() == 0) options.cameras.clear();
    if (std::find(options.cameras.begin(), options.cameras.end(), "eye") == options.cameras.end())
      options.cameras.push_back("eye");
  }
  options.view.scene_file = options.scene;
  if (options.quick) {
    sizes = {"64x36", "96x54"};
    options.frames = 1;
  }
  options.sizes.clear();
  for (const std::string& s : sizes) options.sizes.push_back(parse_frame_size(s));
  options.paths.clear();
  for (const std::string& p : paths) options.paths.push_back(p == "gpu" ? IndexPath::gpu : IndexPath::cpu);
  options.baselines = baselines == "all" ? Baselines::all : Baselines::both;
  options.culls.clear();
  for (const std::string& c : culls) options.culls.push_back(c == "on");
  options.msaa.clear();
  for (const std::string& m : msaa)
    options.msaa.push_back(m == "auto" ? 0u : static_cast<std::uint32_t>(std::stoul(m)));
  return true;
}

}  // namespace tilelight::sweep
