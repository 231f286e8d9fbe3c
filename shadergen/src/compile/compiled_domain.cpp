#include "compile/compiled_domain.h"

#include <set>

#include "spec/kind_declarations.h"

namespace shadergen {

std::vector<std::string> CompiledDomain::defines_of(const CompileJob& job) const {
  switch (job.kind) {
    case JobKind::raw: return raw_defines(spec, job.id);
    case JobKind::optimised: return plan.find_optimised(job.id)->defines;
    case JobKind::companion: return spec.companions[job.id].defines;
  }
  return {};
}

const std::filesystem::path& CompiledDomain::path_of(const CompileJob& job) const {
  if (job.kind == JobKind::companion) return spec.companions[job.id].file.path;
  return job.vertex_half ? spec.program_vertex->path : spec.uber.path;
}

std::string CompiledDomain::label_of(const CompileJob& job) const {
  switch (job.kind) {
    case JobKind::raw: return "raw " + std::to_string(job.id) + (job.vertex_half ? " vertex" : "");
    case JobKind::optimised: return "optimised " + std::to_string(job.id) + (job.vertex_half ? " vertex" : "");
    case JobKind::companion: return "companion " + spec.companions[job.id].name;
  }
  return {};
}

namespace {

const Blob* blob_of(const CompiledDomain& d, const std::vector<int>& index, std::optional<std::size_t> slot) {
  if (!slot || *slot >= index.size() || index[*slot] < 0) return nullptr;
  int blob = d.jobs[static_cast<std::size_t>(index[*slot])].blob;
  return blob < 0 ? nullptr : &d.blobs[static_cast<std::size_t>(blob)];
}

}  // namespace

const Blob* CompiledDomain::raw_blob(std::uint32_t id) const { return blob_of(*this, raw_jobs, plan.raw_position(id)); }

const Blob* CompiledDomain::optimised_blob(std::uint32_t id) const {
  return blob_of(*this, optimised_jobs, plan.optimised_position(id));
}

const Blob* CompiledDomain::companion_blob(std::size_t index) const { return blob_of(*this, companion_jobs, index); }

const Blob* CompiledDomain::raw_vertex_blob(std::uint32_t id) const {
  return blob_of(*this, raw_vertex_jobs, plan.raw_position(id));
}

const Blob* CompiledDomain::optimised_vertex_blob(std::uint32_t id) const {
  return blob_of(*this, optimised_vertex_jobs, plan.optimised_position(id));
}

namespace {

// The words of `features`' values in `raw_id`, as one key.
std::string value_key(const std::vector<const RawFeature*>& features, std::uint32_t raw_id) {
  std::string key;
  for (const RawFeature* f : features) {
    const std::uint32_t index = f->index_in(raw_id);
    const std::int32_t word = f->valued() ? value_number(*f, index) : static_cast<std::int32_t>(index);
    key.append(reinterpret_cast<const char*>(&word), sizeof word);
  }
  return key;
}

}  // namespace

std::vector<BlobServes> blob_serves(const CompiledDomain& d) {
  std::vector<BlobServes> serves(d.blobs.size());
  const std::vector<const RawFeature*> specs = d.spec.specialization_features(), branches = d.spec.branch_features();
  if (specs.empty() && branches.empty()) return serves;
  std::vector<std::set<std::string>> pipelines(d.blobs.size()), values(d.blobs.size());
  for (const RawPermutation& raw : d.plan.raw) {
    if (raw.pruned) continue;
    const Blob* blob = d.spec.collapsed ? d.optimised_blob(raw.optimised) : d.raw_blob(raw.id);
    if (!blob) continue;
    const auto index = static_cast<std::size_t>(blob - d.blobs.data());
    ++serves[index].raw_ids;
    pipelines[index].insert(value_key(specs, raw.id));
    values[index].insert(value_key(branches, raw.id));
  }
  for (std::size_t i = 0; i < serves.size(); ++i) {
    serves[i].pipelines = pipelines[i].size();
    serves[i].branch_values = values[i].size();
  }
  return serves;
}

}  // namespace shadergen
