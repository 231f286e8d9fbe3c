#include "compile/compiled_domain.h"

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

}  // namespace shadergen
