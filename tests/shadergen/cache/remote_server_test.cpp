// The remote cache against a real server: Debian's nginx with WebDAV PUT, started by each test
// on 127.0.0.1 at a free port with its files in the build tree, and stopped at the end (its
// destructor kills it, also when an assertion fails). Builds of the toy fixture, each with its
// own local cache, standing in for two machines; each must end with the same bytes as a plain
// local build, whatever the server did.
#include <gtest/gtest.h>

#include <netinet/in.h>
#include <sys/socket.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <thread>

#include <testsupport/apache_server.h>
#include <testsupport/nginx_server.h>
#include "cache/cache.h"
#include "cache/http_client.h"
#include "remote_builds.h"
#include "shadergen/build.h"
#include "shadergen/cli.h"
#include "test_helpers.h"

namespace shadergen {
namespace {

namespace fs = std::filesystem;
using testsupport::NginxMode;
using testsupport::NginxServer;

const std::string kTail = "; the rest of this build does not use it";

using sgtest::build_toy;
using sgtest::build_toy_with;
using sgtest::reference_output;
using sgtest::RemoteBuild;

std::vector<fs::path> stored_objects(const NginxServer& server) { return sgtest::files_under(server.data_dir()); }

#define START_SERVER(server, ...)  \
  NginxServer server(__VA_ARGS__); \
  ASSERT_TRUE(server.running()) << server.error()

TEST(RemoteCacheServer, SecondMachineCompilesNothingAndWritesTheSameBytes) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  RemoteBuild first = build_toy(dir, "first", server.url());
  ASSERT_TRUE(first.summary) << first.errors;
  EXPECT_EQ(first.summary->compiled, 13u);
  EXPECT_EQ(first.summary->remote->uploaded, 13u);
  EXPECT_EQ(stored_objects(server).size(), 13u);

  RemoteBuild second = build_toy(dir, "second", server.url());
  ASSERT_TRUE(second.summary) << second.errors;
  EXPECT_EQ(second.summary->compiled, 0u);
  EXPECT_EQ(second.summary->remote->fetched, 13u);
  EXPECT_EQ(second.summary->remote->uploaded, 0u);
  EXPECT_EQ(second.summary->remote->failed, 0u);
  EXPECT_TRUE(first.warnings.empty() && second.warnings.empty());
  EXPECT_EQ(second.output, first.output);
  EXPECT_EQ(second.output, reference_output(dir));

  // What came from the server was kept locally: a third build on that machine needs no server.
  server.kill();
  RemoteBuild third = build_toy(dir, "second", server.url());
  ASSERT_TRUE(third.summary) << third.errors;
  EXPECT_EQ(third.summary->compiled, 0u);
  EXPECT_EQ(third.summary->remote->fetched, 0u);
  EXPECT_TRUE(third.warnings.empty()) << "a warm local cache sends no request";
}

TEST(RemoteCacheServer, ServerKilledMidBuildDegradesToLocal) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  RemoteBuild killed = build_toy(dir, "killed", server.url(), false, [&](const std::string& line) {
    if (line.rfind("[3/13] ", 0) == 0) server.kill();
  });
  ASSERT_TRUE(killed.summary) << killed.errors;
  EXPECT_EQ(killed.summary->compiled, 13u);
  EXPECT_EQ(killed.summary->remote->uploaded, 3u) << "the three sources done before the kill";
  EXPECT_EQ(killed.summary->remote->failed, 1u) << "one failed request, then no more";
  ASSERT_EQ(killed.warnings.size(), 1u);
  EXPECT_EQ(killed.warnings[0].rfind("warning: remote cache " + server.url() + ": GET ", 0), 0u) << killed.warnings[0];
  EXPECT_TRUE(killed.warnings[0].ends_with(kTail)) << killed.warnings[0];
  EXPECT_EQ(killed.output, reference_output(dir));
}

TEST(RemoteCacheServer, ServerErrorsDegradeToLocal) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx", NginxMode::errors);
  RemoteBuild result = build_toy(dir, "errors", server.url());
  ASSERT_TRUE(result.summary) << result.errors;
  EXPECT_EQ(result.summary->compiled, 13u);
  EXPECT_EQ(result.summary->remote->failed, 1u);
  EXPECT_EQ(result.summary->remote->uploaded, 0u);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].rfind("warning: remote cache " + server.url() + ": GET ", 0), 0u) << result.warnings[0];
  EXPECT_TRUE(result.warnings[0].ends_with(": HTTP 500" + kTail)) << result.warnings[0];
  EXPECT_EQ(sgtest::count_of(sgtest::read_file(server.access_log()), "\"GET "), 1u)
      << "one request, not one per source";
  EXPECT_EQ(result.output, reference_output(dir));
}

// Each kind of damage to one object on the server: that source is compiled here (and its good
// entry uploaded over the bad one), the other twelve come from the server.
TEST(RemoteCacheServer, DamagedObjectIsRecompiledAndReplaced) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  ASSERT_TRUE(build_toy(dir, "writer", server.url()).summary);
  const std::vector<fs::path> objects = stored_objects(server);
  ASSERT_EQ(objects.size(), 13u);
  const fs::path& victim = objects[5];
  const std::string key = victim.filename().string(), good = sgtest::read_file(victim);
  const std::string other = sgtest::read_file(objects[6]);
  std::string flipped = good;
  flipped[good.size() - 5] = static_cast<char>(flipped[good.size() - 5] ^ 0x40);
  const std::map<std::string, std::string> damage{{"truncated", good.substr(0, good.size() / 2)},
                                                  {"one byte flipped", flipped},
                                                  {"another key's entry", other},
                                                  {"garbage", "<html>502 Bad Gateway</html>"}};
  const std::map<std::string, std::string> expected = reference_output(dir);
  int run = 0;
  for (const auto& [what, bytes] : damage) {
    sgtest::write_file(victim, bytes);
    RemoteBuild result = build_toy(dir, "reader" + std::to_string(run++), server.url());
    ASSERT_TRUE(result.summary) << what << ": " << result.errors;
    EXPECT_EQ(result.summary->compiled, 1u) << what;
    EXPECT_EQ(result.summary->remote->fetched, 12u) << what;
    EXPECT_EQ(result.summary->remote->failed, 1u) << what;
    EXPECT_EQ(result.summary->remote->uploaded, 1u) << what;
    EXPECT_EQ(result.warnings,
              std::vector<std::string>{"warning: remote cache " + server.url() + ": " + key.substr(0, 2) + "/" + key +
                                       " is not a valid entry (truncated, corrupted, foreign or "
                                       "from another version); compiled here instead"})
        << what;
    EXPECT_EQ(result.output, expected) << what;
    EXPECT_EQ(sgtest::read_file(victim), good) << what << ": the upload replaced the bad object";
  }
}

TEST(RemoteCacheServer, ReadOnlyNeverUploads) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  RemoteBuild empty = build_toy(dir, "developer1", server.url(), true);
  ASSERT_TRUE(empty.summary) << empty.errors;
  EXPECT_EQ(empty.summary->compiled, 13u);
  EXPECT_EQ(empty.summary->remote->uploaded, 0u);
  EXPECT_TRUE(stored_objects(server).empty());
  EXPECT_EQ(sgtest::count_of(sgtest::read_file(server.access_log()), "\"PUT "), 0u);

  ASSERT_TRUE(build_toy(dir, "ci", server.url()).summary);  // read-write, like CI
  RemoteBuild served = build_toy(dir, "developer2", server.url(), true);
  ASSERT_TRUE(served.summary) << served.errors;
  EXPECT_EQ(served.summary->compiled, 0u);
  EXPECT_EQ(served.summary->remote->fetched, 13u);
  EXPECT_EQ(sgtest::count_of(sgtest::read_file(server.access_log()), "\"PUT "), 13u) << "only CI's uploads";
  EXPECT_TRUE(empty.warnings.empty() && served.warnings.empty());
  EXPECT_EQ(served.output, reference_output(dir));
}

TEST(RemoteCacheServer, UnreachableUrlDegradesToLocal) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  const std::string url = "http://127.0.0.1:" + std::to_string(testsupport::unused_local_port()) + "/cache";
  RemoteBuild result = build_toy(dir, "offline", url);
  ASSERT_TRUE(result.summary) << result.errors;
  EXPECT_EQ(result.summary->compiled, 13u);
  EXPECT_EQ(result.summary->remote->failed, 1u);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].rfind("warning: remote cache " + url + ": GET ", 0), 0u) << result.warnings[0];
  EXPECT_NE(result.warnings[0].find("Couldn't connect to server"), std::string::npos) << result.warnings[0];
  EXPECT_TRUE(result.warnings[0].ends_with(kTail)) << result.warnings[0];
  EXPECT_EQ(result.output, reference_output(dir));
}

// A server that accepts the connection and never answers costs one bounded wait, not a hang:
// the client gives up by its own timeout. The assertions are about what happened, not how fast
// (a loaded machine may take longer to notice): the error is a timeout, and it did wait for the
// configured limit rather than fail at once. A client without the limit would hang here until
// ctest's timeout fails the test.
TEST(RemoteCacheServer, StalledServerTimesOut) {
  int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  ASSERT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(listener, 4), 0);  // the kernel completes the handshake; nobody reads
  ASSERT_EQ(::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &size), 0);
  auto client = make_curl_http_client(HttpTimeouts{std::chrono::milliseconds(500), std::chrono::milliseconds(700)});
  auto start = std::chrono::steady_clock::now();
  const std::string url = "http://127.0.0.1:" + std::to_string(ntohs(address.sin_port)) + "/cache/ab/ab";
  auto response = client->send(HttpRequest{"GET", url, {}, std::chrono::seconds(10)});
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::close(listener);
  ASSERT_FALSE(response.ok());
  EXPECT_NE(response.errors().front().message.find("timed out"), std::string::npos)
      << response.errors().front().message;
  EXPECT_GE(seconds, 0.5) << "gave up before the 500 ms connect and 700 ms transfer limits";
}

// The CLI takes the URL from SHADERGEN_REMOTE_CACHE and prints the counts in its summary.
TEST(RemoteCacheServer, CliReadsTheEnvironmentAndReportsCounts) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  ::setenv("SHADERGEN_REMOTE_CACHE", server.url().c_str(), 1);
  auto cli = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args{"build",       sgtest::toy_spec().string(),        "--out", (dir / name).string(),
                                  "--cache-dir", (dir / (name + ".cache")).string(), "-j",    "1"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::ostringstream out, err;
    EXPECT_EQ(run_cli(args, out, err), 0) << err.str();
    return out.str();
  };
  std::string first = cli("first", {}), second = cli("second", {"--remote-cache-readonly"});
  ::unsetenv("SHADERGEN_REMOTE_CACHE");
  EXPECT_NE(first.find("(13 compiled, 0 cached; remote: 0 fetched, 13 uploaded, 0 failed)"), std::string::npos)
      << first;
  EXPECT_NE(second.find("(0 compiled, 13 cached; remote: 13 fetched, 0 uploaded, 0 failed)"), std::string::npos)
      << second;
  std::ostringstream out, err;
  EXPECT_EQ(run_cli({"build", sgtest::toy_spec().string(), "--out", (dir / "bad").string(), "--remote-cache",
                     "ftp://host/cache"},
                    out, err),
            2);
  EXPECT_EQ(err.str(),
            "shadergen: error: --remote-cache: \"ftp://host/cache\" is not an http:// or https:// URL "
            "(set by the option or SHADERGEN_REMOTE_CACHE)\n");
}

// Apache's mod_dav refuses a PUT into a collection that does not exist (409): the client creates
// <url>/<prefix>/ with MKCOL and sends the PUT again, so its cache fills like nginx's.
TEST(RemoteCacheServer, ApacheModDavFillsAndServes) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  testsupport::ApacheServer server(dir / "apache");
  ASSERT_TRUE(server.running()) << server.error();
  RemoteBuild first = build_toy(dir, "first", server.url());
  ASSERT_TRUE(first.summary) << first.errors;
  EXPECT_TRUE(first.warnings.empty()) << first.warnings.front();
  EXPECT_EQ(first.summary->remote->uploaded, 13u);
  EXPECT_EQ(sgtest::files_under(server.data_dir()).size(), 13u);
  EXPECT_GE(sgtest::count_of(sgtest::read_file(server.access_log()), "MKCOL "), 1u);

  RemoteBuild second = build_toy(dir, "second", server.url());
  ASSERT_TRUE(second.summary) << second.errors;
  EXPECT_EQ(second.summary->compiled, 0u);
  EXPECT_EQ(second.summary->remote->fetched, 13u);
  EXPECT_TRUE(second.warnings.empty());
  EXPECT_EQ(second.output, reference_output(dir));
}

// With a secret, CI's uploads are signed and a reader with the same secret takes them; entries
// written without it, or signed with another, are compiled here (one warning), cold-build bytes.
TEST(RemoteCacheServer, SignedEntriesNeedTheSecret) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  auto with_secret = [](const std::string& secret) {
    return [secret](BuildOptions& options) { options.remote_cache_secret = secret; };
  };
  ASSERT_TRUE(build_toy_with(dir, "ci", server.url(), with_secret("team secret")).summary);
  const auto expected = reference_output(dir);

  RemoteBuild developer = build_toy_with(dir, "developer", server.url(), with_secret("team secret"));
  ASSERT_TRUE(developer.summary) << developer.errors;
  EXPECT_EQ(developer.summary->remote->fetched, 13u);
  EXPECT_TRUE(developer.warnings.empty());
  EXPECT_EQ(developer.output, expected);

  RemoteBuild outsider = build_toy_with(dir, "outsider", server.url(), [](BuildOptions& options) {
    options.remote_cache_secret = "a guess";
    options.remote_cache_read_only = true;
  });
  ASSERT_TRUE(outsider.summary) << outsider.errors;
  EXPECT_EQ(outsider.summary->remote->fetched, 0u);
  EXPECT_EQ(outsider.summary->compiled, 13u);
  ASSERT_EQ(outsider.warnings.size(), 1u);
  EXPECT_NE(outsider.warnings[0].find("is not signed with this build's secret"), std::string::npos)
      << outsider.warnings[0];
  EXPECT_EQ(outsider.output, expected);

  // A reader without the secret takes the signed entries unchecked (its own trust decision).
  RemoteBuild unchecked = build_toy(dir, "unchecked", server.url(), true);
  ASSERT_TRUE(unchecked.summary) << unchecked.errors;
  EXPECT_EQ(unchecked.summary->remote->fetched, 13u);
  EXPECT_EQ(unchecked.output, expected);

  // Entries written without the secret (someone who can write the server) are refused.
  for (const fs::path& object : stored_objects(server)) fs::remove(object);
  ASSERT_TRUE(build_toy(dir, "unsigned writer", server.url()).summary);
  RemoteBuild refused = build_toy_with(dir, "refused", server.url(), with_secret("team secret"));
  ASSERT_TRUE(refused.summary) << refused.errors;
  EXPECT_EQ(refused.summary->remote->fetched, 0u);
  EXPECT_EQ(refused.warnings.size(), 1u);
  EXPECT_EQ(refused.output, expected);
}

// A machine whose local cache is warm fills an empty server (one HEAD per entry it does not
// know the server has); once it knows, a warm build sends nothing.
TEST(RemoteCacheServer, WarmAgentFillsAnEmptyServer) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  ASSERT_TRUE(build_toy(dir, "agent", "").summary) << "warm the local cache without any server";
  RemoteBuild filling = build_toy(dir, "agent", server.url());
  ASSERT_TRUE(filling.summary) << filling.errors;
  EXPECT_EQ(filling.summary->compiled, 0u);
  EXPECT_EQ(filling.summary->remote->uploaded, 13u);
  EXPECT_EQ(stored_objects(server).size(), 13u);
  EXPECT_TRUE(filling.warnings.empty());

  // nginx logs a request after answering it: wait for the 13 HEADs and 13 PUTs to be written.
  auto log_lines = [&] { return sgtest::count_of(sgtest::read_file(server.access_log()), "\n"); };
  for (int i = 0; i < 500 && log_lines() < 26; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(log_lines(), 26u);
  RemoteBuild again = build_toy(dir, "agent", server.url());
  ASSERT_TRUE(again.summary) << again.errors;
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(log_lines(), 26u) << "no request: the server has every entry";

  RemoteBuild other = build_toy(dir, "other machine", server.url(), true);
  ASSERT_TRUE(other.summary) << other.errors;
  EXPECT_EQ(other.summary->remote->fetched, 13u);
  EXPECT_EQ(other.output, reference_output(dir));
}

// With a secret, the input set (the content keys of this spec's inputs) is shared too: a machine
// with an empty local cache skips preprocessing. Without the secret it is neither sent nor used.
TEST(RemoteCacheServer, SignedServerSharesTheInputSet) {
  sgtest::TempDir run_dir("run");
  const fs::path& dir = run_dir.path();
  START_SERVER(server, dir / "nginx");
  auto secret = [](BuildOptions& options) { options.remote_cache_secret = "team secret"; };
  ASSERT_TRUE(build_toy(dir, "unsigned", server.url()).summary);
  EXPECT_FALSE(fs::exists(server.data_dir() / "inputs")) << "an unsigned input set is never uploaded";
  ASSERT_TRUE(build_toy_with(dir, "ci", server.url(), secret).summary);
  EXPECT_EQ(sgtest::files_under(server.data_dir() / "inputs").size(), 1u);

  RemoteBuild served = build_toy_with(dir, "developer", server.url(), secret);
  ASSERT_TRUE(served.summary) << served.errors;
  EXPECT_TRUE(served.summary->inputs_reused) << "no preprocessing";
  EXPECT_EQ(served.summary->compiled, 0u);
  EXPECT_TRUE(served.warnings.empty());
  EXPECT_EQ(served.output, reference_output(dir));

  RemoteBuild unsigned_reader = build_toy(dir, "no secret", server.url(), true);
  ASSERT_TRUE(unsigned_reader.summary) << unsigned_reader.errors;
  EXPECT_FALSE(unsigned_reader.summary->inputs_reused) << "without the secret the input set is not trusted";
  EXPECT_EQ(unsigned_reader.summary->remote->fetched, 13u);
}

}  // namespace
}  // namespace shadergen
