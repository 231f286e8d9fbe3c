#pragma once
// Classification on the GPU (uber/classify/classify_tiles.comp): one invocation per row of a
// block of 4x4 tiles writes the raw IDs in the blocked layout, then the IDs are copied to host
// memory for the CPU index builder (and the report).

#include "lighting_interface.h"
#include "render_targets.h"
#include "tilelight/tiles/tile_grid.h"
#include "tilelight/vulkan/buffer.h"
#include "tilelight/vulkan/vk_handles.h"

#include <cstdint>
#include <span>

namespace tilelight {

class Context;

class TileClassification {
 public:
  // `targets`: the G-buffer that `lighting` binds (the classifier is specialised to its sample
  // count).
  TileClassification(const Context& context, const TileGrid& grid, const RenderTargets& targets,
                     const LightingInterface& lighting, VkDescriptorPool pool);

  // Dispatches classification and copies the IDs to host memory. Afterwards the device ID
  // buffer is readable by compute shaders and the host copy by the host.
  void record(VkCommandBuffer cmd) const;
  // The device-side blocked raw IDs (input of the GPU-driven index build).
  const Buffer& device_ids() const { return ids_; }
  // The host copy; valid once the submission that ran record() has completed.
  std::span<const std::uint8_t> host_ids() const;

 private:
  const LightingInterface* lighting_;
  TileGrid grid_;
  Buffer ids_, host_ids_;
  VkDescriptorSet ids_set_ = VK_NULL_HANDLE;
  UniquePipeline classify_;
};

}  // namespace tilelight
