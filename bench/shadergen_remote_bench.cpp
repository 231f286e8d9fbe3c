// shadergen_remote_bench - what a shared cache saves a machine that has never built the domain
// (issue 20): a cold build against a build served entirely by the remote cache.
//
// It starts its own nginx (WebDAV PUT, 127.0.0.1, a free port, files under the work folder; the
// same server the tests use) and runs, each repetition, with an empty local cache every time:
//   a) `shadergen build -j 2` without a remote cache (cold: everything compiled);
//   b) the same with `--remote-cache URL --remote-cache-secret-file F` against an empty server
//      (cold, and every entry and the input set uploaded, signed: what the first CI build pays);
//   c) the same again, other local cache, same server (served: every entry fetched, 0 compiled).
// Every step is a separate process, timed from start to exit. Prints the medians and the ratio.
// With --slow S, then once: (d) a build against a server answering every request after S seconds
// (<testsupport/fake_http_server.h>), to show the time budget's bound.
// Exits 1 if a step fails, (b) did not upload every source, (c) compiled anything or fetched
// fewer, or an output differs from (a)'s, so a one-repetition run is a smoke test.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <unistd.h>

#include <median/median.h>
#include <testsupport/fake_http_server.h>
#include <testsupport/nginx_server.h>
#include "timed_process.h"

namespace {

namespace fs = std::filesystem;

struct Options {
  fs::path spec = SHADERGEN_SOURCE_DIR "/permutations/split_second.json";
  fs::path shadergen = SHADERGEN_EXE;
  fs::path work;  // empty: a fresh folder under the system temporary folder, removed at the end
  int repetitions = 5;
  double slow = 0.0;  // > 0: also one build against a server answering every request after this many seconds
};

std::optional<Options> parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string arg = argv[i], value = argv[i + 1];
    if (arg == "--spec")
      o.spec = value;
    else if (arg == "--shadergen")
      o.shadergen = value;
    else if (arg == "--work")
      o.work = value;
    else if (arg == "--reps")
      o.repetitions = std::atoi(value.c_str());
    else if (arg == "--slow")
      o.slow = std::atof(value.c_str());
    else
      return std::nullopt;
  }
  if (argc % 2 == 0 || o.repetitions < 1) return std::nullopt;
  return o;
}

// "(13 compiled, 0 cached; remote: 0 fetched, 13 uploaded, 0 failed)" -> its numbers.
struct Counts {
  int sources = -1, compiled = -1, fetched = -1, uploaded = -1, failed = -1;
};

Counts counts_of(const std::string& summary) {
  std::smatch m;
  Counts c;
  if (std::regex_search(summary, m, std::regex(R"((\d+) distinct sources \((\d+) compiled)"))) {
    c.sources = std::stoi(m[1]);
    c.compiled = std::stoi(m[2]);
  }
  if (std::regex_search(summary, m, std::regex(R"(remote: (\d+) fetched, (\d+) uploaded, (\d+) failed)"))) {
    c.fetched = std::stoi(m[1]);
    c.uploaded = std::stoi(m[2]);
    c.failed = std::stoi(m[3]);
  }
  return c;
}

class RemoteBench {
 public:
  RemoteBench(Options o, std::string url, fs::path server_data)
      : o_(std::move(o)), url_(std::move(url)), server_data_(std::move(server_data)) {}

  bool repetition() {
    for (const char* dir : {"cold", "upload", "served"}) {
      fs::remove_all(o_.work / dir);
      fs::remove_all(o_.work / (std::string(dir) + ".cache"));
    }
    fs::remove_all(server_data_);
    fs::create_directories(server_data_);
    bench::Run a = step("cold build", build("cold", false));
    bench::Run b = step("cold build uploading", build("upload", true));
    bench::Run c = step("build served by the remote cache", build("served", true));
    if (!a.ok || !b.ok || !c.ok) return false;
    Counts up = counts_of(b.out), served = counts_of(c.out);
    if (up.uploaded != up.sources || up.failed != 0) return fail("(b) did not upload every source:\n" + b.out);
    if (served.compiled != 0 || served.fetched != served.sources || served.failed != 0)
      return fail("(c) was not served entirely by the remote cache:\n" + c.out);
    auto expected = bench::output_files(o_.work / "cold");
    if (bench::output_files(o_.work / "upload") != expected || bench::output_files(o_.work / "served") != expected)
      return fail("an output differs from the cold build's");
    sources_ = served.sources;
    cold_s_.push_back(a.seconds), upload_s_.push_back(b.seconds), served_s_.push_back(c.seconds);
    return true;
  }

  void report() const {
    double cold = median::of(cold_s_), upload = median::of(upload_s_), served = median::of(served_s_);
    std::printf("shadergen remote cache: %s, %d distinct sources, %d repetition(s), medians, empty local cache\n",
                o_.spec.string().c_str(), sources_, o_.repetitions);
    std::printf("  (a) shadergen build -j 2, no remote cache (cold)              %8.3f s\n", cold);
    std::printf("  (b) ... --remote-cache URL, empty server (cold + uploads)     %8.3f s  %6.2fx the time of (a)\n",
                upload, upload / cold);
    std::printf("  (c) ... --remote-cache URL, full server (served, 0 compiled)  %8.3f s  %6.2fx faster than (a)\n",
                served, cold / served);
    std::printf("  every run (s): (a) %s; (b) %s; (c) %s\n", bench::seconds_list(cold_s_).c_str(),
                bench::seconds_list(upload_s_).c_str(), bench::seconds_list(served_s_).c_str());
  }

  // (d) One build with an empty local cache against a server that answers every request (404 to
  // GET and HEAD, 201 to PUT) after `slow` seconds: the remote cache's time budget must bound
  // what it costs (issue 26: 3 s per request, split_second, at most 40 s), outputs as (a)'s.
  bool slow_server() {
    auto delay = std::chrono::milliseconds(static_cast<long long>(o_.slow * 1000.0));
    testsupport::FakeHttpServer server([delay](const testsupport::FakeRequest& request) {
      return testsupport::FakeReply{request.method == "PUT" ? 201 : 404, {}, delay};
    });
    fs::remove_all(o_.work / "slow"), fs::remove_all(o_.work / "slow.cache");
    std::vector<std::string> args = build("slow", false);
    args.insert(args.end(), {"--remote-cache", server.url()});
    bench::Run d = step("build against a slow server", args);
    if (!d.ok) return false;
    if (bench::output_files(o_.work / "slow") != bench::output_files(o_.work / "cold"))
      return fail("(d)'s output differs from the cold build's");
    std::printf("  (d) ... --remote-cache URL, every answer after %.1f s          %8.3f s  (one run; warning: %s)\n",
                o_.slow, d.seconds, d.out.find("whole budget") != std::string::npos ? "budget spent" : "other");
    return true;  // the server's destructor waits for the requests still sleeping
  }

 private:
  std::vector<std::string> build(const std::string& name, bool remote) const {
    std::vector<std::string> args{o_.shadergen.string(),
                                  "build",
                                  o_.spec.string(),
                                  "--out",
                                  (o_.work / name).string(),
                                  "-j",
                                  "2",
                                  "--cache-dir",
                                  (o_.work / (name + ".cache")).string()};
    // Signed, as CI and developers sharing a secret run it: the served build then also takes the
    // input set (the content keys of this spec's inputs) from the server and skips preprocessing.
    if (remote) {
      std::ofstream(o_.work / "secret") << "shadergen_remote_bench secret\n";
      args.insert(args.end(), {"--remote-cache", url_, "--remote-cache-secret-file", (o_.work / "secret").string()});
    }
    return args;
  }

  bench::Run step(const std::string& what, const std::vector<std::string>& args) const {
    bench::Run r = bench::run(args);
    if (!r.ok) std::cerr << "shadergen_remote_bench: " << what << " failed:\n" << r.out;
    return r;
  }

  static bool fail(const std::string& why) {
    std::cerr << "shadergen_remote_bench: " << why << "\n";
    return false;
  }

  Options o_;
  std::string url_;
  fs::path server_data_;
  int sources_ = 0;
  std::vector<double> cold_s_, upload_s_, served_s_;
};

}  // namespace

int main(int argc, char** argv) {
  auto options = parse_args(argc, argv);
  if (!options) {
    std::cerr << "usage: shadergen_remote_bench [--spec SPEC] [--reps N] [--shadergen EXE] [--work DIR] [--slow S]\n";
    return 2;
  }
  bool temporary = options->work.empty();
  if (temporary) options->work = fs::temp_directory_path() / ("shadergen-remote-bench-" + std::to_string(::getpid()));
  options->work = fs::absolute(options->work);
  fs::remove_all(options->work);
  fs::create_directories(options->work);
  bool ok = false;
  {
    testsupport::NginxServer server(options->work / "nginx");
    if (!server.running()) {
      std::cerr << "shadergen_remote_bench: " << server.error() << "\n";
      return 1;
    }
    RemoteBench bench(*options, server.url(), server.data_dir());
    ok = true;
    for (int rep = 0; rep < options->repetitions && ok; ++rep) ok = bench.repetition();
    if (ok) bench.report();
    if (ok && options->slow > 0) ok = bench.slow_server();
  }
  if (temporary) fs::remove_all(options->work);
  return ok ? 0 : 1;
}
