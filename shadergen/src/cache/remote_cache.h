// remote_cache.h - the content cache shared over HTTP: a team's CI and its developers compile
// each distinct source once, through a server they already run (nginx or Apache WebDAV, the
// servers ccache's HTTP storage uses, bazel-remote behind a rewrite).
//
// Layout: the entry of key K is GET/PUT at <url>/<K[0:2]>/<K>, its body exactly the bytes of a
// local entry (encode_cache_entry), followed by a signature trailer when a secret is set
// (signed_entry.h). A PUT refused with 409 (the <K[0:2]> collection does not exist: Apache's
// mod_dav, nginx without create_full_put_path) creates it with MKCOL and is sent again.
//
// What the server says is not trusted. An entry is used only when it decodes like a local
// entry (magic, key, sizes, checksum), carries a valid signature when a secret is set, and
// passes the caller's check (the build validates its SPIR-V for the target and the stage, and
// reflects it before use). A rejected entry prints one warning (the first only) naming the
// server and is compiled here; it keeps the remote cache on: one bad object says nothing about
// the others.
//
// The network never fails a build, and never costs it more than the time budget. The first
// request that gets no answer, or an answer other than the entry or 404 (GET/HEAD) or 2xx (PUT),
// prints one warning naming the URL and the failure and turns the remote cache off for the rest
// of the build: a dead server costs one timeout, not one per source. Requests also share a
// budget of waiting time (the wall-clock time during which any request is in flight); each
// request may take at most what is left of it (and at most the per-request limit), and once it
// is spent the remote cache turns off with one warning. So a slow server costs a build at most
// the budget, however many sources it has.
//
// Credentials in the URL ("user:password@") are never printed: every message carries the URL
// with them replaced by "***".
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include "cache/cache.h"
#include "cache/http_client.h"
#include "cache/remote_defaults.h"
#include "cache/remote_stats.h"

namespace shadergen {

enum class RemoteRole { build, shard, merge };

struct RemoteCacheSettings {
  std::string url;  // is_remote_cache_url(); a trailing '/' is dropped
  bool read_only = false;
  // Not empty: uploads are signed with it, and only entries signed with it are accepted.
  std::string secret;
  // The waiting time all requests of one build may cost together, and each one at most.
  std::chrono::milliseconds budget = kDefaultRemoteCacheBudget;
  std::chrono::milliseconds request_limit = kDefaultRemoteCacheRequestLimit;
  // A shard or a merge (build --shard, --require-remote-hits) lives on the network: no budget,
  // and a request that gets no answer or a 5xx is sent again, up to kNetworkedRetries more
  // times, after 1, 2 and 4 s. Each attempt still waits at most request_limit.
  bool networked = false;
  // Who reads the entries, for what its warnings say becomes of a rejected one: a build
  // compiles it here, a shard uploads its own copy in its place, a merge counts it corrupt.
  RemoteRole role = RemoteRole::build;
};

inline constexpr int kNetworkedRetries = 3;

class RemoteCache {
 public:
  using Warn = std::function<void(const std::string&)>;
  // The reason an entry's blob is unfit for this build, or empty when it is fit.
  using Check = std::function<std::string(const CachedBlob&)>;

  // Preconditions: `http` is not null. `warn` receives whole warning lines ("warning: remote
  // cache ..."); may be empty.
  RemoteCache(RemoteCacheSettings settings, std::unique_ptr<HttpClient> http, Warn warn);
  RemoteCache(std::string url, bool read_only, std::unique_ptr<HttpClient> http, Warn warn);

  // What a lookup found: the entry (verified as load() says), none (404), an entry that failed
  // the checks (rejected: unsigned, corrupt, foreign or unfit), or no answer (the cache is off).
  enum class Found { entry, none, rejected, no_answer };
  struct Lookup {
    Found found = Found::no_answer;
    std::optional<CachedBlob> blob;  // only with Found::entry
  };
  Lookup lookup(std::string_view key, const Check& check = {});
  // The verified entry of `key` that passes `check` (when given), or nullopt (a miss, a
  // rejected entry, a failure, or off).
  std::optional<CachedBlob> load(std::string_view key, const Check& check = {}) { return lookup(key, check).blob; }
  // Uploads the entry unless read-only or off; true when it was uploaded. Never fails: failures
  // only warn and count.
  bool store(std::string_view key, const CachedBlob& blob);
  // Uploads the entry if the server lacks it (a HEAD answered 404): how a machine whose local
  // cache is warm fills an empty server. True when the server holds the entry now.
  bool offer(std::string_view key, const CachedBlob& blob);
  // The input-set entry of `key` (input_cache.h) at <url>/inputs/<key>, signed like entries;
  // only with a secret (nullopt without one, and for unsigned or wrongly signed bodies). An
  // input set maps the bytes of every file a build reads to the content keys, so a server
  // writer could redirect a build to other (valid) entries with it: unsigned ones are not used.
  // `found` (when given) says why there is none: a 404, a body that failed the signature, or no
  // answer (also: no secret).
  std::optional<std::string> load_input_set(std::string_view key, Found* found = nullptr);
  // Uploads an input-set entry's bytes, signed; only with a secret and unless read-only or off.
  // True when stored.
  bool store_input_set(std::string_view key, std::string_view bytes);
  // A small signed text at <url>/<relative> (a shard's record, shard_record.h): signed when there
  // is a secret, and read only when its signature holds. store_text() returns true when stored;
  // load_text() nullopt for a 404, a failure or a bad signature, and `found` says which.
  bool store_text(const std::string& relative, std::string_view text);
  std::optional<std::string> load_text(const std::string& relative, Found* found = nullptr);
  // Turns the remote cache off with one warning: the build found its entries unusable as a
  // whole (`why`, untrusted text allowed) and compiles them here.
  void distrust(const std::string& why);

  std::string entry_url(std::string_view key) const;
  const std::string& url() const { return url_; }
  // The URL as messages show it: credentials replaced by "***".
  const std::string& shown_url() const { return shown_url_; }
  bool read_only() const { return settings_.read_only; }
  bool signs() const { return !settings_.secret.empty(); }
  RemoteCacheStats stats() const;

 private:
  std::optional<HttpResponse> send(std::string_view method, const std::string& relative, std::string_view body = {});
  std::optional<HttpResponse> send_once(std::string_view method, const std::string& relative, std::string_view body,
                                        bool quiet = false);
  std::optional<std::string> fetch(const std::string& relative, bool* not_found = nullptr);
  std::optional<std::string> body_entry(std::string_view body) const;
  bool put(const std::string& relative, std::string_view body);
  bool create_collections(const std::string& relative);
  void turn_off(std::string_view method, std::string_view relative, const std::string& failure);
  void budget_spent();
  void reject(std::string_view relative, const std::string& why);
  void warn(const std::string& line) const;

  // The wall-clock time during which at least one request was in flight, so far.
  std::chrono::steady_clock::duration waited();
  std::chrono::milliseconds begin_request();
  void end_request();

  RemoteCacheSettings settings_;
  std::string url_;        // without a trailing '/'
  std::string shown_url_;  // url_ without credentials
  std::unique_ptr<HttpClient> http_;
  Warn warn_;
  std::atomic<bool> off_{false};
  std::atomic<bool> rejected_once_{false};
  std::atomic<std::uint32_t> fetched_{0}, missed_{0}, uploaded_{0}, failed_{0};
  std::mutex clock_mutex_;
  int in_flight_ = 0;
  std::chrono::steady_clock::time_point busy_since_;
  std::chrono::steady_clock::duration waited_{};
};

// True for "http://..." and "https://..." with something after the scheme.
bool is_remote_cache_url(std::string_view url);
// Why `url` cannot be a remote cache URL ("is not an http:// or https:// URL", "has a query
// ..."), or empty when it can. The entry URLs are built by appending to it, so it can carry
// neither a query nor a fragment.
std::string remote_cache_url_problem(std::string_view url);

}  // namespace shadergen
