// tilelight_sweep: every design choice of the tile-classified light pass measured side by side
// in one process (issue 4, target 2). For each comparison it prints a markdown table on stdout
// and writes a bar chart; DIR/results.json holds every number. Progress goes to stderr.
//
//   tilelight_sweep [--frames N] [--out DIR] [--sizes 720p,1080p,1440p] [--cameras default,...]
//                   [--msaa auto,1] [--path cpu,gpu] [--baselines both|all] [--only ID,...] [--device ...]
//                   [--quick] [--update-doc docs/results.md]

#include "sweep/doc_update.h"
#include "sweep/measurement.h"
#include "sweep/sweep_charts.h"
#include "sweep/sweep_json.h"
#include "sweep/sweep_options.h"
#include "sweep/sweep_plan.h"
#include "sweep/sweep_tables.h"

#include "plot/bar_chart.h"
#include "tilelight/app/camera_choice.h"
#include "tilelight/app/output_files.h"
#include "tilelight/app/usage_error.h"
#include "tilelight/base/atomic_write.h"
#include "tilelight/base/error.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight/picture/png.h"
#include "tilelight/scene/scene.h"
#include "tilelight/vulkan/context.h"

#include <fmt/format.h>
#include <whole_file/whole_file.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <tuple>
#include <utility>

#include <unistd.h>

namespace {

using namespace tilelight;
using namespace tilelight::sweep;

std::vector<const Measurement*> rows_of(const Comparison& c, const std::vector<Measurement>& measurements) {
  std::map<std::string, const Measurement*> by_key;
  for (const Measurement& m : measurements) by_key[m.key] = &m;
  std::vector<const Measurement*> rows;
  for (const std::string& key : c.keys) rows.push_back(by_key.at(key));
  return rows;
}

std::string read_document(const std::filesystem::path& path) {
  std::string text;
  if (auto failure = whole_file::read(path, text))
    throw Error("--update-doc " + path.string() + ": cannot read: " + failure->reason.message());
  return text;
}

// The document's sweep sections: one per comparison, and "run" for the line naming the run.
std::map<std::string, std::string> empty_sections(const SweepPlan& plan) {
  std::map<std::string, std::string> sections{{"run", ""}};
  for (const Comparison& c : plan.comparisons) sections[c.id] = "";
  return sections;
}

void update_document(const std::filesystem::path& path, const std::map<std::string, std::string>& sections) {
  // Blank lines around each section keep the markers (HTML comments) apart from the tables.
  std::map<std::string, std::string> padded;
  for (const auto& [id, content] : sections) padded[id] = "\n" + content + "\n";
  const std::string text = replace_marked_sections(read_document(path), padded, path.string());
  write_file_atomically(path, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

// Prints the run line and every comparison's table on stdout and stages its chart in `files`;
// returns the tables by comparison id, and the run line as "run" (the document's sections).
std::map<std::string, std::string> report_comparisons(const SweepPlan& plan,
                                                      const std::vector<Measurement>& measurements,
                                                      const std::string& run_line, const std::string& device_name,
                                                      app::OutputFiles& files) {
  std::map<std::string, std::string> sections{{"run", run_line}};
  std::cout << run_line;
  for (const Comparison& c : plan.comparisons) {
    const std::vector<const Measurement*> rows = rows_of(c, measurements);
    sections[c.id] = markdown_table(c, rows, device_name);
    std::cout << "\n### " << c.title << "\n\n" << sections[c.id];
    const Rgba8Canvas chart = plot::draw_bar_chart(comparison_chart(c, rows));
    files.stage(c.id + ".png", encode_png(chart.width, chart.height, chart.pixels));
  }
  return sections;
}

// Round-robin within each frame size and MSAA mode (in the order they first appear): every
// renderer of a group is alive at once, and a group of 4K renderers at every camera, light-pass
// kind and index build is as much GPU memory as should be held together (24 at 3840x2160 with
// 2x MSAA in scripts/gpu-bench.sh's run).
std::vector<Measurement> measure_in_groups(const Context& context, const SceneFor& scene,
                                           const std::vector<RendererOptions>& configurations, std::uint32_t frames) {
  using Group = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;  // width, height, msaa
  std::vector<Group> groups;
  for (const RendererOptions& o : configurations) {
    const Group g{o.width, o.height, o.msaa};
    if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
  }
  std::vector<Measurement> measurements;
  for (const Group& g : groups) {
    std::vector<RendererOptions> group;
    for (const RendererOptions& o : configurations) {
      if (Group{o.width, o.height, o.msaa} == g) group.push_back(o);
    }
    const auto& [width, height, msaa] = g;
    std::cerr << fmt::format("{}x{}, msaa {}: {} configuration(s)\n", width, height,
                             msaa == 0 ? std::string("auto") : std::to_string(msaa), group.size());
    for (Measurement& m : measure_round_robin(context, scene, group, frames, std::cerr)) {
      measurements.push_back(std::move(m));
    }
  }
  return measurements;
}

// The kinds comparison's rows also say what their build costs: each row's light spec compiled by
// shadergen, cold, after every frame was measured (so no build competes with a timed frame).
void add_spec_builds(const SweepPlan& plan, std::vector<Measurement>& measurements) {
  const auto kinds = std::find_if(plan.comparisons.begin(), plan.comparisons.end(),
                                  [](const Comparison& c) { return c.facet == Facet::kinds; });
  if (kinds == plan.comparisons.end()) return;
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / fmt::format("tilelight-sweep-specs-{}", ::getpid());
  // One build per spec: its raster and compute rows share it (one spec, both uber-shaders).
  std::map<std::string, SpecBuild> built;
  for (Measurement& m : measurements) {
    if (std::find(kinds->keys.begin(), kinds->keys.end(), m.key) == kinds->keys.end()) continue;
    const std::filesystem::path spec = light_spec(TILELIGHT_PERMUTATIONS_DIR, m.options.light_kinds);
    if (!built.count(spec.string())) {
      std::cerr << "shadergen build " << spec.filename().string() << " (no companions, --no-cache)" << std::flush;
      built[spec.string()] = build_light_spec(SHADERGEN_EXE, spec, scratch);
      std::cerr << fmt::format(": {} blobs in {:.2f} s\n", built[spec.string()].blobs, built[spec.string()].seconds);
    }
    m.spec_build = built[spec.string()];
  }
  std::filesystem::remove_all(scratch);
}

// The scene with its sun fitted to a configuration's camera (tilelight's choice: a procedural
// camera as it always was, a file's or a placed one fitted to its view at that frame size).
class FittedScene {
 public:
  FittedScene(Scene scene, const app::CameraRequest& view) : scene_(std::move(scene)), sun_(scene_.sun), view_(view) {}

  const Scene& operator()(RendererOptions& o) {
    scene_.sun = sun_;
    app::CameraRequest request = view_;
    request.camera = o.camera;
    if (o.camera != "eye") request.eye.clear();
    o.camera_pose =
        app::choose_camera(request, scene_, static_cast<float>(o.width) / static_cast<float>(o.height)).placed;
    return scene_;
  }
  const Scene& scene() const { return scene_; }

 private:
  Scene scene_;
  SunAndAtmosphere sun_;  // as loaded: each fit starts from it
  app::CameraRequest view_;
};

// The procedural scene, or the --scene file (a bad one is an error naming the flag and file;
// what it holds that is not drawn is a warning on stderr, as tilelight prints it, kept for
// results.json).
GltfScene sweep_scene(const SweepOptions& options) {
  if (options.scene.empty()) return GltfScene{make_demo_scene(), {}};
  try {
    GltfScene loaded = load_gltf(options.scene, GltfLoadOptions{options.scene_index});
    for (const std::string& warning : loaded.warnings) std::cerr << warning << '\n';
    return loaded;
  } catch (const Error& e) {
    throw Error(std::string("--scene ") + e.what());
  }
}

int run_sweep(const SweepOptions& options) {
  GltfScene loaded = sweep_scene(options);  // a bad file fails before any Vulkan work
  FittedScene fitted(std::move(loaded.scene), options.view);
  const Scene& scene = fitted.scene();
  // So does a camera that cannot be drawn (exit 2, as tilelight's).
  for (const std::string& camera : options.cameras) {
    RendererOptions probe;
    probe.camera = camera;
    (void)fitted(probe);
  }
  ContextOptions context_options;
  context_options.device = options.device;
  const Context context(context_options);
  app::OutputFiles files(options.out);  // proves --out writable before the long part
  const SweepPlan plan = make_sweep_plan(options);
  // A document without its markers fails now, not after the long part.
  if (!options.update_doc.empty()) {
    (void)replace_marked_sections(read_document(options.update_doc), empty_sections(plan), options.update_doc);
  }
  std::vector<Measurement> measurements =
      measure_in_groups(context, std::ref(fitted), plan.configurations, options.frames);
  add_spec_builds(plan, measurements);

  const char* threads = std::getenv("LP_NUM_THREADS");
  const std::string run_line = fmt::format(
      "Device: {}, {}x MSAA where no row says otherwise, median of {} frame(s) after 1 warm-up frame "
      "(configurations of one frame size and MSAA mode measured round-robin), LP_NUM_THREADS={}, scene {} ({} "
      "triangles)\n",
      context.device_name(), measurements.front().msaa_samples, options.frames,
      threads != nullptr ? threads : "(default)", scene.source.empty() ? "procedural" : scene.source,
      scene.triangle_count());
  const std::map<std::string, std::string> sections =
      report_comparisons(plan, measurements, run_line, context.device_name(), files);
  const SweepRun run{
      context.device_name(),  threads != nullptr ? threads : "", &options, &plan, &measurements, scene.source,
      scene.triangle_count(), std::move(loaded.warnings)};
  files.stage_text("results.json", results_json(run));
  files.commit();
  std::cerr << "wrote " << (files.folder() / "results.json").string() << " and one PNG per comparison\n";
  if (!options.update_doc.empty()) {
    update_document(options.update_doc, sections);
    std::cerr << "updated the tables in " << options.update_doc << '\n';
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  SweepOptions options;
  int exit_code = 0;
  try {
    if (!parse_sweep_options(argc, argv, options, exit_code, std::cout, std::cerr)) return exit_code;
    return run_sweep(options);
  } catch (const app::UsageError& e) {
    std::cerr << e.what() << "\nRun with --help for more information.\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tilelight_sweep: error: " << e.what() << '\n';
    return 1;
  }
}
