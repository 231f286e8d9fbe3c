#pragma once
// The command line of tilelight_sweep: how many frames, which sizes, which device, where to.

#include "tilelight/app/camera_choice.h"
#include "tilelight/render/tile_renderer.h"

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tilelight::sweep {

struct FrameSize {
  std::uint32_t width = 0, height = 0;
  std::string name;  // as given on the command line ("720p", "96x54")
};

struct SweepOptions {
  std::uint32_t frames = 5;
  std::string out = "tilelight-sweep";
  // The first size is the one every design-choice comparison runs at; all of them make the
  // resolution comparison.
  std::vector<FrameSize> sizes;
  // The baseline comparison (classified vs dynamic vs naive) runs at every size, for every one
  // of these cameras and G-buffer sample counts (0 = auto, as tilelight --msaa auto).
  std::vector<std::string> cameras;
  std::vector<std::uint32_t> msaa;
  // The index builds of the baseline comparison (tilelight --path), each a row per view.
  std::vector<IndexPath> paths{IndexPath::cpu};
  // The full-frame passes every frame of the baseline comparison runs: both (naive, dynamic) or
  // all (the floor pass too); with `all` its table shows the whole frames and the floor as well.
  Baselines baselines = Baselines::both;
  // The light-pass kinds of the baseline comparison (tilelight --light-pass), each a row per view.
  std::vector<std::string> light_passes{"raster", "compute"};
  // Batch culling in the baseline comparison (tilelight --no-cull is false), each a row per view.
  std::vector<bool> culls{true};
  // The comparisons to run, by id (sweep_plan.h); empty = all.
  std::vector<std::string> only;
  std::string device;  // as tilelight --device: "" = lavapipe, an index or a name substring
  bool quick = false;
  // A glTF file to measure instead of the procedural scene ("" = the procedural scene), and
  // which of its scenes; with a file, the cameras default to its one camera, "default".
  std::string scene;
  std::optional<std::uint32_t> scene_index;
  // tilelight's camera and lighting flags (--eye, --target, --up, --fov, --sun-direction, the
  // distances): a placed camera is the view "eye", the only one unless --cameras names others.
  app::CameraRequest view;
  // A markdown file whose marked sections (see doc_update.h) get the new tables; "" = none.
  std::string update_doc;
};

// "720p", "1080p", "1440p" or "<width>x<height>". Throws tilelight::Error:
//   "--sizes <text>: expected 720p, 1080p, 1440p or <width>x<height>"
FrameSize parse_frame_size(const std::string& text);

// Parses argv. On --help or a usage error it prints to `out` / `err` and sets `exit_code`
// (0 for help, 2 for a usage error), returning false; true means go on and sweep.
bool parse_sweep_options(int argc, const char* const* argv, SweepOptions& options, int& exit_code, std::ostream& out,
                         std::ostream& err);

}  // namespace tilelight::sweep
