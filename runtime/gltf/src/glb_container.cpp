#include "glb_container.h"

#include "json_schema.h"
#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <cstring>

namespace tilelight::gltf_detail {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;

std::uint32_t read_u32(std::span<const std::uint8_t> bytes, std::size_t offset) {
  const std::uint8_t* p = bytes.data() + offset;
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

}  // namespace

bool is_glb(std::span<const std::uint8_t> bytes) { return bytes.size() >= 4 && read_u32(bytes, 0) == kMagic; }

GlbChunks split_glb(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < kHeaderBytes + kChunkHeaderBytes) {
    throw Error(fmt::format("truncated GLB: {} bytes, fewer than a GLB header and a chunk header (20)", bytes.size()));
  }
  const std::uint32_t version = read_u32(bytes, 4);
  if (version == 1) throw Error(kGltf1Refused);
  if (version != 2) throw Error(fmt::format("GLB version {}; only glTF 2.0 (version 2) is supported", version));
  const std::uint64_t length = read_u32(bytes, 8);
  if (length > bytes.size()) {
    throw Error(fmt::format("truncated GLB: the header says {} bytes, the file has {}", length, bytes.size()));
  }
  if (length < bytes.size()) {
    throw Error(fmt::format("the GLB header says {} bytes, but the file has {} (trailing data)", length, bytes.size()));
  }
  const std::uint64_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kJsonChunk) throw Error("the first GLB chunk is not a JSON chunk");
  const std::uint64_t json_end = kHeaderBytes + kChunkHeaderBytes + json_length;
  if (json_end > length) {
    throw Error(fmt::format("truncated GLB: the JSON chunk of {} bytes ends at byte {}, past the end of the file ({})",
                            json_length, json_end, length));
  }
  GlbChunks chunks;
  chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data() + kHeaderBytes + kChunkHeaderBytes),
                                 static_cast<std::size_t>(json_length));
  if (json_end == length) return chunks;
  if (json_end % 4 != 0) throw Error(fmt::format("the GLB JSON chunk's length {} is not a multiple of 4", json_length));
  if (json_end + kChunkHeaderBytes > length) {
    throw Error(
        fmt::format("truncated GLB: {} bytes after the JSON chunk, too few for a chunk header", length - json_end));
  }
  const std::uint64_t bin_length = read_u32(bytes, static_cast<std::size_t>(json_end));
  const std::uint32_t bin_type = read_u32(bytes, static_cast<std::size_t>(json_end) + 4);
  const std::uint64_t bin_end = json_end + kChunkHeaderBytes + bin_length;
  if (bin_end > length) {
    throw Error(
        fmt::format("truncated GLB: the second chunk of {} bytes ends at byte {}, past the end of the file ({})",
                    bin_length, bin_end, length));
  }
  if (bin_type == kBinChunk) {
    chunks.bin =
        bytes.subspan(static_cast<std::size_t>(json_end + kChunkHeaderBytes), static_cast<std::size_t>(bin_length));
  }
  return chunks;
}

namespace {

void append_u32(std::vector<std::uint8_t>& out, std::size_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

}  // namespace

std::vector<std::uint8_t> make_glb(std::string_view json, std::span<const std::uint8_t> bin) {
  const std::size_t json_bytes = (json.size() + 3) / 4 * 4;
  const std::size_t bin_bytes = (bin.size() + 3) / 4 * 4;
  const std::size_t total =
      kHeaderBytes + kChunkHeaderBytes + json_bytes + (bin.empty() ? 0 : kChunkHeaderBytes + bin_bytes);
  std::vector<std::uint8_t> out;
  out.reserve(total);
  append_u32(out, kMagic);
  append_u32(out, 2);
  append_u32(out, total);
  append_u32(out, json_bytes);
  append_u32(out, kJsonChunk);
  out.insert(out.end(), json.begin(), json.end());
  out.resize(out.size() + json_bytes - json.size(), ' ');
  if (!bin.empty()) {
    append_u32(out, bin_bytes);
    append_u32(out, kBinChunk);
    out.insert(out.end(), bin.begin(), bin.end());
    out.resize(out.size() + bin_bytes - bin.size(), 0);
  }
  return out;
}

}  // namespace tilelight::gltf_detail
