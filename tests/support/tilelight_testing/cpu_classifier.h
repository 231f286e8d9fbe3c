#pragma once
// The CPU reference classifier: the exact tile classification, recomputed on the host from the
// read-back G-buffer and shadow map, for tests. It classifies every sample the lighting shades
// and counts every shadow tap; uber/classify/classify_tiles.comp decides position-dependent bits
// from per-tile bounds instead, so the GPU may set MSAA_EDGE, SHADOW_FADE and LIGHT_SCATTERING
// where no sample needs them and call a tile SOFT where the taps say SOLID or lit; it must never
// miss a bit or pick a shadow type a sample rules out (tests/runtime/app/frame_support.h
// compare_with_reference).
//
// The GPU decides every threshold with `precise` arithmetic, but the driver's normalize(),
// matrix products and divisions may still round differently from the host's. So for each
// decision the reference also reports whether the value lies within a small margin of its
// threshold; a tile bit that depends on such a decision is "uncertain" and may legitimately
// differ. Everything else must match exactly. Margins: view depth 1e-4 relative (at least
// 1e-4 m); shadow-map texel position 1e-3 texel; shadow depth compare 2e-6. Sky and sun-facing
// are read from the depth's bits as stored (gbuffer.glsl), so they are never uncertain.

#include "tilelight_testing/gbuffer_samples.h"

#include "tilelight/render/tile_renderer.h"
#include "tilelight/scene/uniform_blocks.h"
#include "tilelight/tiles/tile_grid.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tilelight {

// Raw bit values (from the generated registry, split_second::raw_bit).
struct RawBitLayout {
  std::uint32_t shadow_solid, shadow_soft, shadow_fade, light_scattering, msaa_edge, sky, sun_light;
};
RawBitLayout registry_raw_bits();

struct ReferenceClassification {
  std::vector<std::uint8_t> raw_ids;         // row-major per tile
  std::vector<std::uint8_t> uncertain_bits;  // row-major per tile: bits that may differ from the GPU
  // Row-major per tile: a sample whose shadow matters for sure (sun-facing, not faded out
  // completely, no decision near a threshold) has a lit tap (SOLID is wrong for the tile) /
  // an occluded tap (no shadow is wrong for the tile).
  std::vector<std::uint8_t> solid_ruled_out;
  std::vector<std::uint8_t> lit_ruled_out;
};

// Preconditions: gbuffer covers grid.width x grid.height; shadow_map holds size^2 depths with
// size = params.shadow_map_size.x.
ReferenceClassification classify_on_cpu(const TileGrid& grid, const GBufferSamples& gbuffer,
                                        std::span<const float> shadow_map, const LightingParamsBlock& params,
                                        const RawBitLayout& bits);

}  // namespace tilelight
