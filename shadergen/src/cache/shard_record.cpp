#include "cache/shard_record.h"

#include <charconv>
#include <map>

#include "base/sha256.h"

namespace shadergen {
namespace {

constexpr std::string_view kMagic = "shadergen-shard-record 1";

std::optional<std::uint32_t> number(const std::string& text) {
  std::uint32_t value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

}  // namespace

std::string shard_build_key(const std::filesystem::path& spec_path, std::string_view spec_digest,
                            std::string_view settings) {
  std::error_code ec;
  std::filesystem::path cwd = std::filesystem::current_path(ec);
  return Sha256()
      .field("shadergen-shard-build")
      .field(ec ? std::string() : cwd.string())
      .field(spec_path.string())
      .field(spec_digest)
      .field(settings)
      .finish_hex();
}

std::string shard_record_path(std::string_view build_key, std::uint32_t index, std::uint32_t count) {
  // Flat under shards/: a server without create_full_put_path makes one collection for it.
  return "shards/" + std::string(build_key) + "-" + std::to_string(index) + "-of-" + std::to_string(count);
}

CacheKeyParts recorded_tools(CacheKeyParts tools) {
  tools.optimiser_recipe = sha256_hex(tools.optimiser_recipe);
  return tools;
}

std::string encode_shard_record(const ShardRecord& record) {
  return std::string(kMagic) + "\nindex " + std::to_string(record.index) + "\ncount " + std::to_string(record.count) +
         "\ntool " + record.tools.tool_version + "\nglslang " + record.tools.glslang_version + "\nspirv-tools " +
         record.tools.spirv_tools_version + "\ntarget " + record.tools.target + "\noptimiser " +
         record.tools.optimiser_recipe + "\n";
}

std::optional<ShardRecord> decode_shard_record(std::string_view text) {
  if (text.substr(0, kMagic.size()) != kMagic || text.size() == kMagic.size() || text[kMagic.size()] != '\n')
    return std::nullopt;
  std::map<std::string, std::string> fields;
  std::size_t at = kMagic.size() + 1;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) return std::nullopt;  // every line ends with a newline
    std::string_view line = text.substr(at, end - at);
    std::size_t space = line.find(' ');
    if (space == std::string_view::npos) return std::nullopt;
    fields[std::string(line.substr(0, space))] = std::string(line.substr(space + 1));
    at = end + 1;
  }
  for (const char* name : {"index", "count", "tool", "glslang", "spirv-tools", "target", "optimiser"})
    if (!fields.count(name)) return std::nullopt;
  auto index = number(fields["index"]), count = number(fields["count"]);
  if (!index || !count || *index >= *count) return std::nullopt;
  return ShardRecord{
      *index, *count,
      CacheKeyParts{fields["tool"], fields["glslang"], fields["spirv-tools"], fields["target"], fields["optimiser"]}};
}

std::string tools_text(const CacheKeyParts& tools) {
  return "shadergen " + tools.tool_version + " (glslang " + tools.glslang_version + ", SPIRV-Tools " +
         tools.spirv_tools_version + ")";
}

std::string tools_difference(const CacheKeyParts& a, const CacheKeyParts& b) {
  if (a.tool_version != b.tool_version) return "the shadergen version";
  if (a.glslang_version != b.glslang_version) return "the glslang version";
  if (a.spirv_tools_version != b.spirv_tools_version) return "the SPIRV-Tools version";
  if (a.target != b.target) return "the target description";
  if (a.optimiser_recipe != b.optimiser_recipe) return "the optimiser recipe";
  return {};
}

}  // namespace shadergen
