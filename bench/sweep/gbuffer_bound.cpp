#include "gbuffer_bound.h"

#include <array>
#include <utility>

namespace tilelight::sweep {
namespace {

// Peak memory bandwidth from NVIDIA's datasheets ("NVIDIA H100 Tensor Core GPU" datasheet: H100
// SXM 3.35 TB/s, H100 PCIe 2 TB/s; "NVIDIA H200 Tensor Core GPU" datasheet: 4.8 TB/s for both
// H200 SXM and H200 NVL). The first matching substring wins: the SXM part names itself
// "NVIDIA H100 80GB HBM3", the PCIe one "NVIDIA H100 PCIe".
constexpr std::array<std::pair<std::string_view, double>, 3> kBandwidths{{
    {"H200", 4.8e12},
    {"H100 PCIe", 2.0e12},
    {"H100 80GB HBM3", 3.35e12},
}};

}  // namespace

std::uint64_t gbuffer_bytes(std::uint32_t width, std::uint32_t height, std::uint32_t samples) {
  return std::uint64_t{width} * height * samples * kGBufferBytesPerSample;
}

std::optional<double> memory_bandwidth(std::string_view device_name) {
  for (const auto& [name, bytes_per_second] : kBandwidths) {
    if (device_name.find(name) != std::string_view::npos) return bytes_per_second;
  }
  return std::nullopt;
}

std::optional<double> gbuffer_read_bound_ms(std::uint64_t bytes, std::optional<double> bytes_per_second) {
  if (!bytes_per_second || *bytes_per_second <= 0) return std::nullopt;
  return static_cast<double>(bytes) / *bytes_per_second * 1000.0;
}

}  // namespace tilelight::sweep
