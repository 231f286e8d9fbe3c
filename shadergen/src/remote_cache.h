// remote_cache.h - the content cache shared over HTTP: a team's CI and its developers compile
// each distinct source once, through a server they already run (nginx WebDAV, the servers
// ccache's HTTP storage uses, bazel-remote behind a rewrite).
//
// Layout: the entry of key K is GET/PUT at <url>/<K[0:2]>/<K>, its body exactly the bytes of a
// local entry (encode_cache_entry), and it is verified by the same decode_cache_entry: a
// truncated, corrupted, foreign or other-version entry is rejected and compiled locally.
//
// The network never fails a build. The first request that gets no answer, or an answer other
// than the entry or 404 (GET) or 2xx (PUT), prints one warning naming the URL and the failure
// and turns the remote cache off for the rest of the build: a dead server costs one timeout,
// not one per source. A rejected entry prints one warning too (the first only) but keeps the
// remote cache on: one bad object says nothing about the others.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "cache.h"
#include "http_client.h"

namespace shadergen {

struct RemoteCacheStats {
  std::uint32_t fetched = 0;   // verified entries taken from the server
  std::uint32_t missed = 0;    // GETs answered 404
  std::uint32_t uploaded = 0;  // PUTs answered 2xx
  std::uint32_t failed = 0;    // requests without a usable answer, and rejected entries
};

class RemoteCache {
 public:
  using Warn = std::function<void(const std::string&)>;

  // Preconditions: `url` is an http:// or https:// URL (is_remote_cache_url), `http` is not
  // null. `warn` receives whole warning lines ("warning: remote cache ..."); may be empty.
  RemoteCache(std::string url, bool read_only, std::unique_ptr<HttpClient> http, Warn warn);

  // The verified entry of `key`, or nullopt (a miss, a rejected entry, a failure, or off).
  std::optional<CachedBlob> load(std::string_view key);
  // Uploads the entry unless read-only or off. Never fails: failures only warn and count.
  void store(std::string_view key, const CachedBlob& blob);

  std::string entry_url(std::string_view key) const;
  const std::string& url() const { return url_; }
  bool read_only() const { return read_only_; }
  RemoteCacheStats stats() const;

 private:
  void turn_off(std::string_view method, std::string_view key, const std::string& failure);
  void reject(std::string_view key);

  std::string url_;  // without a trailing '/'
  bool read_only_;
  std::unique_ptr<HttpClient> http_;
  Warn warn_;
  std::atomic<bool> off_{false};
  std::atomic<bool> rejected_once_{false};
  std::atomic<std::uint32_t> fetched_{0}, missed_{0}, uploaded_{0}, failed_{0};
};

// True for "http://..." and "https://..." with something after the scheme.
bool is_remote_cache_url(std::string_view url);

}  // namespace shadergen
