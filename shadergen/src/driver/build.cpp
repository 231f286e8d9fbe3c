#include "shadergen/build.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <span>

#include "base/file_io.h"
#include "base/phase_clock.h"
#include "base/untrusted_text.h"
#include "cache/cache.h"
#include "cache/input_cache.h"
#include "cache/remote_cache.h"
#include "cache/shard_record.h"
#include "compile/blob_spill.h"
#include "compile/compile_domain.h"
#include "compile/shard_partition.h"
#include "compile/toolchain.h"
#include "driver/shard_check.h"
#include "output/codegen.h"
#include "output/manifest.h"
#include "output/output_dir.h"
#include "output/renumbering.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"
#include "spec/defines.h"
#include "spec/load_spec.h"
#include "spec/uber_shader_entries.h"
#include "spec/variants_file.h"

namespace shadergen {
namespace {

Status check_names(const std::string& cpp_name, const std::string& ns) {
  if (!is_valid_namespace(ns))
    return make_error("--namespace: \"" + ns + "\" is not a C++ namespace (identifiers joined by ::)");
  if (cpp_name.empty() || cpp_name.find('/') != std::string::npos || cpp_name.find('\\') != std::string::npos ||
      cpp_name.front() == '.')
    return make_error("--cpp-name: \"" + cpp_name + "\" is not a plain file name");
  return Ok{};
}

// An output written by `write` straight to a file in the spill, staged from there.
template <class Write>
Status spill_output(BlobSpill& spill, StagedOutput& staged, const std::string& name, const Write& write) {
  auto file = spill.scratch_file(name);
  if (!file) return std::move(file).take_errors();
  std::ofstream out(*file, std::ios::binary | std::ios::trunc);
  if (!out) return make_error(spill.shown(*file).string(), 0, std::string("cannot write: ") + std::strerror(errno));
  errno = 0;
  write(out);
  out.close();
  if (!out) return make_error(spill.shown(*file).string(), 0, "write failed: " + BlobSpill::write_failure(errno));
  staged.add_file(name, *file);
  return Ok{};
}

// Every output that grows with the domain is a file in the spill (the blobs since they were
// made); only the header is held in memory. `entries`: one compiled domain per uber-shader.
Result<StagedOutput> outputs_for(const BuildOptions& options, std::span<const CompiledDomain> entries, BlobSpill& spill,
                                 const std::string& cpp_name, const std::string& ns, double seconds) {
  StagedOutput staged(options.out_dir);
  Status s = spill_output(spill, staged, "manifest.json", [&](std::ostream& out) { write_manifest(entries, out); });
  if (!s) return std::move(s).take_errors();
  for (const CompiledDomain& domain : entries)
    for (const Blob& blob : domain.blobs) staged.add_file(blob_relative_path(blob), spill.path_of(blob.hash));
  staged.add(cpp_name + ".h", generated_header(entries, ns));
  auto source = spill.scratch_file(cpp_name + ".cpp");
  if (!source) return std::move(source).take_errors();
  if (Status written = write_generated_source(entries, spill, cpp_name + ".h", ns, *source); !written)
    return std::move(written).take_errors();
  staged.add_file(cpp_name + ".cpp", *source);
  if (options.write_stats) {
    s = spill_output(spill, staged, "stats.json", [&](std::ostream& out) { write_stats(entries, seconds, out); });
    if (!s) return std::move(s).take_errors();
  }
  return staged;
}

// The command line's defines on top of the spec's. A feature's define is refused: the
// permutations without the feature would have it on.
Status apply_command_line_defines(DomainSpec& spec, const std::vector<std::string>& arguments) {
  Diagnostics errors;
  std::vector<std::string> parsed;
  for (const std::string& argument : arguments) {
    auto define = parse_define_argument(argument);
    if (!define) {
      errors.push_back(define.errors().front());
      continue;
    }
    for (const RawFeature& feature : spec.raw_features)
      if (feature.define == define_name(*define))
        errors.push_back(make_error("--define " + argument + ": " + feature.define + " is the define of raw feature " +
                                    feature.name + " of " + spec.spec_path.string() +
                                    "; a fixed define cannot also be a feature"));
    parsed.push_back(std::move(define).value());
  }
  if (!errors.empty()) return errors;
  spec.defines = override_defines(std::move(spec.defines), parsed);
  return Ok{};
}

// --target-env wins over the spec's "target_env".
Status apply_target_env(DomainSpec& spec, const std::string& argument) {
  if (argument.empty() || parse_target_env(argument, spec.target_env)) return Ok{};
  return make_error("--target-env: unknown target environment \"" + argument + "\" (expected " +
                    std::string(target_env_choices()) + ")");
}

// The settings that the spec's bytes do not hold but that decide the content keys, for the
// input-set key.
// The variants file is an input like the spec: its digest is part of the key.
std::string preprocessing_settings(const DomainSpec& spec, const std::string& variants_digest) {
  std::string text = "target " + std::string(target_env_name(spec.target_env)) + "\ndefines";
  for (const std::string& define : spec.defines) text += "\n" + define;
  if (!variants_digest.empty()) text += "\nvariants " + variants_digest;
  return text;
}

// The depfile names the variants file too, so that editing it rebuilds.
void add_dependency(std::vector<std::filesystem::path>& dependencies, const std::filesystem::path& file) {
  if (file.empty()) return;
  auto at = std::lower_bound(dependencies.begin(), dependencies.end(), file);
  if (at == dependencies.end() || *at != file) dependencies.insert(at, file);
}

// The plan's counts once, the compile counts summed over the entries (one per uber-shader).
BuildSummary summarise(std::span<const CompiledDomain> entries) {
  BuildSummary s;
  const CompiledDomain& first = entries.front();
  s.raw = static_cast<std::uint32_t>(first.plan.raw.size());
  for (const RawPermutation& raw : first.plan.raw) s.pruned += raw.pruned;
  s.optimised = static_cast<std::uint32_t>(first.plan.optimised.size());
  s.inputs_reused = true;
  for (const CompiledDomain& d : entries) {
    s.companions += static_cast<std::uint32_t>(d.spec.companions.size());
    s.unique_sources += static_cast<std::uint32_t>(d.sources.size());
    for (const SourceRecord& source : d.sources) (source.cache_hit ? s.cache_hits : s.compiled)++;
    // A shard's jobs only: the others have no source there.
    for (const CompileJob& job : d.jobs) {
      if (job.source < 0) continue;
      ++s.permutations;
      (d.sources[static_cast<std::size_t>(job.source)].cache_hit ? s.reused : s.recompiled)++;
    }
    s.inputs_reused = s.inputs_reused && d.inputs_reused;
    s.unique_blobs += static_cast<std::uint32_t>(d.blobs.size());
    for (const Blob& b : d.blobs) s.optimiser_fallbacks += b.fell_back;
    for (const BlobServes& serves : blob_serves(d)) {
      s.most_pipelines_per_blob = std::max(s.most_pipelines_per_blob, static_cast<std::uint32_t>(serves.pipelines));
      s.most_branch_values_per_blob =
          std::max(s.most_branch_values_per_blob, static_cast<std::uint32_t>(serves.branch_values));
    }
    if (d.remote) s.remote = d.remote;
  }
  return s;
}

// "out/" and "out" are the same folder; the staging logic needs the form with a file name.
BuildOptions normalised(BuildOptions options) {
  std::filesystem::path out = options.out_dir.lexically_normal();
  while (!out.empty() && !out.has_filename() && out.has_parent_path() && out != out.root_path())
    out = out.parent_path();
  options.out_dir = out;
  return options;
}

// A shard and a merge live on the network: they use the remote cache even with --no-cache
// (which then only skips the local one), with no budget and with retries.
std::unique_ptr<RemoteCache> remote_cache_for(const BuildOptions& options) {
  const BuildRole& role = options.role;
  if ((!options.use_cache && !role.networked()) || options.remote_cache_url.empty()) return nullptr;
  // A merge uploads nothing, whatever --remote-cache-readonly says: its success must prove that
  // the shards put everything there.
  RemoteCacheSettings settings{options.remote_cache_url,
                               options.remote_cache_read_only || role.is_merge(),
                               options.remote_cache_secret,
                               options.remote_cache_budget,
                               options.remote_cache_request_limit,
                               role.networked(),
                               role.is_shard()   ? RemoteRole::shard
                               : role.is_merge() ? RemoteRole::merge
                                                 : RemoteRole::build};
  return std::make_unique<RemoteCache>(std::move(settings), make_curl_http_client(), options.log);
}

// Optimised IDs that no raw ID maps to cost a compile each and are never drawn: name them.
void warn_unreachable(const BuildOptions& options, const PermutationPlan& plan) {
  std::string ids;
  std::size_t count = 0;
  for (const OptimisedPermutation& o : plan.optimised)
    if (o.raw_mapped == 0) ids += (count++ ? ", " : "") + std::to_string(o.id);
  if (count == 0 || !options.log) return;
  options.log("warning: " + options.spec_path.string() + ": optimised ID" + (count > 1 ? "s " : " ") + ids +
              (count > 1 ? " are" : " is") +
              " reached by no raw ID; compiled all the same (`shadergen lut` shows the table; to avoid them, "
              "change the optimised bits' \"when\" rules so that no combination of bits is impossible, or use "
              "fewer bits)");
}

// A shard writes nothing: its summary says what became of its sources (of every entry).
BuildSummary shard_summary(std::span<const CompiledDomain> entries, std::vector<PhaseTime> phases,
                           std::chrono::steady_clock::time_point start) {
  BuildSummary summary = summarise(entries);
  summary.sharded = true;
  for (const CompiledDomain& domain : entries) {
    const ShardOutcome& shard = *domain.shard;
    summary.shard_index = shard.index, summary.shard_count = shard.count;
    summary.domain_permutations += static_cast<std::uint32_t>(domain.jobs.size());
    summary.shard_sources += shard.sources, summary.shard_on_server += shard.on_server;
    summary.shard_uploaded += shard.uploaded, summary.shard_replaced += shard.replaced;
  }
  summary.phases = std::move(phases);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

// Compiles the plan from each uber-shader of the spec ("uber_shaders"; else the one), in spec
// order. Each entry has its own input set (its settings name it).
Result<std::vector<CompiledDomain>> compile_entries(const DomainSpec& spec, PermutationPlan plan,
                                                    CompileOptions options, const std::string& input_key_settings,
                                                    const BuildOptions& build_options, const std::string& digest) {
  std::vector<CompiledDomain> entries;
  const std::size_t count = uber_shader_count(spec);
  for (std::size_t i = 0; i < count; ++i) {
    DomainSpec entry_spec = for_uber_shader(spec, i);
    if (!options.input_key.empty()) {
      std::string settings = input_key_settings;
      if (!entry_spec.entry.empty()) settings += "\nuber_shader " + entry_spec.entry;
      options.input_key = input_set_key(current_cache_key_parts(), build_options.spec_path, digest, settings);
    }
    // The last (usually only) entry takes the plan; the others a copy. The plan is moved on the
    // last iteration only, which clang-tidy's use-after-move check cannot see in a loop.
    // NOLINTNEXTLINE(bugprone-use-after-move)
    auto domain = compile_domain(std::move(entry_spec), i + 1 == count ? std::move(plan) : plan, options);
    if (!domain) return std::move(domain).take_errors();
    entries.push_back(std::move(domain).value());
  }
  return entries;
}

}  // namespace

Result<BuildSummary> build(const BuildOptions& given) {
  if (Status valid = validate(given); !valid) return std::move(valid).take_errors();
  const BuildOptions options = normalised(given);
  auto start = std::chrono::steady_clock::now();
  std::vector<PhaseTime> phases;
  PhaseClock clock(phases);
  auto loaded = load_spec(options.spec_path);
  if (!loaded) return std::move(loaded).take_errors();
  Result<DomainSpec> spec(std::move(loaded->spec));
  if (options.log)
    for (const Diagnostic& warning : spec->warnings) options.log(warning.to_string());
  std::string cpp_name = options.cpp_name.empty() ? spec->name : options.cpp_name;
  std::string ns = options.cpp_namespace.empty() ? spec->name : options.cpp_namespace;
  if (Status ok = check_names(cpp_name, ns); !ok) return std::move(ok).take_errors();
  if (Status ok = apply_command_line_defines(*spec, options.defines); !ok) return std::move(ok).take_errors();
  if (Status ok = apply_target_env(*spec, options.target_env); !ok) return std::move(ok).take_errors();
  spec->strip_debug = spec->strip_debug || options.strip_debug;
  auto variants_digest = read_variants_file(*spec, options.variants);
  if (!variants_digest) return std::move(variants_digest).take_errors();
  auto plan = expand(*spec);
  if (!plan) return std::move(plan).take_errors();
  warn_unreachable(options, *plan);
  clock.lap("parse spec");

  ContentCache cache;
  InputCache inputs;
  // A merge reads the server alone and writes no local cache: a warm local cache must not stand
  // in for entries the shards failed to upload.
  if (options.use_cache && !options.role.is_merge()) {
    std::filesystem::path dir = options.cache_dir.empty() ? default_cache_directory() : options.cache_dir;
    if (!dir.empty()) cache = ContentCache(dir), inputs = InputCache(dir);
  }
  CompileOptions compile_options;
  compile_options.build = &options;
  compile_options.cache = cache.enabled() ? &cache : nullptr;
  std::unique_ptr<RemoteCache> remote = remote_cache_for(options);
  compile_options.remote = remote.get();
  // Every blob's words go here as they are made, beside the output; removed on every return.
  std::optional<BlobSpill> spill;
  if (!options.role.is_shard())
    compile_options.spill = &spill.emplace(spill_folder_beside(options.out_dir), options.out_dir);
  // The input set is also shared through the remote cache, so a shard or a merge run with
  // --no-cache (no local cache on a farm's fresh node) still takes it from the server.
  if (inputs.enabled() || remote) {
    if (inputs.enabled()) compile_options.inputs = &inputs;
    compile_options.input_key = input_set_key(current_cache_key_parts(), options.spec_path, loaded->digest,
                                              preprocessing_settings(*spec, *variants_digest));
  }
  const std::string shard_key =
      shard_build_key(options.spec_path, loaded->digest, preprocessing_settings(*spec, *variants_digest));
  if (options.role.is_merge() && options.role.shards() > 0) {
    const std::string repair = shard_rerun_command(options.spec_path.string(), "I/N", remote->shown_url());
    if (Status ready = check_shard_records(*remote, shard_key, options.role.shards(), options.jobs, repair); !ready)
      return std::move(ready).take_errors();
    clock.lap("shard records");
  }
  auto compiled = compile_entries(*spec, std::move(plan).value(), compile_options,
                                  preprocessing_settings(*spec, *variants_digest), options, loaded->digest);
  if (!compiled) return std::move(compiled).take_errors();
  if (options.role.is_shard())
    if (Status recorded = record_shard(*remote, shard_key, options.role.place().index, options.role.place().count);
        !recorded)
      return std::move(recorded).take_errors();
  std::vector<CompiledDomain>& entries = *compiled;
  for (CompiledDomain& domain : entries) {
    add_dependency(domain.dependencies, domain.spec.variants_path);
    phases.insert(phases.end(), domain.phases.begin(), domain.phases.end());
  }
  if (remote) entries.back().remote = remote->stats();
  clock.restart();
  if (entries.front().shard) return shard_summary(entries, std::move(phases), start);

  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const CompiledDomain& domain : entries)
    for (const Blob& blob : domain.blobs)
      if (blob.fell_back && options.log)
        // The reason may come from a remote cache's entry: printed escaped and bounded.
        options.log("warning: optimiser fallback for blob " + blob.hash.substr(0, 16) + ": " +
                    printable(blob.fallback_reason));
  if (options.cancelled && options.cancelled()) return make_error("build interrupted");
  // Read before the commit replaces it: the numbering of the previous output.
  const Renumbering renumbered =
      renumbering(previous_numbering(options.out_dir / "manifest.json"), *spec, entries.front().plan);
  auto staged = outputs_for(options, entries, *spill, cpp_name, ns, seconds);
  if (!staged) return std::move(staged).take_errors();
  clock.lap("manifest and codegen");
  auto changed = staged->commit(options.cancelled);
  if (!changed) return std::move(changed).take_errors();
  clock.lap("output compare or write");
  if (!options.depfile.empty()) {
    std::string target = (options.out_dir / (cpp_name + ".h")).string();
    std::string text = write_depfile(target, entries);
    if (!file_has_bytes(options.depfile, text))
      if (Status written = write_file_atomic(options.depfile, text); !written) return std::move(written).take_errors();
  }
  clock.lap("depfile");
  BuildSummary summary = summarise(entries);
  summary.output_changed = *changed;
  summary.renumbered_raw_ids = renumbered.raw_ids;
  summary.kind_changes = renumbered.features;
  summary.phases = std::move(phases);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace shadergen
