#include "compile/compiled_domain.h"

namespace shadergen {

std::string CompileJob::label() const {
  switch (kind) {
    case JobKind::raw: return "raw " + std::to_string(id) + (vertex_half ? " vertex" : "");
    case JobKind::optimised: return "optimised " + std::to_string(id) + (vertex_half ? " vertex" : "");
    case JobKind::companion: return "companion " + name;
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
