#include "draco_stream_header.h"

#include "tilelight/base/error.h"

#include <fmt/format.h>

#include <string_view>

namespace tilelight::gltf_detail {
namespace {

constexpr std::size_t kHeaderBytes = 11;
constexpr std::uint16_t kMetadataFlag = 0x8000;

struct Reader {
  std::span<const std::uint8_t> bytes;
  std::size_t at = 0;
  const std::string& path;

  std::uint8_t byte() {
    if (at >= bytes.size()) throw Error(path + ": the Draco stream ends inside its header");
    return bytes[at++];
  }

  // Draco's varint: 7 bits a byte, least significant first; a count fits 5 bytes.
  std::uint64_t varint() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 35; shift += 7) {
      const std::uint8_t b = byte();
      value |= static_cast<std::uint64_t>(b & 0x7F) << shift;
      if ((b & 0x80) == 0) return value;
    }
    throw Error(path + ": a count in the Draco header is longer than 5 bytes");
  }
};

}  // namespace

DracoStreamCounts draco_stream_counts(std::span<const std::uint8_t> stream, const std::string& path) {
  if (stream.size() < kHeaderBytes || std::string_view(reinterpret_cast<const char*>(stream.data()), 5) != "DRACO") {
    throw Error(path + ": not a Draco stream (it does not start with \"DRACO\")");
  }
  const int major = stream[5], minor = stream[6], type = stream[7], method = stream[8];
  const auto flags = static_cast<std::uint16_t>(stream[9] | stream[10] << 8);
  if (major != 2 || minor != 2) {
    throw Error(fmt::format("{}: Draco bitstream version {}.{}; this loader reads 2.2 (Draco 1.3 and later)", path,
                            major, minor));
  }
  if (type != 1) throw Error(fmt::format("{}: the Draco stream is not a triangle mesh (encoder type {})", path, type));
  if ((flags & kMetadataFlag) != 0)
    throw Error(path + ": the Draco stream carries metadata, which this loader does not read");
  Reader reader{stream, kHeaderBytes, path};
  DracoStreamCounts counts;
  if (method == 0) {
    counts.faces = reader.varint();
    counts.vertices = reader.varint();
  } else if (method == 1) {
    (void)reader.byte();  // the traversal decoder: libdraco checks it
    counts.vertices = reader.varint();
    counts.faces = reader.varint();
    counts.vertices_are_points = false;
  } else {
    throw Error(fmt::format("{}: unknown Draco connectivity method {}", path, method));
  }
  return counts;
}

}  // namespace tilelight::gltf_detail
