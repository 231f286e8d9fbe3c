#include "cache/tiered_cache.h"

#include <utility>

namespace shadergen {

std::optional<TieredCache::Hit> TieredCache::load(const std::string& key, const RemoteCache::Check& check) {
  if (local_)
    if (auto hit = local_->load(key)) {
      if (remote_ && !remote_->read_only() && !server_has(key) && remote_->offer(key, *hit)) note_on_server(key);
      return Hit{std::move(*hit), false};
    }
  if (!remote_in_use()) return std::nullopt;
  if (auto hit = remote_->load(key, check)) return Hit{std::move(*hit), true};
  return std::nullopt;
}

void TieredCache::upload(const std::string& key, const CachedBlob& blob) {
  if (remote_in_use() && remote_->store(key, blob)) note_on_server(key);
}

void TieredCache::remember_server_keys() {
  std::lock_guard lock(server_keys_mutex_);
  if (local_ && remote_ && server_keys_changed_) local_->remember_keys_on_server(remote_->shown_url(), server_keys_);
}

void TieredCache::distrust_remote(const std::string& why) {
  set_aside_ = true;
  if (remote_) remote_->distrust(why);
}

// What the local cache knows the server holds, read on first use.
bool TieredCache::server_has(const std::string& key) {
  std::lock_guard lock(server_keys_mutex_);
  if (!server_keys_loaded_ && local_ && remote_) server_keys_ = local_->keys_on_server(remote_->shown_url());
  server_keys_loaded_ = true;
  return server_keys_.count(key) > 0;
}

void TieredCache::note_on_server(const std::string& key) {
  if (!server_has(key)) {
    std::lock_guard lock(server_keys_mutex_);
    server_keys_changed_ = server_keys_.insert(key).second || server_keys_changed_;
  }
}

}  // namespace shadergen
