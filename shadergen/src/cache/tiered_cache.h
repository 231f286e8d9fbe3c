// tiered_cache.h - the local content cache in front of the remote one, and the policy between
// them for one build:
//   - a lookup asks the local cache first, then the server; a local hit is offered to a server
//     that may be written and may lack it (a warm machine fills an empty server);
//   - what the server is known to hold (sent or received) is remembered in the local cache
//     between builds (ContentCache::keys_on_server), so a warm build offers only what it may lack;
//   - a server whose entries failed the build's checks together is set aside for the rest of
//     the build (no more lookups or uploads), and blamed with one warning when that is proven.
// A remote entry reaches the local cache only when the caller says the build has used it
// (kept()): the local cache never holds what the checks would reject.
#pragma once

#include <atomic>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "cache/cache.h"
#include "cache/remote_cache.h"

namespace shadergen {

class TieredCache {
 public:
  // Either may be null (no local cache, no remote cache); both must outlive this.
  TieredCache(const ContentCache* local, RemoteCache* remote) : local_(local), remote_(remote) {}

  struct Hit {
    CachedBlob blob;
    bool remote = false;  // taken from the server (not yet in the local cache)
  };
  // The entry of `key`: local, else a remote one that passes `check`. Thread-safe.
  std::optional<Hit> load(const std::string& key, const RemoteCache::Check& check);
  // A blob compiled here (the caller stores it locally): uploaded unless there is no server,
  // it is read-only, or it was set aside. Thread-safe.
  void upload(const std::string& key, const CachedBlob& blob);
  // A remote hit the whole build has used and the caller stored locally: the server holds it.
  void kept(const std::string& key) { note_on_server(key); }
  // Writes what the server is known to hold back to the local cache, when that changed.
  void remember_server_keys();

  // The server, unless there is none or it was set aside.
  bool remote_in_use() const { return remote_ && !set_aside_; }
  // No more lookups or uploads this build (its entries are being checked again without it).
  void set_aside_remote() { set_aside_ = true; }
  // Sets the server aside with one warning: its entries were unusable as a whole (`why`).
  void distrust_remote(const std::string& why);

 private:
  bool server_has(const std::string& key);
  void note_on_server(const std::string& key);

  const ContentCache* local_;
  RemoteCache* remote_;
  std::atomic<bool> set_aside_{false};
  std::mutex server_keys_mutex_;  // guards the three below
  std::set<std::string> server_keys_;
  bool server_keys_loaded_ = false, server_keys_changed_ = false;
};

}  // namespace shadergen
