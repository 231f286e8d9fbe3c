#include "cache/input_cache.h"

#include <algorithm>
#include <map>
#include <sstream>

#include "base/file_io.h"
#include "base/sha256.h"
#include "cache/cache.h"

namespace shadergen {
namespace {

constexpr std::string_view kMagic = "SGINPUT1";
constexpr std::size_t kKeyLength = 64;
constexpr std::size_t kMaxCount = 1u << 20;  // more files or jobs than this: corrupt

bool is_hex_key(std::string_view text) {
  return text.size() == kKeyLength &&
         std::all_of(text.begin(), text.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

// Reads "<word> <count>" and checks the word.
bool read_count(std::istream& in, std::string_view word, std::size_t& count) {
  std::string line;
  if (!std::getline(in, line) || line.rfind(std::string(word) + " ", 0) != 0) return false;
  std::string digits = line.substr(word.size() + 1);
  if (digits.empty() || digits.size() > 7 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  count = std::stoul(digits);
  return count <= kMaxCount;
}

// "F <digest> <path>" for a file read, "A - <path>" for a probe that found nothing.
std::optional<InputRead> parse_file_line(const std::string& line) {
  if (line.size() < 4 || line[1] != ' ') return std::nullopt;
  InputRead read;
  read.found = line[0] == 'F';
  if (!read.found && line[0] != 'A') return std::nullopt;
  std::size_t digest_end = line.find(' ', 2);
  if (digest_end == std::string::npos) return std::nullopt;
  std::string digest = line.substr(2, digest_end - 2);
  if (read.found ? !is_hex_key(digest) : digest != "-") return std::nullopt;
  if (read.found) read.digest = digest;
  read.path = line.substr(digest_end + 1);
  if (read.path.empty()) return std::nullopt;
  return read;
}

}  // namespace

std::string input_set_key(const CacheKeyParts& tools, const std::filesystem::path& spec_path,
                          std::string_view spec_digest, std::string_view settings) {
  std::error_code ec;
  std::filesystem::path cwd = std::filesystem::current_path(ec);
  return Sha256()
      .field("shadergen-input-set")
      // The content-cache key of nothing: changes with shadergen, glslang, SPIRV-Tools, the
      // target and the optimiser recipe, exactly when every content key does.
      .field(cache_key(tools, "input-set", ""))
      // Paths in the preprocessed text (and in the entry) are relative to where we run.
      .field(ec ? std::string() : cwd.string())
      .field(spec_path.string())
      .field(spec_digest)
      .field(settings)
      .finish_hex();
}

std::string input_set_part_key(std::string_view input_key, std::uint32_t index, std::uint32_t count) {
  return Sha256()
      .field("shadergen-input-set-part")
      .field(input_key)
      .field(std::to_string(index))
      .field(std::to_string(count))
      .finish_hex();
}

Result<InputSet> join_input_parts(std::vector<InputSet> parts) {
  const std::string count = std::to_string(parts.size());
  std::map<std::filesystem::path, std::pair<InputRead, std::size_t>> by_path;  // -> the read, its first part
  InputSet joined;
  for (std::size_t part = 0; part < parts.size(); ++part) {
    for (InputRead& read : parts[part].files) {
      auto [it, fresh] = by_path.try_emplace(read.path, read, part);
      if (!fresh && (it->second.first.found != read.found || it->second.first.digest != read.digest))
        return make_error("shards " + std::to_string(it->second.second) + "/" + count + " and " + std::to_string(part) +
                          "/" + count + " read different bytes of " + read.path.string() +
                          ": it changed while the shards ran; rerun the shards");
    }
    for (std::string& key : parts[part].source_keys) joined.source_keys.push_back(std::move(key));
  }
  joined.files.reserve(by_path.size());
  for (auto& [path, read] : by_path) joined.files.push_back(std::move(read.first));
  return joined;
}

std::optional<std::vector<InputRead>> merge_reads(const std::vector<std::vector<InputRead>>& per_job) {
  std::map<std::filesystem::path, InputRead> by_path;
  for (const auto& reads : per_job)
    for (const InputRead& read : reads) {
      auto [it, fresh] = by_path.try_emplace(read.path, read);
      if (!fresh && (it->second.found != read.found || it->second.digest != read.digest)) return std::nullopt;
    }
  std::vector<InputRead> out;
  out.reserve(by_path.size());
  for (auto& [path, read] : by_path) out.push_back(std::move(read));
  return out;
}

bool inputs_unchanged(const std::vector<InputRead>& files) {
  for (const InputRead& file : files) {
    std::error_code ec;
    bool present = std::filesystem::is_regular_file(file.path, ec);
    if (present != file.found) return false;
    if (!present) continue;
    auto bytes = read_file(file.path);
    if (!bytes || sha256_hex(*bytes) != file.digest) return false;
  }
  return true;
}

std::string encode_input_set(std::string_view key, const InputSet& set) {
  std::string body = std::string(kMagic) + "\n" + std::string(key) + "\n";
  body += "files " + std::to_string(set.files.size()) + "\n";
  for (const InputRead& file : set.files)
    body += std::string(file.found ? "F " + file.digest : "A -") + " " + file.path.string() + "\n";
  body += "jobs " + std::to_string(set.source_keys.size()) + "\n";
  for (const std::string& source_key : set.source_keys) body += source_key + "\n";
  return body + "checksum " + sha256_hex(body) + "\n";
}

std::optional<InputSet> decode_input_set(std::string_view key, std::string_view bytes) {
  std::size_t checksum_at = bytes.rfind("checksum ");
  if (checksum_at == std::string_view::npos) return std::nullopt;
  std::string_view body = bytes.substr(0, checksum_at);
  if (bytes.substr(checksum_at) != "checksum " + sha256_hex(body) + "\n") return std::nullopt;
  std::istringstream in{std::string(body)};
  std::string line;
  if (!std::getline(in, line) || line != kMagic) return std::nullopt;
  if (!std::getline(in, line) || line != key) return std::nullopt;
  InputSet set;
  std::size_t count = 0;
  if (!read_count(in, "files", count)) return std::nullopt;
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::getline(in, line)) return std::nullopt;
    auto read = parse_file_line(line);
    if (!read) return std::nullopt;
    set.files.push_back(std::move(*read));
  }
  if (!read_count(in, "jobs", count)) return std::nullopt;
  for (std::size_t i = 0; i < count; ++i) {
    if (!std::getline(in, line) || !is_hex_key(line)) return std::nullopt;
    set.source_keys.push_back(line);
  }
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;
  return set;
}

std::optional<InputSet> InputCache::load(std::string_view key) const {
  if (!enabled() || !is_hex_key(key)) return std::nullopt;
  auto bytes = read_file(entry_path(key));
  if (!bytes) return std::nullopt;
  return decode_input_set(key, *bytes);
}

Status InputCache::store(std::string_view key, const InputSet& set) const {
  if (!enabled()) return Ok{};
  // A path with a line break cannot be written in this format; such a build is not remembered.
  for (const InputRead& file : set.files)
    if (file.path.string().find('\n') != std::string::npos) return Ok{};
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  if (ec) return make_error(directory_.string(), 0, "cannot create cache folder: " + ec.message());
  // Not synced, like content entries: it checks itself on read.
  return write_file_atomic(entry_path(key), encode_input_set(key, set), /*durable=*/false);
}

}  // namespace shadergen
