// The remote cache's rules without a server: what it asks for, what it accepts, when it warns
// and when it stops asking. The real client and a real server are in remote_server_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "base/untrusted_text.h"
#include "cache/remote_cache.h"
#include "cache/signed_entry.h"
#include "cache/tiered_cache.h"

namespace shadergen {
namespace {

const std::string kKey = "ab" + std::string(62, '1');
const std::string kOtherKey = "cd" + std::string(62, '2');
const std::string kUrl = "http://cache.example:8080/shaders";

CachedBlob sample_blob() { return CachedBlob{{0x07230203u, 1u, 2u, 3u}, false, {}}; }

// Answers from a map of URL -> response; `failure`, when set, is every request's transport error.
class FakeHttp final : public HttpClient {
 public:
  Result<HttpResponse> send(const HttpRequest& request) override {
    std::lock_guard lock(mutex_);
    requests.push_back(std::string(request.method) + " " + request.url);
    if (!failure.empty()) return make_error(failure);
    if (request.method == "MKCOL") {
      collections.insert(request.url);
      return HttpResponse{201, {}};
    }
    if (request.method == "PUT") {
      if (needs_collections && !collections.count(request.url.substr(0, request.url.rfind('/') + 1)))
        return HttpResponse{409, "Conflict"};
      if (put_status != 201) return HttpResponse{put_status, {}};
      objects[request.url] = HttpResponse{200, std::string(request.body)};
      return HttpResponse{201, {}};
    }
    auto found = objects.find(request.url);
    if (found == objects.end()) return HttpResponse{404, "not found"};
    if (request.method == "HEAD") return HttpResponse{found->second.status, {}};
    return found->second;
  }

  std::set<std::string> collections;
  bool needs_collections = false;  // Apache mod_dav: PUT into a missing collection is 409
  std::map<std::string, HttpResponse> objects;
  std::vector<std::string> requests;
  std::string failure;
  long put_status = 201;

 private:
  std::mutex mutex_;
};

struct Fixture {
  FakeHttp* http = nullptr;  // owned by `cache`
  std::vector<std::string> warnings;
  std::unique_ptr<RemoteCache> cache;

  explicit Fixture(bool read_only = false) {
    auto client = std::make_unique<FakeHttp>();
    http = client.get();
    cache = std::make_unique<RemoteCache>(kUrl + "/", read_only, std::move(client),
                                          [this](const std::string& line) { warnings.push_back(line); });
  }
  std::string entry_url(const std::string& key) const { return kUrl + "/" + key.substr(0, 2) + "/" + key; }
};

TEST(RemoteCache, EntriesLiveAtUrlPrefixKey) {
  Fixture f;
  EXPECT_EQ(f.cache->url(), kUrl) << "the trailing slash is dropped";
  EXPECT_EQ(f.cache->entry_url(kKey), kUrl + "/ab/" + kKey);
}

TEST(RemoteCache, UploadsThenServesAVerifiedEntry) {
  Fixture f;
  EXPECT_FALSE(f.cache->load(kKey)) << "an empty server";
  f.cache->store(kKey, sample_blob());
  auto loaded = f.cache->load(kKey);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->words, sample_blob().words);
  EXPECT_EQ(f.http->objects.at(f.entry_url(kKey)).body, encode_cache_entry(kKey, sample_blob()))
      << "the server holds exactly a local entry's bytes";
  EXPECT_EQ(f.http->requests, (std::vector<std::string>{"GET " + f.entry_url(kKey), "PUT " + f.entry_url(kKey),
                                                        "GET " + f.entry_url(kKey)}));
  RemoteCacheStats s = f.cache->stats();
  EXPECT_EQ(s.fetched, 1u);
  EXPECT_EQ(s.missed, 1u);
  EXPECT_EQ(s.uploaded, 1u);
  EXPECT_EQ(s.failed, 0u);
  EXPECT_TRUE(f.warnings.empty());
}

// Each bad body is rejected by the same check local entries get, warned about once, and does not
// stop the remote cache from serving the next good entry.
TEST(RemoteCache, RejectsEveryDamagedEntryAndKeepsServingGoodOnes) {
  const std::string good = encode_cache_entry(kKey, sample_blob());
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x10);
  std::string other_format = good;
  other_format.replace(0, 8, "SGCACHE2");
  const std::map<std::string, std::string> bodies{
      {"truncated", good.substr(0, good.size() - 3)},
      {"one byte flipped", flipped},
      {"another key's entry", encode_cache_entry(kOtherKey, sample_blob())},
      {"another entry format", other_format},
      {"empty", ""},
      {"an HTML page", "<html><body>Welcome</body></html>"},
  };
  for (const auto& [what, body] : bodies) {
    Fixture f;
    f.http->objects[f.entry_url(kKey)] = HttpResponse{200, body};
    f.http->objects[f.entry_url(kOtherKey)] = HttpResponse{200, encode_cache_entry(kOtherKey, sample_blob())};
    EXPECT_FALSE(f.cache->load(kKey)) << what;
    EXPECT_FALSE(f.cache->load(kKey)) << what << ", asked again";
    EXPECT_TRUE(f.cache->load(kOtherKey)) << what;
    EXPECT_EQ(f.warnings, std::vector<std::string>{"warning: remote cache " + kUrl + ": ab/" + kKey +
                                                   " is not a valid entry (truncated, corrupted, foreign or from "
                                                   "another version); compiled here instead"})
        << what;
    EXPECT_EQ(f.cache->stats().failed, 2u) << what;
    EXPECT_EQ(f.cache->stats().fetched, 1u) << what;
  }
}

struct FailureCase {
  std::string what;
  std::string transport_error;  // empty: the server answers with `get_status` / `put_status`
  long get_status = 404;
  long put_status = 201;
  std::string expected_warning_tail;
};

// A failed request warns once, naming the URL, the request and the failure; after it the remote
// cache sends nothing more, so a dead server costs one request, not one per source.
TEST(RemoteCache, FirstFailureWarnsOnceAndStopsAllRequests) {
  const std::string get = "GET ab/" + kKey + ": ", put = "PUT ab/" + kKey + ": ";
  const std::vector<FailureCase> cases{
      {"connection refused", "Failed to connect: Couldn't connect to server", 404, 201,
       get + "Failed to connect: Couldn't connect to server"},
      {"timeout", "Operation timed out after 10000 milliseconds", 404, 201,
       get + "Operation timed out after 10000 milliseconds"},
      {"GET answered 500", "", 500, 201, get + "HTTP 500"},
      {"GET answered 403", "", 403, 201, get + "HTTP 403"},
      {"PUT answered 500", "", 404, 500, put + "HTTP 500"},
      {"PUT answered 405 (PUT not enabled)", "", 404, 405, put + "HTTP 405"},
  };
  for (const FailureCase& c : cases) {
    Fixture f;
    f.http->failure = c.transport_error;
    f.http->put_status = c.put_status;
    if (c.get_status != 404) f.http->objects[f.entry_url(kKey)] = HttpResponse{c.get_status, "error page"};
    EXPECT_FALSE(f.cache->load(kKey)) << c.what;
    f.cache->store(kKey, sample_blob());
    std::size_t requests = f.http->requests.size();
    EXPECT_FALSE(f.cache->load(kOtherKey)) << c.what;
    f.cache->store(kOtherKey, sample_blob());
    EXPECT_EQ(f.http->requests.size(), requests) << c.what << ": no request after the failure";
    EXPECT_EQ(f.warnings, std::vector<std::string>{"warning: remote cache " + kUrl + ": " + c.expected_warning_tail +
                                                   "; the rest of this build does not use it"})
        << c.what;
    EXPECT_EQ(f.cache->stats().failed, 1u) << c.what;
    EXPECT_EQ(f.cache->stats().uploaded, 0u) << c.what;
  }
}

TEST(RemoteCache, ReadOnlyNeverUploads) {
  Fixture f(/*read_only=*/true);
  f.http->objects[f.entry_url(kOtherKey)] = HttpResponse{200, encode_cache_entry(kOtherKey, sample_blob())};
  EXPECT_FALSE(f.cache->load(kKey));
  f.cache->store(kKey, sample_blob());
  EXPECT_TRUE(f.cache->load(kOtherKey)) << "it still reads";
  EXPECT_EQ(f.http->requests, (std::vector<std::string>{"GET " + f.entry_url(kKey), "GET " + f.entry_url(kOtherKey)}));
  EXPECT_EQ(f.cache->stats().uploaded, 0u);
}

// Compile threads fail together when a server dies: one warning still, every failure counted.
TEST(RemoteCache, ConcurrentFailuresWarnOnce) {
  Fixture f;
  f.http->failure = "Connection reset by peer";
  std::vector<std::thread> threads;
  for (int i = 0; i < 8; ++i)
    threads.emplace_back([&] {
      for (int j = 0; j < 50; ++j) f.cache->load(kKey);
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(f.warnings.size(), 1u);
  EXPECT_GE(f.cache->stats().failed, 1u);
  EXPECT_EQ(f.cache->stats().failed, f.http->requests.size()) << "every request that went out failed";
}

TEST(RemoteCache, AcceptsOnlyHttpUrls) {
  for (const char* url : {"http://host", "https://host:9090/cache/", "http://127.0.0.1:1"})
    EXPECT_TRUE(is_remote_cache_url(url)) << url;
  for (const char* url : {"", "host:8080", "ftp://host", "http://", "file:///tmp/cache", "HTTP//host"})
    EXPECT_FALSE(is_remote_cache_url(url)) << url;
}

// Apache's mod_dav: a PUT into a missing collection is 409; the cache creates it and retries.
TEST(RemoteCache, CreatesMissingCollectionsOn409) {
  Fixture f;
  f.http->needs_collections = true;
  EXPECT_TRUE(f.cache->store(kKey, sample_blob()));
  EXPECT_EQ(f.http->requests, (std::vector<std::string>{"PUT " + f.entry_url(kKey), "MKCOL " + kUrl + "/ab/",
                                                        "PUT " + f.entry_url(kKey)}));
  EXPECT_TRUE(f.cache->load(kKey));
  EXPECT_TRUE(f.warnings.empty());
}

// With a secret: uploads carry the HMAC trailer; unsigned, wrongly signed and re-keyed entries
// (the key field rewritten and the checksum recomputed, the old trailer kept) are refused.
TEST(RemoteCache, SignedEntriesRefuseEverythingElse) {
  auto signed_cache = [](FakeHttp*& http, std::vector<std::string>& warnings, std::string secret) {
    auto client = std::make_unique<FakeHttp>();
    http = client.get();
    RemoteCacheSettings settings{kUrl, false, std::move(secret)};
    return std::make_unique<RemoteCache>(std::move(settings), std::move(client),
                                         [&warnings](const std::string& line) { warnings.push_back(line); });
  };
  FakeHttp* http = nullptr;
  std::vector<std::string> warnings;
  auto cache = signed_cache(http, warnings, "k");
  const std::string url = kUrl + "/ab/" + kKey, other_url = kUrl + "/cd/" + kOtherKey;
  cache->store(kKey, sample_blob());
  EXPECT_EQ(http->objects.at(url).body, signed_entry(encode_cache_entry(kKey, sample_blob()), "k"));
  EXPECT_TRUE(cache->load(kKey));

  const std::string signed_body = http->objects.at(url).body;
  const std::string rekeyed =
      encode_cache_entry(kOtherKey, sample_blob()) + signed_body.substr(signed_body.size() - 39);
  const std::map<std::string, std::string> refused{
      {"unsigned", encode_cache_entry(kOtherKey, sample_blob())},
      {"signed with another secret", signed_entry(encode_cache_entry(kOtherKey, sample_blob()), "guess")},
      {"re-keyed", rekeyed},
  };
  for (const auto& [what, body] : refused) {
    http->objects[other_url] = HttpResponse{200, body};
    EXPECT_FALSE(cache->load(kOtherKey)) << what;
  }
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("is not signed with this build's secret"), std::string::npos) << warnings[0];
}

// A server that answers slowly turns the cache off once the budget is spent, and each request is
// given at most what is left of the budget.
TEST(RemoteCache, BudgetLimitsEveryRequest) {
  class SlowHttp final : public HttpClient {
   public:
    Result<HttpResponse> send(const HttpRequest& request) override {
      timeouts.push_back(request.timeout);
      std::this_thread::sleep_for(std::chrono::milliseconds(60));
      return HttpResponse{404, {}};
    }
    std::vector<std::chrono::milliseconds> timeouts;
  };
  auto client = std::make_unique<SlowHttp>();
  SlowHttp* http = client.get();
  std::vector<std::string> warnings;
  RemoteCache cache(RemoteCacheSettings{kUrl, true, {}, std::chrono::milliseconds(200), std::chrono::milliseconds(150)},
                    std::move(client), [&](const std::string& line) { warnings.push_back(line); });
  for (int i = 0; i < 20; ++i) cache.load(kKey);
  ASSERT_GE(http->timeouts.size(), 2u);
  EXPECT_LE(http->timeouts.size(), 5u) << "about 200 ms / 60 ms requests";
  EXPECT_EQ(http->timeouts[0], std::chrono::milliseconds(150)) << "the per-request limit";
  EXPECT_LT(http->timeouts.back(), std::chrono::milliseconds(150)) << "what is left of the budget";
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "warning: remote cache " + kUrl +
                             ": its requests have kept this build waiting 0.2 s, the whole budget "
                             "(--remote-cache-budget); the rest of this build does not use it");
}

TEST(RemoteCache, CredentialsAreRedacted) {
  EXPECT_EQ(redacted_url("https://alice:pw@host:8080/cache"), "https://***@host:8080/cache");
  EXPECT_EQ(redacted_url("http://token@host/c"), "http://***@host/c");
  EXPECT_EQ(redacted_url("http://host/a@b"), "http://host/a@b") << "an @ in the path is not userinfo";
  EXPECT_EQ(without_credentials("Failed for alice:pw and pw", "http://alice:pw@host"), "Failed for *** and ***");
  Fixture f;
  RemoteCache cache("http://alice:pw@host/cache", false, std::make_unique<FakeHttp>(), {});
  EXPECT_EQ(cache.shown_url(), "http://***@host/cache");
}

TEST(RemoteCache, ServerTextIsPrintable) {
  EXPECT_EQ(printable("ok\x1b[31mred\n\tend\\"), "ok\\x1b[31mred\\n\\tend\\\\");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\\xc3\\xa9");
  EXPECT_EQ(printable(std::string(10, 'a'), 4), "aaaa ... (6 more bytes)");
}

// The local cache in front of the remote one (tiered_cache.h): a local hit is offered to the
// server once, and remembered so a later build does not ask again; a remote hit is not kept
// locally by the lookup; a server set aside is asked nothing, and blamed with one warning.
TEST(TieredCache, OffersLocalHitsOnceAndSetsADistrustedServerAside) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "shadergen_tiered_cache_test";
  std::filesystem::remove_all(dir);
  const ContentCache local(dir);
  ASSERT_TRUE(local.store(kKey, sample_blob()));
  Fixture f;
  {
    TieredCache tiers(&local, f.cache.get());
    auto hit = tiers.load(kKey, {});
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit->remote);
    EXPECT_EQ(f.http->objects.count(f.entry_url(kKey)), 1u) << "offered: the server lacked it";
    tiers.remember_server_keys();
  }
  f.http->requests.clear();
  TieredCache tiers(&local, f.cache.get());
  ASSERT_TRUE(tiers.load(kKey, {}));
  EXPECT_TRUE(f.http->requests.empty()) << "the server is known to hold it";

  f.cache->store(kOtherKey, sample_blob());
  auto remote = tiers.load(kOtherKey, {});
  ASSERT_TRUE(remote);
  EXPECT_TRUE(remote->remote);
  EXPECT_FALSE(local.load(kOtherKey)) << "only kept() entries reach the local cache, through the caller";

  f.http->requests.clear();
  tiers.set_aside_remote();
  EXPECT_FALSE(tiers.remote_in_use());
  EXPECT_FALSE(tiers.load(kOtherKey, {}));
  tiers.upload(kOtherKey, sample_blob());
  EXPECT_TRUE(f.http->requests.empty()) << "a server set aside is asked nothing";
  tiers.distrust_remote("the entries fail together");
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("the entries fail together"), std::string::npos) << f.warnings[0];
  std::filesystem::remove_all(dir);
}

TEST(RemoteCache, UrlsWithQueryOrFragmentAreRefused) {
  EXPECT_FALSE(is_remote_cache_url("http://host/cache?x=1"));
  EXPECT_FALSE(is_remote_cache_url("http://host/cache#frag"));
  EXPECT_NE(remote_cache_url_problem("http://host/cache?x=1").find("query or fragment"), std::string::npos);
}

}  // namespace
}  // namespace shadergen
