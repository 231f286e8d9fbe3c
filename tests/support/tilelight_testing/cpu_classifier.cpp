// The exact per-sample classification that uber/classify/classify_tiles.comp bounds per tile:
// the same include functions (the comments name each GLSL function), evaluated for every
// sample the lighting shades, with every shadow tap counted. It is the answer the GPU's IDs
// must admit (tests/runtime/app/frame_support.h compare_with_reference).
#include "tilelight_testing/cpu_classifier.h"

#include "tilelight/base/error.h"

#include "tilelight_testing/raw_bit_masks.h"

#include <split_second_shaders.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace tilelight {
namespace {

// The flags read best as the bit table they are.
// clang-format off
enum Flag : std::uint32_t {
  kFade = 0x01, kScattering = 0x02, kEdge = 0x04, kSky = 0x08, kSun = 0x10,
  kShadowed = 0x20, kLit = 0x40, kPartial = 0x80,
  // Facts about samples whose shadow certainly matters (sun-facing, not faded out completely)
  // and whose tap count is certain: one with a lit tap rules SOLID out, one with an occluded
  // tap rules "no shadow" (lit) out.
  kRulesOutSolid = 0x100, kRulesOutLit = 0x200,
};
// clang-format on
constexpr std::uint32_t kShadowFlags = kShadowed | kLit | kPartial;

struct Flags {
  std::uint32_t certain = 0;   // set for sure
  std::uint32_t possible = 0;  // set by some rounding of the near-threshold decisions
  void add(std::uint32_t flag, bool set, bool uncertain) {
    if (set && !uncertain) certain |= flag;
    if (set || uncertain) possible |= flag;
  }
  void merge(const Flags& other) {
    certain |= other.certain;
    possible |= other.possible;
  }
};

// What lighting reads of a G-buffer sample: rt0[4], rt1[4], rt2[4], rt3 (surface depth); the
// coverage flags' bits follow (GBufferSamples pads to 16).
constexpr std::size_t kStoredFloats = 13;
constexpr std::size_t kFlagsFloat = 13;
// gbuffer.glsl: GBUFFER_FLAG_PARTIAL, GBUFFER_FLAG_SHARED.
constexpr std::uint32_t kPartialFlag = 1u;
constexpr std::uint32_t kSharedFlag = 2u;

// Whether two samples store the same bits in their first `count` floats. Bits, not values: the
// classifier's question is whether the samples differ at all (a float compare would call -0 and
// +0 equal).
bool same_bits(const float* a, const float* b, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i)
    if (std::bit_cast<std::uint32_t>(a[i]) != std::bit_cast<std::uint32_t>(b[i])) return false;
  return true;
}

struct Sample {
  const float* v;  // rt0[4], rt1[4], rt2[4], rt3, flag bits
  // gbuffer.glsl: the sky lies at surface depth 1.0, every material depth below it.
  bool is_sky() const { return v[12] == 1.0f; }
  // gbuffer.glsl: the lowest mantissa bit of the surface depth, set by the material where the
  // stored normal faces the sun.
  bool sun_bit() const { return !is_sky() && (std::bit_cast<std::uint32_t>(v[12]) & 1u) != 0; }
  std::uint32_t flags() const { return std::bit_cast<std::uint32_t>(v[kFlagsFloat]); }
};

glm::vec4 multiply(const glm::mat4& m, const glm::vec4& v) {
  glm::vec4 r;
  for (int row = 0; row < 4; ++row) {
    r[row] = m[0][row] * v.x + m[1][row] * v.y + m[2][row] * v.z + m[3][row] * v.w;
  }
  return r;
}

bool near_threshold(float value, float threshold, float margin) { return std::fabs(value - threshold) <= margin; }

class SampleClassifier {
 public:
  SampleClassifier(const LightingParamsBlock& p, std::span<const float> map) : params_(p), map_(map) {
    map_size_ = static_cast<int>(p.shadow_map_size.x);
  }

  Flags classify(std::uint32_t x, std::uint32_t y, const Sample& s) const {
    Flags f;
    if (s.is_sky()) {
      f.add(kSky, true, false);
      return f;
    }
    // world_position_from_depth() and linear_view_depth().
    const glm::vec2 ndc{(static_cast<float>(x) + 0.5f) * params_.viewport.z * 2.0f - 1.0f,
                        (static_cast<float>(y) + 0.5f) * params_.viewport.w * 2.0f - 1.0f};
    const glm::vec4 world = multiply(params_.inv_view_proj, {ndc.x, ndc.y, s.v[12], 1.0f});
    const glm::vec3 pos = glm::vec3(world) / world.w;
    const glm::vec3 offset = pos - glm::vec3(params_.camera_pos);
    const float view_depth =
        offset.x * params_.camera_forward.x + offset.y * params_.camera_forward.y + offset.z * params_.camera_forward.z;
    const float depth_margin = std::max(1e-4f, 1e-4f * std::fabs(view_depth));
    // shadow_fade_active(), light_scattering_active().
    f.add(kFade, view_depth > params_.distances.x, near_threshold(view_depth, params_.distances.x, depth_margin));
    f.add(kScattering, view_depth > params_.distances.z, near_threshold(view_depth, params_.distances.z, depth_margin));
    // The sun-facing bit: the G-buffer's decision, which the lighting reads as it is.
    const bool faces = s.sun_bit();
    f.add(kSun, faces, false);
    // shadow_fade_complete(): a completely faded shadow has no say in the tile's shadow type.
    const float fade = (view_depth - params_.distances.x) * params_.distances.y;
    const bool faded = fade >= 1.0f;
    const bool fade_uncertain =
        near_threshold(view_depth, params_.distances.x + 1.0f / params_.distances.y, depth_margin);
    if (faces && (!faded || fade_uncertain)) {
      add_shadow(pos, f, fade_uncertain);
    }
    return f;
  }

 private:
  // sun_shadow_lit_taps(), with the margins of each decision.
  void add_shadow(const glm::vec3& pos, Flags& f, bool participation_uncertain) const {
    const glm::vec4 clip = multiply(params_.sun_view_proj, glm::vec4(pos, 1.0f));
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    bool uncertain =
        participation_uncertain || near_threshold(ndc.z, 0.0f, 2e-6f) || near_threshold(ndc.z, 1.0f, 2e-6f);
    int lit = 8;
    if (ndc.z >= 0.0f && ndc.z <= 1.0f) {
      const float size = params_.shadow_map_size.x;
      glm::vec2 texel_pos = (glm::vec2(ndc) * 0.5f + 0.5f) * size;
      texel_pos = glm::clamp(texel_pos, glm::vec2(-4.0f), glm::vec2(size + 4.0f));
      const glm::vec2 shifted = texel_pos - 0.5f;
      // Near a texel boundary the GPU may pick the neighbouring base texel: count the taps for
      // every base it could pick; the verdict is uncertain only if those counts differ.
      std::array<int, 2> bases_x{static_cast<int>(std::floor(shifted.x)), 0};
      std::array<int, 2> bases_y{static_cast<int>(std::floor(shifted.y)), 0};
      const int count_x = neighbour_base(shifted.x, bases_x);
      const int count_y = neighbour_base(shifted.y, bases_y);
      const float receiver = ndc.z - params_.distances.w;
      lit = lit_taps(bases_x[0], bases_y[0], receiver, uncertain);
      for (int ix = 0; ix < count_x; ++ix) {
        for (int iy = 0; iy < count_y; ++iy) {
          if (lit_taps(bases_x[ix], bases_y[iy], receiver, uncertain) != lit) uncertain = true;
        }
      }
    }
    const std::uint32_t state = lit == 0 ? kShadowed : lit == 8 ? kLit : kPartial;
    // An uncertain sample could be in any shadow state.
    f.add(state, true, uncertain);
    if (uncertain) f.possible |= kShadowFlags;
    if (!uncertain && lit > 0) f.certain |= kRulesOutSolid;
    if (!uncertain && lit < 8) f.certain |= kRulesOutLit;
  }

  // The base texel floor(v) and, when v is within 1e-3 texel of an integer, the neighbour the
  // GPU could pick instead; returns how many candidates there are.
  static int neighbour_base(float v, std::array<int, 2>& bases) {
    const float frac = v - std::floor(v);
    if (frac <= 1e-3f) {
      bases[1] = bases[0] - 1;
      return 2;
    }
    if (frac >= 1.0f - 1e-3f) {
      bases[1] = bases[0] + 1;
      return 2;
    }
    return 1;
  }

  int lit_taps(int base_x, int base_y, float receiver, bool& uncertain) const {
    static constexpr std::array<std::array<int, 2>, 8> kTaps{
        {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {-1, 1}, {2, 0}, {0, -1}, {1, 2}}};
    int lit = 0;
    for (const auto& tap : kTaps) {
      const int tx = base_x + tap[0];
      const int ty = base_y + tap[1];
      if (tx < 0 || ty < 0 || tx >= map_size_ || ty >= map_size_) {
        ++lit;
        continue;
      }
      const float occluder =
          map_[static_cast<std::size_t>(ty) * static_cast<std::size_t>(map_size_) + static_cast<std::size_t>(tx)];
      if (receiver <= occluder) ++lit;
      if (near_threshold(receiver, occluder, 2e-6f)) uncertain = true;
    }
    return lit;
  }

  const LightingParamsBlock& params_;
  std::span<const float> map_;
  int map_size_ = 0;
};

Flags classify_pixel(const SampleClassifier& classifier, const GBufferSamples& g, std::uint32_t x, std::uint32_t y) {
  // classify_tiles.comp: the partial flag on any sample makes an edge (gbuffer.glsl: a pixel
  // whose samples come from several fragments holds a sample of a partial one); the shared flag
  // (partial fragments with shared values: flat faces, the sky) only where some sample differs
  // from sample 0, bit for bit, in some target.
  std::uint32_t flags = 0;
  for (std::uint32_t s = 0; s < g.samples; ++s) flags |= Sample{g.at(x, y, s)}.flags();
  bool edge = (flags & kPartialFlag) != 0;
  const bool shared = (flags & kSharedFlag) != 0;
  for (std::uint32_t s = 1; shared && !edge && s < g.samples; ++s) {
    edge = !same_bits(g.at(x, y, s), g.at(x, y, 0), kStoredFloats);
  }
  const bool partial = edge || shared;
  Flags f;
  f.add(kEdge, edge, false);
  const std::uint32_t classified = partial ? g.samples : 1;
  for (std::uint32_t s = 0; s < classified; ++s) f.merge(classifier.classify(x, y, Sample{g.at(x, y, s)}));
  return f;
}

// raw_id_from_tile_flags().
std::uint32_t raw_id(std::uint32_t flags, const RawBitLayout& bits) {
  const bool shadowed = (flags & kShadowed) != 0, lit = (flags & kLit) != 0, partial = (flags & kPartial) != 0;
  std::uint32_t raw = 0;
  if (shadowed && !lit && !partial) raw |= bits.shadow_solid;
  if (partial || (shadowed && lit)) raw |= bits.shadow_soft;
  if (flags & kFade) raw |= bits.shadow_fade;
  if (flags & kScattering) raw |= bits.light_scattering;
  if (flags & kEdge) raw |= bits.msaa_edge;
  if (flags & kSky) raw |= bits.sky;
  if (flags & kSun) raw |= bits.sun_light;
  return raw;
}

}  // namespace

RawBitLayout registry_raw_bits() {
  namespace bit = tilelight::raw_bit_masks;
  return {bit::SHADOW_SOLID, bit::SHADOW_SOFT, bit::SHADOW_FADE, bit::LIGHT_SCATTERING,
          bit::MSAA_EDGE,    bit::SKY,         bit::SUN_LIGHT};
}

ReferenceClassification classify_on_cpu(const TileGrid& grid, const GBufferSamples& gbuffer,
                                        std::span<const float> shadow_map, const LightingParamsBlock& params,
                                        const RawBitLayout& bits) {
  if (gbuffer.width != grid.width || gbuffer.height != grid.height) {
    throw Error("classify_on_cpu: the G-buffer size does not match the tile grid");
  }
  const SampleClassifier classifier(params, shadow_map);
  std::vector<Flags> tiles(grid.tile_count());
  for (std::uint32_t y = 0; y < grid.height; ++y) {
    for (std::uint32_t x = 0; x < grid.width; ++x) {
      tiles[(y / grid.tile_size) * grid.tiles_x + x / grid.tile_size].merge(classify_pixel(classifier, gbuffer, x, y));
    }
  }
  ReferenceClassification out;
  out.raw_ids.resize(tiles.size());
  out.uncertain_bits.resize(tiles.size());
  out.solid_ruled_out.resize(tiles.size());
  out.lit_ruled_out.resize(tiles.size());
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const std::uint32_t certain_id = raw_id(tiles[i].certain, bits);
    out.raw_ids[i] = static_cast<std::uint8_t>(certain_id);
    std::uint32_t uncertain = raw_id(tiles[i].possible, bits) ^ certain_id;
    // Shadow type is not monotonic in the flags: any doubt about one sample's shadow state
    // makes both shadow bits uncertain.
    if ((tiles[i].possible & kShadowFlags) != (tiles[i].certain & kShadowFlags)) {
      uncertain |= bits.shadow_solid | bits.shadow_soft;
    }
    out.uncertain_bits[i] = static_cast<std::uint8_t>(uncertain);
    out.solid_ruled_out[i] = (tiles[i].certain & kRulesOutSolid) != 0;
    out.lit_ruled_out[i] = (tiles[i].certain & kRulesOutLit) != 0;
  }
  return out;
}

}  // namespace tilelight
