#pragma once
// The physical limit of a full-frame light pass: it reads every G-buffer sample at least once,
// so no light pass can take less than the G-buffer's bytes divided by the device's memory
// bandwidth. The sweep prints that bound beside the measured passes.

#include <cstdint>
#include <optional>
#include <string_view>

namespace tilelight::sweep {

// Bytes per G-buffer sample that lighting reads, as runtime/render/src/render_targets.h
// allocates them: RT0 RGBA8 (4), RT1 RGBA16F (8), RT2 RGBA16F (8), RT3 R32F surface depth (4).
// The hardware depth and the classified path's fragment tags are not read by any light pass.
// That header is private to the renderer; tests/bench checks the sum, and a change of format
// there must change it here.
inline constexpr std::uint64_t kGBufferBytesPerSample = 4 + 8 + 8 + 4;

// G-buffer bytes a light pass reads once per frame: pixels x samples x kGBufferBytesPerSample.
std::uint64_t gbuffer_bytes(std::uint32_t width, std::uint32_t height, std::uint32_t samples);

// Peak memory bandwidth (bytes/s) of the devices the project has been lent, by a substring of
// their Vulkan device name; empty for any other device (lavapipe included).
std::optional<double> memory_bandwidth(std::string_view device_name);

// gbuffer_bytes() / bandwidth in milliseconds; empty where the bandwidth is unknown.
std::optional<double> gbuffer_read_bound_ms(std::uint64_t bytes, std::optional<double> bytes_per_second);

}  // namespace tilelight::sweep
