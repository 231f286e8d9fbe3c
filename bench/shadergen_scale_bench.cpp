// shadergen_scale_bench - how shadergen scales with the domain, on one machine and in shards
// (issue 34, item 5).
//
// For each feature count N it generates a domain the way a material's features change code:
// one fragment uber-shader with one #ifdef block of a few vector operations per feature, every
// define read (so every raw ID is a distinct source), and one impossible rule ("F00 && F01")
// that prunes a quarter. It then runs, each as its own process, timed from start to exit, with
// its CPU time and peak RSS from wait4():
//   a) a cold one-machine build: `shadergen build SPEC --out DIR --no-cache -j J --stats`;
//   b) for the shard domain, K shards one after another (`--shard I/K`, each with an empty local
//      cache) against its own nginx, signed with a secret as a farm's should be, then the merge
//      (`--require-remote-hits --shards K`), whose output must be byte-identical to (a)'s.
// The K-machine projection is the slowest shard plus the merge. Prints a markdown table and the
// targets met or missed; --json FILE also writes the figures. Exits 1 when a step fails or the
// merge differs, so --quick (small domains, 2 shards) is a smoke test.
// --variants-lines L1,L2 also builds a 32-feature domain (2^32 raw IDs) from variants files of
// L1, L2... distinct random combinations, to show that time and memory follow the lines listed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <testsupport/nginx_server.h>
#include "timed_process.h"

namespace {

namespace fs = std::filesystem;

struct Options {
  std::vector<int> features = {14, 16, 18, 20};
  int shard_features = 16;  // the domain that is also built in shards
  int shards = 8;
  int jobs = 2;
  fs::path shadergen = SHADERGEN_EXE;
  fs::path work;                    // empty: a fresh folder under the system temporary folder, removed at the end
  fs::path json;                    // empty: none
  std::vector<int> variants_lines;  // 32-bit domains built from variants files of these many lines
  std::vector<bool> signed_runs = {true, false};  // shard rounds: with a secret, without one
  int tasks = 0;                                  // machines the shards are projected onto (0: one per shard)
  double straggler = 3.0;  // how much slower one of those machines is, in the straggler projection
};

std::vector<int> int_list(const std::string& text) {
  std::vector<int> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) values.push_back(std::atoi(item.c_str()));
  return values;
}

const char* kUsage =
    "usage: shadergen_scale_bench [--quick] [--features 14,16,18,20] [--shard-features 16] [--shards 8]\n"
    "                             [--jobs 2] [--shadergen EXE] [--work DIR] [--json FILE]\n"
    "                             [--variants-lines 2500,10000] [--secret both|signed|unsigned]\n"
    "                             [--tasks K] [--straggler F]\n"
    "  --quick: --features 8,10 --shard-features 10 --shards 2 --variants-lines 50 (a smoke run of a few\n"
    "           seconds)\n"
    "  --variants-lines: also build a 32-feature domain from variants files of that many lines\n"
    "  --secret: the shard rounds to run (default both): signed shards share the input set in parts,\n"
    "            unsigned ones do not, so their merge preprocesses the domain itself\n"
    "  --tasks, --straggler: project the measured shard times onto K machines that take the shards in\n"
    "            index order as they free (a Slurm array throttled with %K), once with every machine\n"
    "            alike and once with one F times slower (default: K = shards, F = 3)\n";

std::optional<Options> parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--quick") {
      o.features = {8, 10}, o.shard_features = 10, o.shards = 2, o.variants_lines = {50};
      continue;
    }
    if (i + 1 >= argc) return std::nullopt;
    std::string value = argv[++i];
    if (arg == "--features")
      o.features = int_list(value);
    else if (arg == "--shard-features")
      o.shard_features = std::atoi(value.c_str());
    else if (arg == "--shards")
      o.shards = std::atoi(value.c_str());
    else if (arg == "--jobs")
      o.jobs = std::atoi(value.c_str());
    else if (arg == "--shadergen")
      o.shadergen = value;
    else if (arg == "--work")
      o.work = value;
    else if (arg == "--json")
      o.json = value;
    else if (arg == "--variants-lines")
      o.variants_lines = int_list(value);
    else if (arg == "--tasks")
      o.tasks = std::atoi(value.c_str());
    else if (arg == "--straggler")
      o.straggler = std::atof(value.c_str());
    else if (arg == "--secret" && (value == "both" || value == "signed" || value == "unsigned"))
      o.signed_runs = value == "both" ? std::vector<bool>{true, false} : std::vector<bool>{value == "signed"};
    else
      return std::nullopt;
  }
  bool sane = o.tasks >= 0 && o.tasks <= o.shards && o.straggler >= 1.0 && o.shards >= 1 && o.jobs >= 1 &&
              o.shard_features >= 2 && !o.features.empty();
  for (int n : o.features) sane = sane && n >= 2 && n <= 32;
  for (int lines : o.variants_lines) sane = sane && lines >= 1;
  if (!sane) return std::nullopt;
  return o;
}

// The generated domain of `n` boolean features in `dir`: scale<n>.json and scale<n>.frag.
fs::path write_domain(const fs::path& dir, int n) {
  fs::create_directories(dir);
  const std::string name = "scale" + std::to_string(n);
  std::ofstream spec(dir / (name + ".json"));
  spec << "{\n  \"format\": 1,\n  \"name\": \"" << name << "\",\n  \"uber_shader\": { \"path\": \"" << name
       << ".frag\" },\n  \"raw\": {\n    \"features\": [\n";
  char feature[96];
  for (int i = 0; i < n; ++i) {
    std::snprintf(feature, sizeof feature, "      { \"name\": \"F%02d\", \"bit\": %d, \"define\": \"USE_F%02d\" }%s\n",
                  i, i, i, i + 1 < n ? "," : "");
    spec << feature;
  }
  spec << "    ],\n    \"impossible\": [ { \"when\": \"F00 && F01\", \"why\": \"prunes a quarter\" } ]\n  }\n}\n";
  std::ofstream frag(dir / (name + ".frag"));
  frag << "#version 450\nlayout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 color;\n"
          "layout(set = 0, binding = 0) uniform sampler2D albedo;\n\nvoid main() {\n  vec4 c = texture(albedo, uv);\n";
  char block[256];
  for (int i = 0; i < n; ++i) {
    std::snprintf(block, sizeof block,
                  "#ifdef USE_F%02d\n  c = c * vec4(%d.0 / 17.0, 0.5, 0.25, 1.0) + vec4(uv, %d.0 / 31.0, 0.0);\n"
                  "  c.xy = c.yx * %d.5;\n#endif\n",
                  i, i + 1, i, i);
    frag << block;
  }
  frag << "  color = c;\n}\n";
  return dir / (name + ".json");
}

// `lines` distinct combinations of the 32 features, none with both F00 and F01 (the impossible
// rule), drawn by a fixed generator so that every run lists the same ones.
fs::path write_variants(const fs::path& dir, int lines) {
  fs::path path = dir / ("listed" + std::to_string(lines) + ".variants");
  std::ofstream out(path);
  out << "# shadergen_scale_bench: " << lines << " distinct combinations of 32 features\n";
  std::vector<std::uint32_t> seen;
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  while (static_cast<int>(seen.size()) < lines) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    auto id = static_cast<std::uint32_t>(state >> 32) & static_cast<std::uint32_t>(state >> 16);  // about 8 of 32 on
    if ((id & 3u) == 3u || std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
    seen.push_back(id);
    std::string text;
    for (int bit = 0; bit < 32; ++bit)
      if (id & (1u << bit))
        text += (text.empty() ? "F" : " | F") + std::string(bit < 10 ? "0" : "") + std::to_string(bit);
    out << (text.empty() ? "(none)" : text) << "\n";
  }
  return path;
}

struct Step {
  bool ok = false;
  std::string failure;  // the output of a failed step
  double seconds = 0.0, cpu_seconds = 0.0, rss_mib = 0.0;
  long sources = -1;          // distinct sources of the domain
  double preprocess_s = 0.0;  // the "preprocess" phase of --stats (0 when skipped)
};

// `log`, when given: where the step's output (its summary and --stats lines) is kept, beside
// the figures, for whoever reads the run later (--work keeps the folder).
Step measured(const std::vector<std::string>& args, const fs::path& log = {}) {
  bench::Run r = bench::run(args);
  if (!log.empty()) std::ofstream(log) << r.out;
  Step s;
  s.ok = r.ok, s.seconds = r.seconds, s.cpu_seconds = r.cpu_seconds;
  s.rss_mib = static_cast<double>(r.peak_rss_kib) / 1024.0;
  std::smatch m;
  if (std::regex_search(r.out, m, std::regex(R"(compile jobs, (\d+) distinct sources)")) ||
      std::regex_search(r.out, m, std::regex(R"(of (\d+) distinct sources)")) ||
      std::regex_search(r.out, m, std::regex(R"(-> (\d+) distinct sources)")))
    s.sources = std::stol(m[1]);
  if (std::regex_search(r.out, m, std::regex(R"(preprocess ([0-9.]+))"))) s.preprocess_s = std::stod(m[1]) / 1000.0;
  if (!r.ok) s.failure = r.out;
  return s;
}

struct DomainRow {
  int features = 0;
  Step build;
};

std::string fixed(double value, int digits = 2) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

std::string first_line(const std::string& text) {
  std::size_t start = text.find("error: ");
  std::string line = text.substr(start == std::string::npos ? 0 : start);
  return line.substr(0, line.find('\n'));
}

void print_domains(const std::vector<DomainRow>& rows, std::ostream& out) {
  out << "| features | raw IDs | distinct sources | wall (s) | CPU (s) | peak RSS (MiB) | s per 1,000 sources | "
         "preprocess (s) |\n|---|---|---|---|---|---|---|---|\n";
  for (const DomainRow& row : rows) {
    out << "| " << row.features << " | " << (1ull << row.features) << " | ";
    if (!row.build.ok) {
      out << "refused: " << first_line(row.build.failure) << " | | | | | |\n";
      continue;
    }
    out << row.build.sources << " | " << fixed(row.build.seconds) << " | " << fixed(row.build.cpu_seconds) << " | "
        << fixed(row.build.rss_mib, 0) << " | "
        << fixed(row.build.seconds * 1000.0 / static_cast<double>(std::max(1L, row.build.sources)), 3) << " | "
        << fixed(row.build.preprocess_s) << " |\n";
  }
}

struct ListedRow {
  int lines = 0;
  Step build;
};

void print_listed(const std::vector<ListedRow>& rows, std::ostream& out) {
  out << "\n32 features (4,294,967,296 raw IDs), built from a variants file:\n\n"
         "| lines listed | distinct sources | wall (s) | CPU (s) | peak RSS (MiB) | s per 1,000 sources |\n"
         "|---|---|---|---|---|---|\n";
  for (const ListedRow& row : rows) {
    out << "| " << row.lines << " | ";
    if (!row.build.ok) {
      out << "failed: " << first_line(row.build.failure) << " | | | | |\n";
      continue;
    }
    out << row.build.sources << " | " << fixed(row.build.seconds) << " | " << fixed(row.build.cpu_seconds) << " | "
        << fixed(row.build.rss_mib, 0) << " | "
        << fixed(row.build.seconds * 1000.0 / static_cast<double>(std::max(1L, row.build.sources)), 3) << " |\n";
  }
}

struct ShardRun {
  std::vector<Step> shards;
  Step merge;
  bool identical = false;
};

// `signed_run`: with a secret, as a farm should be (docs/distributed.md): each shard then uploads
// its part of the input set and the merge joins the parts instead of preprocessing. Without one
// the merge preprocesses the domain itself.
ShardRun run_shards(const Options& o, const fs::path& spec, const fs::path& work, const fs::path& reference,
                    bool signed_run) {
  ShardRun result;
  testsupport::NginxServer server(work / "nginx");
  if (!server.running()) {
    result.merge.failure = "nginx: " + server.error();
    return result;
  }
  const std::string count = std::to_string(o.shards);
  // --no-cache, like the one-machine build it is compared with: a farm's fresh nodes have no
  // local cache worth reading or filling.
  std::vector<std::string> common = {"--remote-cache",       server.url(), "--no-cache", "-j",
                                     std::to_string(o.jobs), "--stats"};
  if (signed_run) {
    const fs::path secret = work / "secret";
    std::ofstream(secret) << "shadergen_scale_bench secret\n";
    common.insert(common.end(), {"--remote-cache-secret-file", secret.string()});
  }
  auto with_common = [&](std::vector<std::string> args) {
    args.insert(args.end(), common.begin(), common.end());
    return args;
  };
  const char* kind = signed_run ? "signed" : "unsigned";
  for (int i = 0; i < o.shards; ++i) {
    std::cerr << "shadergen_scale_bench: " << kind << " shard " << i << "/" << o.shards << "\n";
    result.shards.push_back(measured(
        with_common({o.shadergen.string(), "build", spec.string(), "--shard", std::to_string(i) + "/" + count}),
        work / ("shard-" + std::to_string(i) + ".txt")));
    if (!result.shards.back().ok) return result;
  }
  std::cerr << "shadergen_scale_bench: " << kind << " merge\n";
  result.merge = measured(with_common({o.shadergen.string(), "build", spec.string(), "--out",
                                       (work / "merged").string(), "--require-remote-hits", "--shards", count}),
                          work / "merge.txt");
  // Said before the comparison, which reads gigabytes at 20 features: the figures outlive it.
  std::cerr << "shadergen_scale_bench: merge: " << (result.merge.ok ? "ok" : "FAILED") << ", " << result.merge.seconds
            << " s wall, " << result.merge.cpu_seconds << " s CPU, " << result.merge.rss_mib
            << " MiB; shards (s, MiB):";
  for (const Step& s : result.shards) std::cerr << " " << s.seconds << " " << s.rss_mib;
  std::cerr << "\n";
  result.identical = result.merge.ok && bench::same_output_files(work / "merged", reference);
  return result;
}

const char* verdict(bool met) { return met ? "met" : "MISSED"; }

// When the last of the shards (measured `seconds`, in index order) finishes on `tasks` machines
// that each take the next shard as they free (how Slurm runs `--array=0-(N-1)%K`), machine 0
// taking `slow` times as long as measured. The shards' own start-up is in their times.
double makespan(const std::vector<Step>& shards, int tasks, double slow) {
  std::vector<double> free_at(static_cast<std::size_t>(tasks), 0.0);
  for (const Step& shard : shards) {
    auto next = std::min_element(free_at.begin(), free_at.end());  // the first to free; ties: lowest
    *next += shard.seconds * (next == free_at.begin() ? slow : 1.0);
  }
  return *std::max_element(free_at.begin(), free_at.end());
}

void print_shards(const Options& o, const ShardRun& run, const Step& one_machine, std::ostream& out) {
  out << "\n| shard | wall (s) | CPU (s) | peak RSS (MiB) | preprocess (s) | preprocess share |\n"
         "|---|---|---|---|---|---|\n";
  double slowest = 0.0, largest_rss = 0.0;
  for (std::size_t i = 0; i < run.shards.size(); ++i) {
    const Step& s = run.shards[i];
    slowest = std::max(slowest, s.seconds), largest_rss = std::max(largest_rss, s.rss_mib);
    out << "| " << i << "/" << o.shards << " | " << fixed(s.seconds) << " | " << fixed(s.cpu_seconds) << " | "
        << fixed(s.rss_mib, 0) << " | " << fixed(s.preprocess_s) << " | "
        << fixed(100.0 * s.preprocess_s / std::max(1e-9, s.seconds), 1) << " % |\n";
  }
  out << "| merge | " << fixed(run.merge.seconds) << " | " << fixed(run.merge.cpu_seconds) << " | "
      << fixed(run.merge.rss_mib, 0) << " | " << fixed(run.merge.preprocess_s) << " | "
      << fixed(100.0 * run.merge.preprocess_s / std::max(1e-9, run.merge.seconds), 1) << " % |\n\n";
  const double projection = slowest + run.merge.seconds;
  const double whole = one_machine.seconds;
  out << "- one machine: " << fixed(whole) << " s; " << o.shards
      << "-machine projection (slowest shard + merge): " << fixed(projection) << " s = " << fixed(projection / whole, 3)
      << " of it (target <= 0.25: " << verdict(projection <= whole / 4) << ")\n";
  out << "- merge: " << fixed(run.merge.seconds) << " s = " << fixed(100.0 * run.merge.seconds / whole, 1)
      << " % of the one-machine build (target <= 10 %: " << verdict(run.merge.seconds <= whole / 10) << ")\n";
  out << "- largest shard RSS: " << fixed(largest_rss, 0) << " MiB (target <= 1024: " << verdict(largest_rss <= 1024.0)
      << ")\n";
  out << "- merged output byte-identical to the one-machine build: " << (run.identical ? "yes" : "NO") << "\n";
  const int tasks = o.tasks > 0 ? o.tasks : o.shards;
  if (static_cast<int>(run.shards.size()) != o.shards) return;
  const double even = makespan(run.shards, tasks, 1.0), slowed = makespan(run.shards, tasks, o.straggler);
  out << "- on " << tasks << " machines taking the " << o.shards
      << " shards as they free, with the measured times: " << fixed(even)
      << " s + merge = " << fixed((even + run.merge.seconds) / whole, 3) << " of one machine; with one machine "
      << fixed(o.straggler, 1) << "x slower: " << fixed(slowed)
      << " s + merge = " << fixed((slowed + run.merge.seconds) / whole, 3) << " (the straggler costs "
      << fixed(slowed / even, 2) << "x the shards' time)\n";
}

std::string json_step(const Step& s) {
  return "{\"ok\": " + std::string(s.ok ? "true" : "false") + ", \"wall_s\": " + fixed(s.seconds, 3) +
         ", \"cpu_s\": " + fixed(s.cpu_seconds, 3) + ", \"peak_rss_mib\": " + fixed(s.rss_mib, 1) +
         ", \"sources\": " + std::to_string(s.sources) + ", \"preprocess_s\": " + fixed(s.preprocess_s, 3) + "}";
}

std::string json_shard_run(const ShardRun& run, int shard_features) {
  std::string text = "{\"features\": " + std::to_string(shard_features) + ", \"shards\": [";
  for (std::size_t i = 0; i < run.shards.size(); ++i) text += (i ? ", " : "") + json_step(run.shards[i]);
  return text + "], \"merge\": " + json_step(run.merge) + ", \"identical\": " + (run.identical ? "true" : "false") +
         "}";
}

// "sharded": the signed round, "sharded_unsigned": the unsigned one; each only when it ran.
void write_json(const fs::path& path, const std::vector<DomainRow>& rows,
                const std::vector<std::pair<bool, ShardRun>>& runs, int shard_features) {
  std::ofstream out(path);
  out << "{\n  \"domains\": [\n";
  for (std::size_t i = 0; i < rows.size(); ++i)
    out << "    {\"features\": " << rows[i].features << ", \"build\": " << json_step(rows[i].build) << "}"
        << (i + 1 < rows.size() ? ",\n" : "\n");
  out << "  ]";
  for (const auto& [signed_run, run] : runs)
    out << ",\n  \"" << (signed_run ? "sharded" : "sharded_unsigned") << "\": " << json_shard_run(run, shard_features);
  out << "\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  auto options = parse_args(argc, argv);
  if (!options) {
    std::cerr << kUsage;
    return 2;
  }
  const Options& o = *options;
  const bool own_work = o.work.empty();
  const fs::path work =
      own_work ? fs::temp_directory_path() / ("shadergen_scale_bench." + std::to_string(::getpid())) : o.work;
  fs::remove_all(work);
  std::vector<DomainRow> rows;
  std::optional<fs::path> shard_spec, shard_reference;
  Step shard_baseline;
  bool failed = false;
  std::vector<int> all = o.features;
  if (std::find(all.begin(), all.end(), o.shard_features) == all.end()) all.push_back(o.shard_features);
  for (int n : all) {
    const fs::path dir = work / ("scale" + std::to_string(n));
    const fs::path spec = write_domain(dir, n);
    std::cerr << "shadergen_scale_bench: " << n << " features, one machine\n";
    DomainRow row{n, measured({o.shadergen.string(), "build", spec.string(), "--out", (dir / "out").string(),
                               "--no-cache", "-j", std::to_string(o.jobs), "--stats"},
                              dir / "build.txt")};
    // A domain over the tool's limits is refused at the spec: that is a figure, not a failure.
    const bool refused = row.build.failure.find("error: raw.features:") != std::string::npos;
    if (!row.build.ok && !refused) failed = true;
    if (n == o.shard_features && row.build.ok)
      shard_spec = spec, shard_reference = dir / "out", shard_baseline = row.build;
    rows.push_back(row);
  }
  std::cout << "shadergen_scale_bench: " << o.shadergen.string() << ", -j " << o.jobs
            << ", cold builds (--no-cache)\n\n";
  print_domains(rows, std::cout);
  std::vector<std::pair<bool, ShardRun>> shard_runs;
  if (shard_spec) {
    for (bool signed_run : o.signed_runs) {
      ShardRun shards =
          run_shards(o, *shard_spec, work / (signed_run ? "shards" : "shards-unsigned"), *shard_reference, signed_run);
      std::cout << "\n"
                << o.shard_features << "-feature domain in " << o.shards << " shards "
                << (signed_run ? "with a secret (the merge joins the shards' parts of the input set)"
                               : "without a secret (the merge preprocesses the domain itself)")
                << ", one after another on this machine, then the merge:\n";
      print_shards(o, shards, shard_baseline, std::cout);
      failed = failed || !shards.identical;
      for (const Step& s : shards.shards)
        if (!s.ok) std::cerr << "shadergen_scale_bench: a shard failed:\n" << s.failure;
      if (!shards.merge.ok) std::cerr << "shadergen_scale_bench: the merge failed:\n" << shards.merge.failure;
      shard_runs.emplace_back(signed_run, std::move(shards));
    }
  } else {
    std::cout << "\nno shard run: the " << o.shard_features << "-feature domain did not build\n";
    failed = true;
  }
  std::vector<ListedRow> listed;
  if (!o.variants_lines.empty()) {
    const fs::path dir = work / "scale32";
    const fs::path spec = write_domain(dir, 32);
    for (int lines : o.variants_lines) {
      std::cerr << "shadergen_scale_bench: 32 features, " << lines << " listed\n";
      ListedRow row{lines, measured({o.shadergen.string(), "build", spec.string(), "--variants",
                                     write_variants(dir, lines).string(), "--out", (dir / "out").string(), "--no-cache",
                                     "-j", std::to_string(o.jobs), "--stats"})};
      failed = failed || !row.build.ok;
      listed.push_back(row);
    }
    print_listed(listed, std::cout);
  }
  if (!o.json.empty()) write_json(o.json, rows, shard_runs, o.shard_features);
  if (own_work) fs::remove_all(work);
  return failed ? 1 : 0;
}
