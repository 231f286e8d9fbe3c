#include "shadergen/cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>

#include "shadergen/build.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "suggest.h"
#include "version.h"

namespace shadergen {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_signal(int) { g_interrupted.store(true); }

constexpr int kExitError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInterrupted = 130;

int print_errors(const Diagnostics& errors, std::ostream& err) {
  for (const Diagnostic& d : errors) err << (d.file.empty() ? "shadergen: " : "") << d.to_string() << '\n';
  return kExitError;
}

std::string value_names(const RawFeature& feature) {
  std::string text;
  for (const std::string& v : feature.values) text += (text.empty() ? "" : ", ") + v;
  return "(" + text + ")";
}

// A raw ID as a number (12, 0x0c, 0b1100) or feature names joined by '|', '+' or ','.
std::optional<std::uint32_t> parse_raw_id(const DomainSpec& spec, const std::string& text, std::string& why) {
  try {
    std::size_t used = 0;
    int base = 10;
    std::string digits = text;
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0)
      base = 16, digits = text.substr(2);
    else if (text.rfind("0b", 0) == 0)
      base = 2, digits = text.substr(2);
    if (base != 10 || (!digits.empty() && std::isdigit(static_cast<unsigned char>(digits[0])))) {
      unsigned long value = std::stoul(digits, &used, base);
      if (used != digits.size()) throw std::invalid_argument("trailing characters");
      if (value >= spec.raw_count()) {
        why = "raw ID " + text + " is out of range: domain " + spec.name + " has raw IDs 0 to " +
              std::to_string(spec.raw_count() - 1);
        return std::nullopt;
      }
      return static_cast<std::uint32_t>(value);
    }
  } catch (const std::exception&) {
    why = "\"" + text + "\" is not a raw ID (a number or feature names joined by '|')";
    return std::nullopt;
  }
  std::uint32_t id = 0;
  std::string name;
  // A boolean feature by name, or a valued one as NAME=VALUE.
  auto flush = [&]() -> bool {
    if (name.empty()) return true;
    std::string feature_name = name.substr(0, name.find('='));
    std::string value = feature_name.size() < name.size() ? name.substr(feature_name.size() + 1) : std::string();
    auto found = std::find_if(spec.raw_features.begin(), spec.raw_features.end(),
                              [&](const RawFeature& f) { return f.name == feature_name || f.define == feature_name; });
    if (found == spec.raw_features.end()) {
      why = "unknown raw feature \"" + feature_name + "\" (known: ";
      for (std::size_t i = 0; i < spec.raw_features.size(); ++i) why += (i ? ", " : "") + spec.raw_features[i].name;
      why += ")";
      return false;
    }
    auto index = std::find(found->values.begin(), found->values.end(), value);
    if (found->valued() && index == found->values.end()) {
      why = "\"" + name + "\": " + found->name + " has values " + value_names(*found) + "; write " + found->name +
            "=<value>";
      return false;
    }
    id |= found->valued() ? static_cast<std::uint32_t>(index - found->values.begin()) << found->bit : 1u << found->bit;
    name.clear();
    return true;
  };
  for (char c : text) {
    if (c == '|' || c == '+' || c == ',') {
      if (!flush()) return std::nullopt;
    } else if (c != ' ') {
      name += c;
    }
  }
  if (!flush()) return std::nullopt;
  return id;
}

struct BuildArgs {
  std::string spec, out, cache_dir, depfile, cpp_name, ns, target_env;
  std::vector<std::string> defines;
  unsigned jobs = 0;
  bool no_cache = false, stats = false, verbose = false, strip_debug = false;
  std::string remote_cache;
  bool remote_cache_readonly = false;
  std::string remote_cache_secret_file;
  double remote_cache_budget = 10.0;  // seconds
};

// The signing secret: the file's bytes (without trailing line breaks), else
// $SHADERGEN_REMOTE_CACHE_SECRET, else none. Never an argument: command lines reach logs and
// `ps`. Messages name the file, never its contents.
std::optional<std::string> remote_cache_secret(const BuildArgs& a, std::ostream& err) {
  if (a.remote_cache_secret_file.empty()) {
    const char* secret = std::getenv("SHADERGEN_REMOTE_CACHE_SECRET");
    return std::string(secret ? secret : "");
  }
  std::ifstream file(a.remote_cache_secret_file, std::ios::binary);
  std::string secret((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  while (!secret.empty() && (secret.back() == '\n' || secret.back() == '\r')) secret.pop_back();
  if (!file.good() && !file.eof()) secret.clear();
  if (secret.empty()) {
    err << "shadergen: error: --remote-cache-secret-file " << a.remote_cache_secret_file
        << ": cannot read a secret from it (missing, unreadable or empty)\n";
    return std::nullopt;
  }
  return secret;
}

// "; remote: 13 fetched, 0 uploaded, 0 failed" inside the summary's parentheses, with a remote cache.
std::string remote_counts(const BuildSummary& s) {
  if (!s.remote_cache) return {};
  return "; remote: " + std::to_string(s.remote_fetched) + " fetched, " + std::to_string(s.remote_uploaded) +
         " uploaded, " + std::to_string(s.remote_failed) + " failed";
}

int run_build(const BuildArgs& a, std::ostream& out, std::ostream& err) {
  BuildOptions options;
  options.spec_path = a.spec;
  options.out_dir = a.out;
  options.jobs = a.jobs;
  options.use_cache = !a.no_cache;
  options.cache_dir = a.cache_dir;
  options.depfile = a.depfile;
  options.cpp_name = a.cpp_name;
  options.cpp_namespace = a.ns;
  options.defines = a.defines;
  options.target_env = a.target_env;
  options.write_stats = a.stats;
  options.strip_debug = a.strip_debug;
  options.verbose = a.verbose;
  options.remote_cache_url = a.remote_cache;
  options.remote_cache_read_only = a.remote_cache_readonly;
  options.remote_cache_budget = std::chrono::milliseconds(static_cast<long long>(a.remote_cache_budget * 1000.0));
  auto secret = remote_cache_secret(a, err);
  if (!secret) return kExitError;
  options.remote_cache_secret = std::move(*secret);
  options.log = [&err](const std::string& line) { err << "shadergen: " << line << std::endl; };
  options.cancelled = [] { return g_interrupted.load(); };
  auto summary = build(options);
  if (!summary) {
    if (g_interrupted.load()) {
      err << "shadergen: interrupted; " << a.out << " was left as it was\n";
      return kExitInterrupted;
    }
    return print_errors(summary.errors(), err);
  }
  const BuildSummary& s = *summary;
  out << "shadergen: " << a.out << ": " << s.raw << " raw (" << s.pruned << " pruned), " << s.optimised
      << " optimised, " << s.companions << " companion" << (s.companions == 1 ? "" : "s") << " -> " << s.unique_sources
      << " distinct sources (" << s.compiled << " compiled, " << s.cache_hits << " cached" << remote_counts(s) << "), "
      << s.unique_blobs << " SPIR-V blobs" << (s.output_changed ? "" : "; output unchanged");
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, " in %.2f s\n", s.seconds);
  out << seconds;
  if (a.stats) out << format_build_stats(s);
  return 0;
}

template <class Format>
int run_view(const std::string& spec_path, std::ostream& out, std::ostream& err, Format format) {
  auto spec = load_domain(spec_path);
  if (!spec) return print_errors(spec.errors(), err);
  auto plan = expand(*spec);
  if (!plan) return print_errors(plan.errors(), err);
  return format(*spec, *plan, out, err);
}

// A misspelt subcommand or long option, said with the name meant when one is close
// ("unknown subcommand 'biuld'; did you mean 'build'?"); nullopt when every name is known.
// CLI11's own message for these ("The following arguments were not expected") names no cure.
std::optional<std::string> misspelt_name(CLI::App& app, const std::vector<std::string>& args) {
  if (args.empty() || args[0].empty() || args[0][0] == '-') return std::nullopt;
  std::vector<std::string> subcommands;
  CLI::App* chosen = nullptr;
  for (CLI::App* sub : app.get_subcommands({})) {
    subcommands.push_back(sub->get_name());
    if (sub->get_name() == args[0]) chosen = sub;
  }
  if (!chosen) {
    auto meant = closest_name(args[0], subcommands);
    std::string known;
    for (const std::string& name : subcommands) known += (known.empty() ? "" : ", ") + name;
    return "unknown subcommand '" + args[0] + "'" +
           (meant ? "; did you mean '" + *meant + "'?" : " (subcommands: " + known + ")");
  }
  std::vector<std::string> options{"--help"};
  for (const CLI::Option* option : chosen->get_options({}))
    for (const std::string& name : option->get_lnames()) options.push_back("--" + name);
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--") break;  // everything after is positional
    if (args[i].rfind("--", 0) != 0) continue;
    std::string name = args[i].substr(0, args[i].find('='));
    if (std::find(options.begin(), options.end(), name) != options.end()) continue;
    auto meant = closest_name(name, options);
    return "unknown option '" + name + "' for '" + args[0] + "'" +
           (meant ? "; did you mean '" + *meant + "'?" : std::string());
  }
  return std::nullopt;
}

int run_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"shadergen " SHADERGEN_VERSION
               " - compiles an uber-shader and a permutation-domain spec into every permutation as validated "
               "SPIR-V, a manifest and generated C++ (lookup table + registry).",
               "shadergen"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text());

  BuildArgs b;
  CLI::App* build_cmd = app.add_subcommand("build", "Compile every permutation of a domain into an output folder");
  build_cmd->add_option("spec", b.spec, "Domain spec (JSON)")->required();
  build_cmd->add_option("--out,-o", b.out, "Output folder: manifest.json, spirv/, <name>.h/.cpp (replaced atomically)")
      ->required();
  build_cmd->add_option("-j,--jobs", b.jobs, "Parallel compile jobs (default: one per hardware thread)")
      ->check(CLI::Range(1u, 1024u));
  build_cmd->add_flag("--no-cache", b.no_cache, "Ignore the content cache and compile everything (a cold build)");
  build_cmd->add_option("--cache-dir", b.cache_dir,
                        "Content cache folder (default: $SHADERGEN_CACHE_DIR, else $XDG_CACHE_HOME/shadergen, "
                        "else ~/.cache/shadergen)");
  build_cmd->add_option("--depfile", b.depfile, "Write a Make-style depfile listing the spec and every GLSL file read");
  build_cmd->add_option("--cpp-name", b.cpp_name, "Base name of the generated .h/.cpp (default: the domain name)");
  build_cmd->add_option("--namespace", b.ns, "C++ namespace of the generated code (default: the domain name)");
  build_cmd
      ->add_option("-D,--define", b.defines,
                   "NAME=VALUE (or NAME, meaning 1) for every shader of the domain; repeatable; adds to and "
                   "replaces the spec's \"defines\"")
      ->allow_extra_args(false);
  build_cmd->add_option("--target-env", b.target_env,
                        "vulkan1.0, vulkan1.1, vulkan1.2 or vulkan1.3: the Vulkan (and so SPIR-V) version to compile "
                        "and validate for (default: the spec's \"target_env\", else vulkan1.2)");
  build_cmd->add_flag("--strip-debug", b.strip_debug,
                      "Write blobs without debug instructions (names, sources, lines), as the spec's "
                      "\"strip_debug\": true; the manifest and registry keep the names");
  build_cmd->add_flag("--stats", b.stats, "Also write stats.json: per-stage counts and per-permutation timings");
  build_cmd->add_flag("-v,--verbose", b.verbose, "One progress line per compiled source");
  build_cmd
      ->add_option("--remote-cache", b.remote_cache,
                   "Content cache shared over HTTP, asked after the local one: GET/PUT URL/<key-prefix>/<key>")
      ->envname("SHADERGEN_REMOTE_CACHE");
  build_cmd->add_flag("--remote-cache-readonly", b.remote_cache_readonly,
                      "Only read the remote cache, never upload to it (developer machines)");
  build_cmd->add_option("--remote-cache-secret-file", b.remote_cache_secret_file,
                        "Sign uploads and accept only signed entries, with the secret in this file (default: "
                        "$SHADERGEN_REMOTE_CACHE_SECRET; none: entries are neither signed nor checked)");
  build_cmd
      ->add_option("--remote-cache-budget", b.remote_cache_budget,
                   "Seconds the remote cache's requests may keep a build waiting in all before it is turned off "
                   "for the rest of the build (default 10; each request waits at most 5)")
      ->check(CLI::Range(0.0, 3600.0));

  std::string spec_path;
  CLI::App* lut_cmd = app.add_subcommand("lut", "Print the raw -> optimised lookup table");
  lut_cmd->add_option("spec", spec_path, "Domain spec (JSON)")->required();
  CLI::App* list_cmd = app.add_subcommand("list", "List every raw and optimised permutation with its defines");
  list_cmd->add_option("spec", spec_path, "Domain spec (JSON)")->required();
  std::string raw_text;
  CLI::App* explain_cmd =
      app.add_subcommand("explain", "Explain what a raw ID means and which optimised ID it maps to");
  explain_cmd->add_option("spec", spec_path, "Domain spec (JSON)")->required();
  explain_cmd->add_option("raw-id", raw_text, "A raw ID: 83, 0x53, or names such as SKY|SUN_LIGHT")->required();

  if (auto problem = misspelt_name(app, args)) {
    err << "shadergen: error: " << *problem << '\n';
    return kExitUsage;
  }
  try {
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them backwards
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e, out, err);
    return code == 0 ? 0 : kExitUsage;
  }

  if (*build_cmd) return run_build(b, out, err);
  if (*lut_cmd)
    return run_view(spec_path, out, err,
                    [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o, std::ostream&) {
                      o << format_lut(s, p);
                      return 0;
                    });
  if (*list_cmd)
    return run_view(spec_path, out, err,
                    [](const DomainSpec& s, const PermutationPlan& p, std::ostream& o, std::ostream&) {
                      o << format_list(s, p);
                      return 0;
                    });
  return run_view(spec_path, out, err,
                  [&](const DomainSpec& s, const PermutationPlan& p, std::ostream& o, std::ostream& e) {
                    std::string why;
                    auto id = parse_raw_id(s, raw_text, why);
                    if (!id) {
                      e << "shadergen: error: " << why << '\n';
                      return kExitUsage;
                    }
                    o << format_explanation(s, p, *id);
                    return 0;
                  });
}

}  // namespace

// The library reports what it expects as diagnostics; what is left is the unexpected (out of
// memory in a compile job, a failed thread start), which still deserves a message and exit 1
// rather than std::terminate. The output folder is only replaced at the very end of a build, so
// it is left as it was.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    return run_command(args, out, err);
  } catch (const std::bad_alloc&) {
    err << "shadergen: error: out of memory\n";
  } catch (const std::exception& e) {
    err << "shadergen: error: " << e.what() << '\n';
  }
  return kExitError;
}

int run_cli(int argc, char** argv) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::vector<std::string> args(argv + 1, argv + argc);
  return run_cli(args, std::cout, std::cerr);
}

}  // namespace shadergen
