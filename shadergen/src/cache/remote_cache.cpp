#include "cache/remote_cache.h"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "base/untrusted_text.h"
#include "cache/signed_entry.h"

namespace shadergen {
namespace {

using Clock = std::chrono::steady_clock;

std::string without_trailing_slashes(std::string url) {
  while (!url.empty() && url.back() == '/') url.pop_back();
  return url;
}

std::string relative_entry(std::string_view key) { return std::string(key.substr(0, 2)) + "/" + std::string(key); }

std::string seconds_text(std::chrono::milliseconds ms) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", static_cast<double>(ms.count()) / 1000.0);
  return text;
}

}  // namespace

bool is_remote_cache_url(std::string_view url) { return remote_cache_url_problem(url).empty(); }

std::string remote_cache_url_problem(std::string_view url) {
  bool http = false;
  for (std::string_view scheme : {"http://", "https://"})
    if (url.size() > scheme.size() && url.substr(0, scheme.size()) == scheme) http = true;
  if (!http) return "is not an http:// or https:// URL";
  if (url.find_first_of("?#") != std::string_view::npos)
    return "has a query or fragment ('?' or '#'), which the entry URLs <url>/<key-prefix>/<key> cannot carry; "
           "give the URL of the collection alone";
  return {};
}

RemoteCache::RemoteCache(RemoteCacheSettings settings, std::unique_ptr<HttpClient> http, Warn warn)
    : settings_(std::move(settings)),
      url_(without_trailing_slashes(settings_.url)),
      shown_url_(redacted_url(url_)),
      http_(std::move(http)),
      warn_(std::move(warn)) {}

RemoteCache::RemoteCache(std::string url, bool read_only, std::unique_ptr<HttpClient> http, Warn warn)
    : RemoteCache(RemoteCacheSettings{std::move(url), read_only, {}}, std::move(http), std::move(warn)) {}

std::string RemoteCache::entry_url(std::string_view key) const { return url_ + "/" + relative_entry(key); }

RemoteCache::Lookup RemoteCache::lookup(std::string_view key, const Check& check) {
  const std::string relative = relative_entry(key);
  bool not_found = false;
  auto body = fetch(relative, &not_found);
  if (!body) return Lookup{not_found ? Found::none : Found::no_answer, std::nullopt};
  auto entry = body_entry(*body);
  if (!entry) {
    reject(relative,
           "is not signed with this build's secret (SHADERGEN_REMOTE_CACHE_SECRET or "
           "--remote-cache-secret-file)");
    return Lookup{Found::rejected, std::nullopt};
  }
  // The one verification local entries get too: magic, key, sizes and checksum.
  auto blob = decode_cache_entry(key, *entry);
  if (!blob) {
    reject(relative, "is not a valid entry (truncated, corrupted, foreign or from another version)");
    return Lookup{Found::rejected, std::nullopt};
  }
  if (std::string unfit = check ? check(*blob) : std::string(); !unfit.empty()) {
    reject(relative, "holds SPIR-V unfit for this build (" + printable(unfit) + ")");
    return Lookup{Found::rejected, std::nullopt};
  }
  ++fetched_;
  return Lookup{Found::entry, std::move(blob)};
}

// The body of a 200, or nullopt: a 404 (counted as a miss, and *not_found set) or a failure
// (the cache turns off).
std::optional<std::string> RemoteCache::fetch(const std::string& relative, bool* not_found) {
  auto response = send("GET", relative);
  if (!response) return std::nullopt;
  if (response->status == 404) {
    if (not_found) *not_found = true;
    ++missed_;
    return std::nullopt;
  }
  if (response->status != 200) {
    turn_off("GET", relative, "HTTP " + std::to_string(response->status));
    return std::nullopt;
  }
  return std::move(response->body);
}

std::optional<std::string> RemoteCache::load_input_set(std::string_view key, Found* found) {
  if (found) *found = Found::no_answer;
  if (!signs()) return std::nullopt;
  bool not_found = false;
  auto body = fetch("inputs/" + std::string(key), &not_found);
  if (!body) {
    if (found && not_found) *found = Found::none;
    return std::nullopt;
  }
  auto entry = verified_entry(*body, settings_.secret);
  if (found) *found = entry ? Found::entry : Found::rejected;
  if (!entry) return std::nullopt;  // unsigned: preprocess as without it
  return std::string(*entry);
}

bool RemoteCache::store_input_set(std::string_view key, std::string_view bytes) {
  if (!signs() || settings_.read_only || off_.load()) return false;
  return put("inputs/" + std::string(key), signed_entry(bytes, settings_.secret));
}

// The entry inside a response body: it must carry a valid signature when there is a secret.
std::optional<std::string> RemoteCache::body_entry(std::string_view body) const {
  if (!signs()) return std::string(unsigned_entry(body));
  auto entry = verified_entry(body, settings_.secret);
  if (!entry) return std::nullopt;
  return std::string(*entry);
}

bool RemoteCache::store_text(const std::string& relative, std::string_view text) {
  if (settings_.read_only || off_.load()) return false;
  return put(relative, signs() ? signed_entry(text, settings_.secret) : std::string(text));
}

std::optional<std::string> RemoteCache::load_text(const std::string& relative, Found* found) {
  bool not_found = false;
  auto body = fetch(relative, &not_found);
  std::optional<std::string> text;
  if (body) text = body_entry(*body);
  if (found) *found = text ? Found::entry : body ? Found::rejected : not_found ? Found::none : Found::no_answer;
  return text;
}

bool RemoteCache::store(std::string_view key, const CachedBlob& blob) {
  if (settings_.read_only || off_.load()) return false;
  std::string entry = encode_cache_entry(key, blob);
  if (!put(relative_entry(key), signs() ? signed_entry(entry, settings_.secret) : std::move(entry))) return false;
  ++uploaded_;
  return true;
}

bool RemoteCache::offer(std::string_view key, const CachedBlob& blob) {
  if (settings_.read_only || off_.load()) return false;
  const std::string relative = relative_entry(key);
  auto response = send("HEAD", relative);
  if (!response) return false;
  if (response->status == 404) return store(key, blob);
  if (response->status >= 200 && response->status <= 299) return true;
  turn_off("HEAD", relative, "HTTP " + std::to_string(response->status));
  return false;
}

bool RemoteCache::put(const std::string& relative, std::string_view body) {
  auto response = send("PUT", relative, body);
  if (!response) return false;
  // 409: the collection <key[0:2]> (or the cache's own) does not exist yet.
  if (response->status == 409 && create_collections(relative)) response = send("PUT", relative, body);
  if (!response) return false;
  if (response->status < 200 || response->status > 299) {
    turn_off("PUT", relative, "HTTP " + std::to_string(response->status));
    return false;
  }
  return true;
}

// MKCOL the collection holding `relative` (<url>/<key[0:2]>/), creating <url>/ first when that
// is missing too (409 again). 405 means it exists already (another thread made it): fine.
bool RemoteCache::create_collections(const std::string& relative) {
  const std::string collection = relative.substr(0, relative.rfind('/') + 1);
  auto made = send("MKCOL", collection);
  if (made && made->status == 409) {
    if (!send("MKCOL", "")) return false;
    made = send("MKCOL", collection);
  }
  if (!made) return false;
  if ((made->status < 200 || made->status > 299) && made->status != 405) {
    turn_off("MKCOL", collection, "HTTP " + std::to_string(made->status));
    return false;
  }
  return true;
}

// One request for <url>/<relative> within the budget; nullopt when it got no answer (then the
// cache is off). Networked, it is tried again after a failure or a 5xx (RemoteCacheSettings).
std::optional<HttpResponse> RemoteCache::send(std::string_view method, const std::string& relative,
                                              std::string_view body) {
  if (!settings_.networked) return send_once(method, relative, body);
  std::chrono::seconds pause{1};
  for (int attempt = 0;; ++attempt, pause *= 2) {
    const bool last = attempt == kNetworkedRetries;
    auto response = send_once(method, relative, body, !last);
    // Off (another request used up its retries): no point in waiting.
    if (last || off_.load() || (response && response->status < 500)) return response;
    std::this_thread::sleep_for(pause);
  }
}

// One attempt. `quiet`: a failure neither warns nor turns the cache off (a retry follows).
std::optional<HttpResponse> RemoteCache::send_once(std::string_view method, const std::string& relative,
                                                   std::string_view body, bool quiet) {
  if (off_.load()) return std::nullopt;
  std::chrono::milliseconds limit = begin_request();
  if (limit.count() <= 0) {
    end_request();
    budget_spent();
    return std::nullopt;
  }
  const std::string url = url_ + "/" + relative;
  auto start = Clock::now();
  auto response = http_->send(HttpRequest{method, url, body, limit});
  end_request();
  if (response) return std::move(response).value();
  if (quiet) return std::nullopt;
  // A request shortened to fit the budget that ran its whole time failed because the budget
  // ran out, whatever the HTTP library says.
  bool ran_out = limit < settings_.request_limit && Clock::now() - start + std::chrono::milliseconds(50) >= limit;
  if (!settings_.networked && (ran_out || waited() >= settings_.budget))
    budget_spent();
  else
    turn_off(method, relative, without_credentials(response.errors().front().message, url_));
  return std::nullopt;
}

// What a new request may take: the per-request limit, or less when the budget is nearly spent.
std::chrono::milliseconds RemoteCache::begin_request() {
  std::lock_guard lock(clock_mutex_);
  auto now = Clock::now();
  auto spent = waited_ + (in_flight_ > 0 ? now - busy_since_ : Clock::duration{});
  if (in_flight_++ == 0) busy_since_ = now;
  if (settings_.networked) return settings_.request_limit;
  auto left = std::chrono::duration_cast<std::chrono::milliseconds>(settings_.budget - spent);
  return std::min(left, settings_.request_limit);
}

void RemoteCache::end_request() {
  std::lock_guard lock(clock_mutex_);
  if (--in_flight_ == 0) waited_ += Clock::now() - busy_since_;
}

Clock::duration RemoteCache::waited() {
  std::lock_guard lock(clock_mutex_);
  return waited_ + (in_flight_ > 0 ? Clock::now() - busy_since_ : Clock::duration{});
}

RemoteCacheStats RemoteCache::stats() const {
  return RemoteCacheStats{fetched_.load(), missed_.load(), uploaded_.load(), failed_.load()};
}

void RemoteCache::warn(const std::string& line) const {
  if (warn_) warn_(line);
}

// Requests already in flight on other threads may fail too: they are counted, not warned.
void RemoteCache::turn_off(std::string_view method, std::string_view relative, const std::string& failure) {
  ++failed_;
  if (off_.exchange(true)) return;
  warn("warning: remote cache " + shown_url_ + ": " + std::string(method) + " " + std::string(relative) + ": " +
       printable(failure) + "; the rest of this build does not use it");
}

void RemoteCache::budget_spent() {
  ++failed_;
  if (off_.exchange(true)) return;
  warn("warning: remote cache " + shown_url_ + ": its requests have kept this build waiting " +
       seconds_text(settings_.budget) +
       ", the whole budget (--remote-cache-budget); the rest of this build does not use it");
}

void RemoteCache::distrust(const std::string& why) {
  ++failed_;
  // One warning about bad entries per build: an earlier rejected entry already named the server.
  if (off_.exchange(true) || rejected_once_.exchange(true)) return;
  warn("warning: remote cache " + shown_url_ + ": its entries fail this build's checks (" + printable(why) +
       "); compiled here instead, and the rest of this build does not use it");
}

void RemoteCache::reject(std::string_view relative, const std::string& why) {
  ++failed_;
  if (rejected_once_.exchange(true)) return;
  const char* fate = settings_.role == RemoteRole::merge   ? "; the merge counts it corrupt (the first such entry only "
                                                             "is named here)"
                     : settings_.role == RemoteRole::shard ? "; this shard uploads its own copy in its place"
                                                           : "; compiled here instead";
  warn("warning: remote cache " + shown_url_ + ": " + std::string(relative) + " " + why + fate);
}

}  // namespace shadergen
