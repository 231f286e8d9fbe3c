#include "tile_light_pass.h"

#include "compute_tile_light_pass.h"
#include "raster_tile_light_pass.h"
#include "tilelight/vulkan/error.h"

#include <string>

namespace tilelight {

TileLightPass::TileLightPass(const TileLightPassSetup& setup)
    : host_builds_(setup.path == IndexPath::cpu), floor_(setup.floor) {}

const FloorTarget& TileLightPass::floor() const {
  if (floor_ == nullptr) throw Error("the floor pass was recorded, but this renderer does not run it");
  return *floor_;
}

void TileLightPass::record_prepare(VkCommandBuffer, const RenderTargets&) const {}

std::unique_ptr<TileLightPass> make_tile_light_pass(LightPass kind, const TileLightPassSetup& setup) {
  if (kind == LightPass::compute) return std::make_unique<ComputeTileLightPass>(setup);
  return std::make_unique<RasterTileLightPass>(setup);
}

void check_no_invalid_tiles(std::uint32_t invalid_tiles, std::string_view build) {
  if (invalid_tiles != 0) {
    throw Error(std::to_string(invalid_tiles) + " tiles were classified with an impossible raw ID (" +
                std::string(build) + ")");
  }
}

}  // namespace tilelight
