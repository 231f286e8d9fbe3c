#include "tilelight_testing/renderer_test_seam.h"

#include <utility>

namespace tilelight {

GBufferSamples TileRendererTestSeam::read_gbuffer(TileRenderer& renderer, GBufferKind kind) {
  return renderer.read_gbuffer(kind);
}

std::vector<float> TileRendererTestSeam::read_shadow_map(const TileRenderer& renderer) {
  return renderer.read_shadow_map();
}

const LightingParamsBlock& TileRendererTestSeam::lighting_params(const TileRenderer& renderer) {
  return renderer.lighting_params();
}

void TileRendererTestSeam::set_gbuffer_override(TileRenderer& renderer, const GBufferSamples& samples) {
  renderer.set_gbuffer_override(samples);
}

void TileRendererTestSeam::set_before_host_signal(TileRenderer& renderer, std::function<void()> hook) {
  renderer.set_before_host_signal(std::move(hook));
}

}  // namespace tilelight
