#include "cache/cache.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "base/file_io.h"
#include "base/sha256.h"

namespace shadergen {
namespace {

constexpr std::string_view kMagic = "SGCACHE1";
constexpr std::size_t kKeyLength = 64;
constexpr std::size_t kMaxEntryWords = 64u << 20;  // 256 MiB: anything larger is corrupt

void put_u32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

bool get_u32(std::string_view& in, std::uint32_t& value) {
  if (in.size() < 4) return false;
  value = 0;
  for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(static_cast<unsigned char>(in[i])) << (8 * i);
  in.remove_prefix(4);
  return true;
}

bool take(std::string_view& in, std::size_t count, std::string_view& out) {
  if (in.size() < count) return false;
  out = in.substr(0, count);
  in.remove_prefix(count);
  return true;
}

}  // namespace

std::string entry_checksum(std::string_view key, const CachedBlob& blob);

std::string cache_key(const CacheKeyParts& parts, std::string_view stage_name, std::string_view preprocessed) {
  return Sha256()
      .field("shadergen-cache-entry")
      .field(parts.tool_version)
      .field(parts.glslang_version)
      .field(parts.spirv_tools_version)
      .field(parts.target)
      .field(parts.optimiser_recipe)
      .field(stage_name)
      .field(preprocessed)
      .finish_hex();
}

std::filesystem::path default_cache_directory() {
  if (const char* dir = std::getenv("SHADERGEN_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "shadergen";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "shadergen";
  return {};
}

// Covers every field after the checksum's own position, so no bit of an entry can change
// unnoticed (the fallback flag included).
std::string entry_checksum(std::string_view key, const CachedBlob& blob) {
  Sha256 hash;
  hash.field(key).field(blob.fell_back ? "1" : "0").field(blob.fallback_reason);
  return hash.update_words(blob.words).finish_hex();
}

std::string encode_cache_entry(std::string_view key, const CachedBlob& blob) {
  std::string out(kMagic);
  out += key;
  put_u32(out, blob.fell_back ? 1u : 0u);
  put_u32(out, static_cast<std::uint32_t>(blob.fallback_reason.size()));
  out += blob.fallback_reason;
  put_u32(out, static_cast<std::uint32_t>(blob.words.size()));
  out += entry_checksum(key, blob);
  for (std::uint32_t word : blob.words) put_u32(out, word);
  return out;
}

std::optional<CachedBlob> decode_cache_entry(std::string_view key, std::string_view in) {
  std::string_view magic, stored_key, reason, checksum;
  std::uint32_t flags = 0, reason_size = 0, word_count = 0;
  if (!take(in, kMagic.size(), magic) || magic != kMagic) return std::nullopt;
  if (!take(in, kKeyLength, stored_key) || stored_key != key) return std::nullopt;
  if (!get_u32(in, flags) || flags > 1 || !get_u32(in, reason_size) || !take(in, reason_size, reason))
    return std::nullopt;
  if (!get_u32(in, word_count) || word_count == 0 || word_count > kMaxEntryWords) return std::nullopt;
  if (!take(in, kKeyLength, checksum) || in.size() != std::size_t{word_count} * 4) return std::nullopt;
  CachedBlob blob;
  blob.fell_back = flags == 1;
  blob.fallback_reason = std::string(reason);
  blob.words.resize(word_count);
  for (std::uint32_t& word : blob.words) get_u32(in, word);
  if (entry_checksum(key, blob) != checksum) return std::nullopt;
  return blob;
}

std::filesystem::path ContentCache::entry_path(std::string_view key) const {
  return directory_ / std::string(key.substr(0, 2)) / std::string(key);
}

std::optional<CachedBlob> ContentCache::load(std::string_view key) const {
  if (!enabled() || key.size() != kKeyLength) return std::nullopt;
  auto bytes = read_file(entry_path(key));
  if (!bytes) return std::nullopt;
  return decode_cache_entry(key, bytes.value());
}

namespace {

std::filesystem::path server_keys_path(const std::filesystem::path& directory, std::string_view server) {
  return directory / "remote" / (sha256_hex(server).substr(0, 16) + ".keys");
}

bool is_key(std::string_view text) {
  return text.size() == kKeyLength && text.find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

}  // namespace

std::set<std::string> ContentCache::keys_on_server(std::string_view server) const {
  std::set<std::string> keys;
  if (!enabled()) return keys;
  auto text = read_file(server_keys_path(directory_, server));
  if (!text) return keys;
  std::string_view rest = text.value();
  while (!rest.empty()) {
    std::size_t end = std::min(rest.find('\n'), rest.size());
    if (is_key(rest.substr(0, end))) keys.emplace(rest.substr(0, end));
    rest.remove_prefix(std::min(end + 1, rest.size()));
  }
  return keys;
}

void ContentCache::remember_keys_on_server(std::string_view server, const std::set<std::string>& keys) const {
  if (!enabled()) return;
  std::filesystem::path path = server_keys_path(directory_, server);
  std::string text;
  text.reserve(keys.size() * (kKeyLength + 1));
  for (const std::string& key : keys) text += key + "\n";
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (!ec) (void)write_file_atomic(path, text, /*durable=*/false);
}

Status ContentCache::store(std::string_view key, const CachedBlob& blob) const {
  if (!enabled()) return Ok{};
  std::filesystem::path path = entry_path(key);
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return make_error(path.parent_path().string(), 0, "cannot create cache folder: " + ec.message());
  // Not synced: an entry checks itself on read, so one torn by a crash is only a miss, and a
  // build served by the remote cache writes hundreds of them.
  return write_file_atomic(path, encode_cache_entry(key, blob), /*durable=*/false);
}

}  // namespace shadergen
