#pragma once
// Every G-buffer sample as stored (uber/include/gbuffer.glsl), as the tests' G-buffer dump
// reads it back and their upload writes it: the CPU reference classifier's input.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tilelight {

struct GBufferSamples {
  // Per sample: rt0.rgba, rt1.rgba, rt2.rgba, rt3 (surface depth), the coverage flags' bits (0
  // with one sample), 0, 0 (shaders/gbuffer_dump.comp writes them as four vec4s).
  static constexpr std::size_t kFloatsPerSample = 16;

  std::uint32_t width = 0, height = 0, samples = 0;
  std::vector<float> values;  // per pixel (row-major), per sample: kFloatsPerSample floats
  // width * height * samples * kFloatsPerSample: the size `values` must have.
  std::size_t value_count() const { return std::size_t{width} * height * samples * kFloatsPerSample; }
  // Precondition: x < width, y < height, s < samples. Points at kFloatsPerSample floats.
  const float* at(std::uint32_t x, std::uint32_t y, std::uint32_t s) const {
    return values.data() + ((static_cast<std::size_t>(y) * width + x) * samples + s) * kFloatsPerSample;
  }
};

}  // namespace tilelight
