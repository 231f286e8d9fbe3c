#include "tilelight_testing/renderer_test_seam.h"

#include "lighting_interface.h"
#include "tilelight_testing/gbuffer_dump.h"
#include "tilelight_testing/gbuffer_upload.h"

#include <memory>
#include <utility>

namespace tilelight {

GBufferSamples TileRendererTestSeam::read_gbuffer(TileRenderer& renderer, GBufferKind kind) {
  const GBufferDump dump(renderer.context(), renderer.render_targets(), renderer.lighting_interface());
  renderer.submit_after_gbuffer(kind, [&](VkCommandBuffer cmd) { dump.record(cmd); });
  return dump.read();
}

std::vector<float> TileRendererTestSeam::read_shadow_map(const TileRenderer& renderer) {
  return renderer.read_shadow_map();
}

const LightingParamsBlock& TileRendererTestSeam::lighting_params(const TileRenderer& renderer) {
  return renderer.lighting_params();
}

void TileRendererTestSeam::set_gbuffer_override(TileRenderer& renderer, const GBufferSamples& samples) {
  // Shared by the recorder the renderer keeps: it lives as long as the renderer's frames.
  auto upload = std::make_shared<const GBufferUpload>(renderer.context(), renderer.render_targets(), samples,
                                                      renderer.lighting_params().sun_direction);
  const RenderTargets* targets = &renderer.render_targets();
  renderer.set_gbuffer_recorder([upload, targets](VkCommandBuffer cmd) { upload->record(cmd, *targets); });
}

void TileRendererTestSeam::set_before_host_signal(TileRenderer& renderer, std::function<void()> hook) {
  renderer.set_before_host_signal(std::move(hook));
}

}  // namespace tilelight
