#include "manifest.h"

#include <cstring>

#include "json.h"
#include "stages.h"

namespace shadergen {

std::string blob_relative_path(const Blob& blob) { return "spirv/" + blob.hash.substr(0, 16) + ".spv"; }

namespace {

void write_stage_list(json::Writer& w, std::uint32_t stages) {
  std::vector<std::string> names;
  for (std::uint32_t bit = 1; bit <= static_cast<std::uint32_t>(Stage::callable); bit <<= 1)
    if (stages & bit) names.emplace_back(stage_name(static_cast<Stage>(bit)));
  w.inline_string_array(names);
}

void write_bindings(json::Writer& w, const std::vector<BindingInfo>& bindings);
void write_variables(json::Writer& w, const char* key, const std::vector<VariableInfo>& variables);

// With "layout": "per_permutation", the permutation's own layout: its blob's bindings, push
// constants and outputs.
void write_own_layout(json::Writer& w, const Blob& blob) {
  w.key("layout");
  w.begin_object();
  write_bindings(w, blob.reflection.bindings);
  w.key("push_constant_size"), w.value(blob.reflection.push_constant_size);
  write_variables(w, "outputs", blob.reflection.outputs);
  w.end_object();
}

void write_blob_fields(json::Writer& w, const Blob* blob, const DomainSpec& spec) {
  if (!blob) return;
  w.key("spirv");
  w.value(blob_relative_path(*blob));
  w.key("hash");
  w.value(blob->hash);
  if (spec.layout == LayoutMode::per_permutation) write_own_layout(w, *blob);
}

// The "program" form: the permutation's vertex shader beside its fragment shader.
void write_vertex_half(json::Writer& w, const Blob* blob) {
  if (!blob) return;
  w.key("vertex_spirv"), w.value(blob_relative_path(*blob));
  w.key("vertex_hash"), w.value(blob->hash);
}

void write_features(json::Writer& w, const DomainSpec& spec) {
  w.key("raw_features");
  w.begin_array();
  for (const RawFeature& f : spec.raw_features) {
    w.begin_object();
    w.key("name"), w.value(f.name);
    w.key("bit"), w.value(f.bit);
    w.key("define"), w.value(f.define);
    w.end_object();
  }
  w.end_array();
  w.key("optimised_bits");
  w.begin_array();
  for (const OptimisedBit& b : spec.optimised_bits) {
    w.begin_object();
    w.key("name"), w.value(b.name);
    w.key("bit"), w.value(b.bit);
    w.key("when"), w.value(b.when.text);
    w.end_object();
  }
  w.end_array();
}

void write_permutations(json::Writer& w, const CompiledDomain& d) {
  w.key("raw");
  w.begin_array();
  for (const RawPermutation& raw : d.plan.raw) {
    w.begin_object();
    w.key("id"), w.value(raw.id);
    w.key("defines"), w.inline_string_array(raw.defines);
    w.key("pruned"), w.value(raw.pruned);
    if (d.spec.collapsed) w.key("optimised"), w.value(raw.optimised);
    write_blob_fields(w, raw.pruned ? nullptr : d.raw_blob(raw.id), d.spec);
    write_vertex_half(w, raw.pruned ? nullptr : d.raw_vertex_blob(raw.id));
    w.end_object();
  }
  w.end_array();
  w.key("optimised");
  w.begin_array();
  for (const OptimisedPermutation& optimised : d.plan.optimised) {
    w.begin_object();
    w.key("id"), w.value(optimised.id);
    w.key("defines"), w.inline_string_array(optimised.defines);
    w.key("raw_equivalent"), w.value(optimised.raw_equivalent);
    w.key("raw_mapped"), w.value(optimised.raw_mapped);
    write_blob_fields(w, d.optimised_blob(optimised.id), d.spec);
    write_vertex_half(w, d.optimised_vertex_blob(optimised.id));
    w.end_object();
  }
  w.end_array();
}

void write_companions(json::Writer& w, const CompiledDomain& d) {
  w.key("companions");
  w.begin_array();
  for (std::size_t i = 0; i < d.spec.companions.size(); ++i) {
    const CompanionSpec& c = d.spec.companions[i];
    w.begin_object();
    w.key("name"), w.value(c.name);
    w.key("stage"), w.value(stage_name(c.file.stage));
    w.key("defines"), w.inline_string_array(c.defines);
    w.key("shared_layout"), w.value(c.shared_layout);
    write_blob_fields(w, d.companion_blob(i), d.spec);
    w.end_object();
  }
  w.end_array();
}

// {set, binding, kind, count, stages, name}, plus runtime_sized and input_attachment_index
// where they apply.
void write_bindings(json::Writer& w, const std::vector<BindingInfo>& bindings) {
  w.key("bindings");
  w.begin_array();
  for (const BindingInfo& b : bindings) {
    w.begin_object();
    w.key("set"), w.value(b.set);
    w.key("binding"), w.value(b.binding);
    w.key("kind"), w.value(descriptor_kind_name(b.kind));
    w.key("count"), w.value(b.count);
    w.key("stages"), write_stage_list(w, b.stages);
    w.key("name"), w.value(b.name);
    if (b.runtime_sized) w.key("runtime_sized"), w.value(true);
    if (b.kind == DescriptorKind::input_attachment) w.key("input_attachment_index"), w.value(b.input_attachment_index);
    w.end_object();
  }
  w.end_array();
}

void write_variables(json::Writer& w, const char* key, const std::vector<VariableInfo>& variables) {
  w.key(key);
  w.begin_array();
  for (const VariableInfo& v : variables) {
    w.begin_object();
    w.key("location"), w.value(v.location);
    w.key("components"), w.value(v.components);
    w.key("name"), w.value(v.name);
    w.end_object();
  }
  w.end_array();
}

std::string_view scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::boolean: return "bool";
    case ScalarType::int32: return "int";
    case ScalarType::uint32: return "uint";
    case ScalarType::float32: return "float";
  }
  return "?";
}

// The default as JSON of its own type.
void write_default(json::Writer& w, const SpecConstantInfo& c) {
  switch (c.type) {
    case ScalarType::boolean: w.value(c.default_bits != 0); break;
    case ScalarType::int32: w.value(static_cast<std::int64_t>(static_cast<std::int32_t>(c.default_bits))); break;
    case ScalarType::uint32: w.value(static_cast<std::int64_t>(c.default_bits)); break;
    case ScalarType::float32: {
      float f = 0;
      std::memcpy(&f, &c.default_bits, sizeof f);
      w.value(static_cast<double>(f));
      break;
    }
  }
}

void write_workgroup(json::Writer& w, const ReflectionInfo& r) {
  w.key("local_size");
  w.begin_array();
  for (std::uint32_t size : r.local_size) w.value(size);
  w.end_array();
  w.key("local_size_ids");
  w.begin_array();
  for (std::uint32_t id : r.local_size_ids)
    if (id == Reflection::kNoConstant)
      w.null();
    else
      w.value(id);
  w.end_array();
}

// Every distinct blob with its own reflection: what a permutation needs when it has a
// pipeline layout of its own, its work-group size and its specialization constants.
void write_blobs(json::Writer& w, const CompiledDomain& d) {
  std::vector<Stage> stages(d.blobs.size(), Stage::fragment);
  for (const CompileJob& job : d.jobs) stages[static_cast<std::size_t>(job.blob)] = job.stage;
  w.key("blobs");
  w.begin_array();
  for (std::size_t i = 0; i < d.blobs.size(); ++i) {
    const ReflectionInfo& r = d.blobs[i].reflection;
    w.begin_object();
    w.key("spirv"), w.value(blob_relative_path(d.blobs[i]));
    w.key("stage"), w.value(stage_name(stages[i]));
    write_bindings(w, r.bindings);
    w.key("push_constant_size"), w.value(r.push_constant_size);
    write_variables(w, "inputs", r.inputs);
    write_variables(w, "outputs", r.outputs);
    if (has_workgroup(stages[i])) write_workgroup(w, r);
    w.key("specialization_constants");
    w.begin_array();
    for (const SpecConstantInfo& c : r.specialization_constants) {
      w.begin_object();
      w.key("id"), w.value(c.id);
      w.key("name"), w.value(c.name);
      w.key("type"), w.value(scalar_type_name(c.type));
      w.key("default"), write_default(w, c);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.end_array();
}

void write_layout(json::Writer& w, const MergedLayout& layout) {
  w.key("pipeline_layout");
  w.begin_object();
  write_bindings(w, layout.bindings);
  w.key("push_constants");
  w.begin_array();
  for (const PushConstantInfo& p : layout.push_constants) {
    w.begin_object();
    w.key("size"), w.value(p.size);
    w.key("stages"), write_stage_list(w, p.stages);
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

}  // namespace

std::string write_manifest(const CompiledDomain& d) {
  json::Writer w;
  w.begin_object();
  w.key("format"), w.value(1);
  w.key("generator"), w.value("shadergen " SHADERGEN_VERSION);
  w.key("domain"), w.value(d.spec.name);
  w.key("uber_shader"), w.value(d.spec.uber.path.filename().string());
  w.key("stage"), w.value(stage_name(d.spec.uber.stage));
  if (d.spec.program_vertex) w.key("vertex_shader"), w.value(d.spec.program_vertex->path.filename().string());
  w.key("target_env"), w.value(target_env_name(d.spec.target_env));
  w.key("collapsed"), w.value(d.spec.collapsed);
  w.key("layout"), w.value(d.spec.layout == LayoutMode::shared ? "shared" : "per_permutation");
  write_features(w, d.spec);
  write_permutations(w, d);
  write_companions(w, d);
  write_layout(w, d.layout);
  write_blobs(w, d);
  w.end_object();
  return w.take();
}

std::string write_stats(const CompiledDomain& d, double seconds) {
  std::uint32_t pruned = 0, hits = 0, fallbacks = 0;
  for (const RawPermutation& raw : d.plan.raw) pruned += raw.pruned;
  for (const SourceRecord& s : d.sources) hits += s.cache_hit;
  for (const Blob& b : d.blobs) fallbacks += b.fell_back;
  json::Writer w;
  w.begin_object();
  w.key("stages");
  w.begin_object();
  w.key("raw"), w.value(static_cast<std::uint32_t>(d.plan.raw.size()));
  w.key("pruned"), w.value(pruned);
  w.key("canonical"), w.value(static_cast<std::uint32_t>(d.jobs.size()));
  w.key("unique_sources"), w.value(static_cast<std::uint32_t>(d.sources.size()));
  w.key("cache_hits"), w.value(hits);
  w.key("unique_blobs"), w.value(static_cast<std::uint32_t>(d.blobs.size()));
  w.key("optimiser_fallbacks"), w.value(fallbacks);
  w.end_object();
  std::uint32_t recompiled = 0;
  for (const CompileJob& job : d.jobs) recompiled += !d.sources[static_cast<std::size_t>(job.source)].cache_hit;
  w.key("recompiled_permutations"), w.value(recompiled);
  w.key("reused_permutations"), w.value(static_cast<std::uint32_t>(d.jobs.size()) - recompiled);
  w.key("inputs_reused"), w.value(d.inputs_reused);
  if (d.remote) {
    w.key("remote_cache");
    w.begin_object();
    w.key("fetched"), w.value(d.remote->fetched);
    w.key("missed"), w.value(d.remote->missed);
    w.key("uploaded"), w.value(d.remote->uploaded);
    w.key("failed"), w.value(d.remote->failed);
    w.end_object();
  }
  w.key("phases_ms");
  w.begin_object();
  for (const PhaseTime& phase : d.phases) w.key(phase.name), w.value(phase.ms);
  w.end_object();
  w.key("seconds"), w.value(seconds);
  w.key("permutations");
  w.begin_array();
  for (const CompileJob& job : d.jobs) {
    const SourceRecord& source = d.sources[static_cast<std::size_t>(job.source)];
    const Blob& blob = d.blobs[static_cast<std::size_t>(job.blob)];
    w.begin_object();
    w.key("permutation"), w.value(job.label());
    w.key("source"), w.value(job.source);
    w.key("compiled_here"), w.value(source.first_job == static_cast<std::size_t>(&job - d.jobs.data()));
    w.key("cache_hit"), w.value(source.cache_hit);
    w.key("preprocess_ms"), w.value(job.preprocess_ms);
    w.key("compile_ms"), w.value(source.compile_ms);
    w.key("spirv_bytes"), w.value(static_cast<std::int64_t>(blob.words.size() * 4));
    if (blob.fell_back) w.key("optimiser_fallback"), w.value(blob.fallback_reason);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return w.take();
}

namespace {
std::string escape_make(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}
}  // namespace

std::string write_depfile(const std::string& target, const CompiledDomain& d) {
  std::string out = escape_make(target) + ":";
  for (const auto& dep : d.dependencies) {
    std::error_code ec;
    auto absolute = std::filesystem::absolute(dep, ec);
    out += " \\\n  " + escape_make((ec ? dep : absolute).lexically_normal().string());
  }
  return out + "\n";
}

}  // namespace shadergen
