#pragma once
// Which mesh batches a pass can skip: those whose every instance lies outside the pass's clip
// volume (the camera's frustum for the G-buffer, the sun's orthographic box for the shadow
// map). The pipelines clip (no depth clamp), so a batch wholly outside one plane of the volume
// puts no fragment in its target: skipping it changes no pixel. The test is conservative: a
// batch whose bounds straddle a plane, or that is outside only where two planes meet, is drawn.

#include "tilelight/scene/scene.h"
#include "tilelight/scene/world_box.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tilelight {

// One box per entry of scene.batches: the union of its instances' transformed mesh bounds
// (empty for a batch without vertices).
// Precondition: every batch names a mesh of the scene and instances inside scene.instances.
std::vector<WorldBox> batch_bounds(const Scene& scene);

// True when `box` lies wholly outside one of the six planes of the clip volume of
// `view_proj` (Vulkan clip space: -w <= x, y <= w, 0 <= z <= w). An empty box is outside.
bool outside_clip_volume(const glm::mat4& view_proj, const WorldBox& box);

// Per batch, whether a pass with clip volume `view_proj` draws it, and how many it skips.
struct BatchSelection {
  std::vector<bool> drawn;
  std::uint32_t culled = 0;
};
BatchSelection select_batches(const std::vector<WorldBox>& bounds, const glm::mat4& view_proj);

}  // namespace tilelight
