// The remote cache against a hostile server of the tests' own (fake_http_server.h): entries
// that are well formed (their checksums recomputed, as anyone who can write a server can do) but
// hold random or foreign SPIR-V, a server that answers every request after 3 s, credentials in
// the URL, text with terminal escape sequences. Each build must succeed with a cold build's
// bytes, warn once naming the server (without its credentials) and leave the local cache clean.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <random>
#include <sstream>
#include <tuple>

#include <testsupport/fake_http_server.h>
#include "cache/cache.h"
#include "compile/entry_check.h"
#include "compile/glsl_compiler.h"
#include "remote_builds.h"
#include "shadergen/build.h"
#include "shadergen/cli.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;
using sgtest::build_toy;
using sgtest::build_toy_with;
using sgtest::RemoteBuild;
using testsupport::FakeHttpServer;
using testsupport::FakeReply;
using testsupport::FakeRequest;

// The key a request asks for: the last path component.
std::string key_of(const FakeRequest& request) { return request.path.substr(request.path.rfind('/') + 1); }

// Serves, for the first `count` keys asked, a well-formed entry of that key holding `words`;
// 404 for the others.
FakeHttpServer::Handler serving(const std::vector<std::uint32_t>& words, int count) {
  auto served = std::make_shared<std::atomic<int>>(0);
  return [words, count, served](const FakeRequest& request) {
    if (request.method != "GET") return FakeReply{201, {}};
    if (served->fetch_add(1) >= count) return FakeReply{404, {}};
    return FakeReply{200, encode_cache_entry(key_of(request), CachedBlob{words, false, {}})};
  };
}

// A valid fragment shader whose set 0 binding 0 is a texture where the toy domain has its
// uniform block: each entry passes validation and reflection, the merged layout does not.
std::vector<std::uint32_t> foreign_fragment_shader(const fs::path& dir) {
  const fs::path path = dir / "foreign.frag";
  sgtest::write_file(path,
                     "#version 450\nlayout(set = 0, binding = 0) uniform sampler2D stolen;\n"
                     "layout(location = 0) in vec2 in_uv;\nlayout(location = 0) out vec4 out_color;\n"
                     "void main() { out_color = texture(stolen, in_uv); }\n");
  auto words = compile(GlslSource{path, Stage::fragment, {}, {}, {}, TargetEnv::vulkan1_2});
  EXPECT_TRUE(words.ok());
  return words ? *words : std::vector<std::uint32_t>{};
}

// After a build against a hostile server, the local cache alone must give the cold bytes.
void expect_clean_local_cache(const fs::path& dir, const std::string& name,
                              const std::map<std::string, std::string>& expected) {
  RemoteBuild offline = build_toy(dir, name, "");
  ASSERT_TRUE(offline.summary) << name << ": " << offline.errors;
  EXPECT_EQ(offline.summary->compiled, 0u) << name << ": everything came from the local cache";
  EXPECT_EQ(offline.output, expected) << name << ": the local cache holds nothing from the server";
}

TEST(RemoteCacheHostile, WellFormedEntriesWithBadSpirvAreCompiledHere) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  const auto expected = sgtest::reference_output(dir);
  std::mt19937 random(26);
  std::vector<std::uint32_t> noise{0x07230203u, 0x00010500u, 0u, 64u, 0u};
  for (int i = 0; i < 200; ++i) noise.push_back(static_cast<std::uint32_t>(random()));
  const std::vector<std::uint32_t> foreign = foreign_fragment_shader(dir);
  // The toy domain's 12 fragment sources are asked for first, then its compute companion.
  const std::vector<std::tuple<std::string, std::vector<std::uint32_t>, int>> payloads{
      {"random words after a SPIR-V header", noise, 13},
      {"a foreign shader whose layout conflicts with the rest", foreign, 1},
  };
  int run = 0;
  for (const auto& [what, words, count] : payloads) {
    FakeHttpServer server(serving(words, count));
    ASSERT_TRUE(server.running());
    const std::string name = "reader" + std::to_string(run++);
    RemoteBuild result = build_toy(dir, name, server.url(), true);
    ASSERT_TRUE(result.summary) << what << ": " << result.errors;
    EXPECT_EQ(result.summary->compiled, 13u) << what;

    EXPECT_EQ(result.output, expected) << what;
    ASSERT_EQ(result.warnings.size(), 1u) << what;
    EXPECT_EQ(result.warnings[0].rfind("warning: remote cache " + server.url() + ": ", 0), 0u) << result.warnings[0];
    EXPECT_NE(result.warnings[0].find("compiled here instead"), std::string::npos) << result.warnings[0];
    expect_clean_local_cache(dir, name, expected);
  }
}

// The per-entry check: valid SPIR-V for the target, an entry point of the job's stage, reflects.
TEST(RemoteCacheHostile, EntryCheckRefusesNoiseAndOtherStages) {
  sgtest::TempDir run_dir("run");
  const std::vector<std::uint32_t> fragment = foreign_fragment_shader(run_dir.path());
  EXPECT_EQ(unfit_reason(fragment, Stage::fragment, TargetEnv::vulkan1_2), "");
  EXPECT_EQ(unfit_reason(fragment, Stage::compute, TargetEnv::vulkan1_2), "no entry point of the expected stage");
  EXPECT_NE(unfit_reason(std::vector<std::uint32_t>{0x07230203u, 0x00010500u, 0u, 9u, 0u, 1u, 2u}, Stage::fragment,
                         TargetEnv::vulkan1_2),
            "");
  // A signed entry gets the stage check alone; on words that are not SPIR-V it still answers.
  EXPECT_EQ(wrong_stage_reason(fragment, Stage::fragment), "");
  EXPECT_EQ(wrong_stage_reason(fragment, Stage::compute), "no entry point of the expected stage");
  EXPECT_EQ(wrong_stage_reason(std::vector<std::uint32_t>{0x07230203u, 0x00010500u, 0u, 9u, 0u, 0x0005000Fu, 4u},
                               Stage::fragment),
            "no entry point of the expected stage");
}

// Every request answered after 3 s: the budget turns the remote cache off (one warning) and the
// build finishes locally, well within budget + one request + the build itself.
TEST(RemoteCacheHostile, SlowServerCostsAtMostTheBudget) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  FakeHttpServer server([](const FakeRequest&) { return FakeReply{404, {}, std::chrono::seconds(3)}; });
  ASSERT_TRUE(server.running());
  RemoteBuild result = build_toy_with(
      dir, "slow", server.url(), [](BuildOptions& options) { options.remote_cache_budget = std::chrono::seconds(4); });
  ASSERT_TRUE(result.summary) << result.errors;
  EXPECT_EQ(result.summary->compiled, 13u);
  EXPECT_EQ(result.output, sgtest::reference_output(dir));
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("kept this build waiting 4.0 s, the whole budget"), std::string::npos)
      << result.warnings[0];
  EXPECT_LE(server.requests().size(), 3u) << "about budget / 3 s requests, not one per source";
  EXPECT_LT(result.seconds, 30.0) << "a loaded machine's generous bound; 13 requests would take 39 s";
}

// user:password@ in the URL reaches the server but no message and no file.
TEST(RemoteCacheHostile, CredentialsAreNeverPrintedOrWritten) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  FakeHttpServer server([](const FakeRequest&) { return FakeReply{500, "oops"}; });
  ASSERT_TRUE(server.running());
  const std::string url = "http://alice:s3cret@127.0.0.1:" + std::to_string(server.port()) + "/cache";
  RemoteBuild result = build_toy_with(dir, "creds", url, [](BuildOptions& options) { options.write_stats = true; });
  ASSERT_TRUE(result.summary) << result.errors;
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].rfind("warning: remote cache http://***@127.0.0.1:", 0), 0u) << result.warnings[0];
  ASSERT_FALSE(server.requests().empty());
  EXPECT_EQ(server.requests()[0].headers.at("authorization"), "Basic YWxpY2U6czNjcmV0") << "alice:s3cret";
  for (const auto& [file, bytes] : result.output) EXPECT_EQ(bytes.find("s3cret"), std::string::npos) << file;

  std::ostringstream out, err;
  EXPECT_EQ(run_cli({"build", sgtest::toy_spec().string(), "--out", (dir / "bad").string(), "--remote-cache",
                     "ftp://alice:s3cret@host/cache"},
                    out, err),
            2);
  EXPECT_EQ(err.str(),
            "shadergen: error: --remote-cache: \"ftp://***@host/cache\" is not an http:// or https:// URL "
            "(set by the option or SHADERGEN_REMOTE_CACHE)\n");
}

// Credentials from ~/.netrc (libcurl's lookup): the URL carries none.
TEST(RemoteCacheHostile, NetrcSuppliesCredentials) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  FakeHttpServer server([](const FakeRequest&) { return FakeReply{404, {}}; });
  ASSERT_TRUE(server.running());
  sgtest::write_file(dir / "home" / ".netrc", "machine 127.0.0.1 login bob password hunter2\n");
  const char* old_home = std::getenv("HOME");
  const std::string saved = old_home ? old_home : "";
  ::setenv("HOME", (dir / "home").c_str(), 1);
  RemoteBuild result = build_toy(dir, "netrc", server.url(), true);
  if (old_home)
    ::setenv("HOME", saved.c_str(), 1);
  else
    ::unsetenv("HOME");
  ASSERT_TRUE(result.summary) << result.errors;
  ASSERT_FALSE(server.requests().empty());
  EXPECT_EQ(server.requests()[0].headers.at("authorization"), "Basic Ym9iOmh1bnRlcjI=") << "bob:hunter2";
}

// The optimiser-fallback reason of an entry is server text: printed with its escape sequences
// escaped and its length bounded.
TEST(RemoteCacheHostile, ServerTextIsEscapedAndBounded) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  std::mutex mutex;
  std::map<std::string, std::string> stored;  // key -> entry, as a WebDAV server keeps them
  FakeHttpServer server([&](const FakeRequest& request) {
    std::lock_guard lock(mutex);
    if (request.method == "PUT") {
      stored[key_of(request)] = request.body;
      return FakeReply{201, {}};
    }
    auto found = stored.find(key_of(request));
    return found == stored.end() ? FakeReply{404, {}} : FakeReply{200, found->second};
  });
  ASSERT_TRUE(server.running());
  ASSERT_TRUE(build_toy(dir, "writer", server.url()).summary);
  {
    std::lock_guard lock(mutex);
    const std::string hostile = "\x1b]0;owned\x07\x1b[2J\r" + std::string(5000, 'A') + "\nrm -rf";
    for (auto& [key, entry] : stored) {
      auto blob = decode_cache_entry(key, entry);
      ASSERT_TRUE(blob);
      blob->fell_back = true;
      blob->fallback_reason = hostile;
      entry = encode_cache_entry(key, *blob);
    }
  }
  RemoteBuild reader = build_toy(dir, "reader", server.url(), true);
  ASSERT_TRUE(reader.summary) << reader.errors;
  ASSERT_FALSE(reader.warnings.empty());
  for (const std::string& warning : reader.warnings) {
    for (char c : warning) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "a raw control byte in: " << warning.substr(0, 80);
    EXPECT_LT(warning.size(), 600u);
  }
  EXPECT_NE(reader.warnings[0].find("\\x1b]0;owned\\x07"), std::string::npos) << reader.warnings[0].substr(0, 120);
}

TEST(RemoteCacheHostile, UrlWithQueryOrFragmentIsRefused) {
  sgtest::TempDir run_dir("run");
  for (const char* url : {"http://host/cache?token=1", "https://host/cache#part"}) {
    std::ostringstream out, err;
    EXPECT_EQ(run_cli({"build", sgtest::toy_spec().string(), "--out", (run_dir.path() / "out").string(),
                       "--remote-cache", url},
                      out, err),
              2);
    EXPECT_EQ(err.str(), "shadergen: error: --remote-cache: \"" + std::string(url) +
                             "\" has a query or fragment ('?' or '#'), which the entry URLs "
                             "<url>/<key-prefix>/<key> cannot carry; give the URL of the collection alone "
                             "(set by the option or SHADERGEN_REMOTE_CACHE)\n");
  }
}

}  // namespace
}  // namespace shadergen
