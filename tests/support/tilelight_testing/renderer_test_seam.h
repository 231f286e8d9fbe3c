#pragma once
// The tests' way into TileRenderer's test-only members, which are private: TileRenderer
// befriends this class, and only the test-support library defines it, so production code cannot
// call them while the frame tests still drive the real render path. The G-buffer dump and upload
// are the test support's own passes (gbuffer_dump.h, gbuffer_upload.h), recorded through the
// renderer's generic hooks.

#include "tilelight_testing/gbuffer_samples.h"

#include "tilelight/render/tile_renderer.h"

#include <functional>
#include <vector>

namespace tilelight {

class TileRendererTestSeam {
 public:
  // The last frame's G-buffer, every sample as stored, and shadow map (size^2 depths,
  // row-major), and the lighting parameters the shaders read: the CPU reference's inputs.
  // `kind`: which G-buffer (the classified one by default); the plain one is drawn for the dump.
  static GBufferSamples read_gbuffer(TileRenderer& renderer, GBufferKind kind = GBufferKind::classified);
  static std::vector<float> read_shadow_map(const TileRenderer& renderer);
  static const LightingParamsBlock& lighting_params(const TileRenderer& renderer);

  // Later frames take their G-buffer from `samples` instead of rendering the scene (the shadow
  // map still comes from the scene). Precondition: size and sample count match `renderer`.
  static void set_gbuffer_override(TileRenderer& renderer, const GBufferSamples& samples);

  // `hook` runs on the host after the tile pass was submitted and before the host signals it;
  // an exception it throws must still leave the GPU unblocked. An empty hook removes it.
  static void set_before_host_signal(TileRenderer& renderer, std::function<void()> hook);
};

}  // namespace tilelight
