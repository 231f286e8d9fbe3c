#include "remote_cache.h"

namespace shadergen {
namespace {

std::string without_trailing_slashes(std::string url) {
  while (!url.empty() && url.back() == '/') url.pop_back();
  return url;
}

std::string relative_entry(std::string_view key) { return std::string(key.substr(0, 2)) + "/" + std::string(key); }

}  // namespace

bool is_remote_cache_url(std::string_view url) {
  for (std::string_view scheme : {"http://", "https://"})
    if (url.size() > scheme.size() && url.substr(0, scheme.size()) == scheme) return true;
  return false;
}

RemoteCache::RemoteCache(std::string url, bool read_only, std::unique_ptr<HttpClient> http, Warn warn)
    : url_(without_trailing_slashes(std::move(url))),
      read_only_(read_only),
      http_(std::move(http)),
      warn_(std::move(warn)) {}

std::string RemoteCache::entry_url(std::string_view key) const { return url_ + "/" + relative_entry(key); }

std::optional<CachedBlob> RemoteCache::load(std::string_view key) {
  if (off_.load()) return std::nullopt;
  auto response = http_->get(entry_url(key));
  if (!response) {
    turn_off("GET", key, response.errors().front().message);
    return std::nullopt;
  }
  if (response->status == 404) {
    ++missed_;
    return std::nullopt;
  }
  if (response->status != 200) {
    turn_off("GET", key, "HTTP " + std::to_string(response->status));
    return std::nullopt;
  }
  // The one verification local entries get too: magic, key, sizes and checksum.
  auto blob = decode_cache_entry(key, response->body);
  if (!blob) {
    reject(key);
    return std::nullopt;
  }
  ++fetched_;
  return blob;
}

void RemoteCache::store(std::string_view key, const CachedBlob& blob) {
  if (read_only_ || off_.load()) return;
  auto response = http_->put(entry_url(key), encode_cache_entry(key, blob));
  if (!response) return turn_off("PUT", key, response.errors().front().message);
  if (response->status < 200 || response->status > 299)
    return turn_off("PUT", key, "HTTP " + std::to_string(response->status));
  ++uploaded_;
}

RemoteCacheStats RemoteCache::stats() const {
  return RemoteCacheStats{fetched_.load(), missed_.load(), uploaded_.load(), failed_.load()};
}

// Requests already in flight on other threads may fail too: they are counted, not warned.
void RemoteCache::turn_off(std::string_view method, std::string_view key, const std::string& failure) {
  ++failed_;
  if (off_.exchange(true) || !warn_) return;
  warn_("warning: remote cache " + url_ + ": " + std::string(method) + " " + relative_entry(key) + ": " + failure +
        "; the rest of this build does not use it");
}

void RemoteCache::reject(std::string_view key) {
  ++failed_;
  if (rejected_once_.exchange(true) || !warn_) return;
  warn_("warning: remote cache " + url_ + ": " + relative_entry(key) +
        " is not a valid entry (truncated, corrupted, foreign or from another version); compiled here instead");
}

}  // namespace shadergen
