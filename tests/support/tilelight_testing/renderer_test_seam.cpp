#include "tilelight_testing/renderer_test_seam.h"

#include <utility>

namespace tilelight {

void TileRendererTestSeam::set_gbuffer_override(TileRenderer& renderer, const GBufferSamples& samples) {
  renderer.set_gbuffer_override(samples);
}

void TileRendererTestSeam::set_before_host_signal(TileRenderer& renderer, std::function<void()> hook) {
  renderer.set_before_host_signal(std::move(hook));
}

}  // namespace tilelight
