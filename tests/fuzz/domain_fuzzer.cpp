// Fuzz entry point: the domain-spec parser, then what `shadergen lut` / `list` / `explain` do
// with a spec it accepts (expansion, the lookup table, the text views). No GLSL is compiled.
//
// Beyond "no crash, no hang, no leak", it checks that every rejection names the file, and that
// an accepted spec expands to a plan of the advertised size whose table entries are in range.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.h"
#include "shadergen/domain.h"
#include "shadergen/permutations.h"

namespace {

constexpr const char* kFile = "fuzz.json";

void check_errors_name_the_file(const shadergen::Diagnostics& errors) {
  using shadergen::fuzz::require;
  require(!errors.empty(), "a failed result carries at least one diagnostic");
  for (const shadergen::Diagnostic& d : errors) {
    require(d.file == kFile, "every diagnostic names the spec file");
    require(!d.message.empty(), "every diagnostic says what is wrong");
  }
}

void check_plan(const shadergen::DomainSpec& spec, const shadergen::PermutationPlan& plan, std::size_t pick) {
  using shadergen::fuzz::require;
  require(plan.raw.size() == spec.raw_space(), "one raw permutation per raw ID");
  require(plan.optimised.size() == spec.optimised_count(), "one optimised permutation per optimised ID");
  for (const shadergen::RawPermutation& raw : plan.raw)
    require(spec.collapsed ? raw.optimised < spec.optimised_count() : raw.optimised == raw.id,
            "every table entry is an optimised ID (the raw ID itself without collapse)");
  for (const shadergen::OptimisedPermutation& optimised : plan.optimised)
    require(optimised.raw_equivalent < spec.raw_space(), "every optimised ID compiles a raw feature set");
  // The text views walk every permutation; explain one raw ID chosen by the input.
  require(!shadergen::format_lut(spec, plan).empty(), "the lookup table prints");
  require(!shadergen::format_list(spec, plan).empty(), "the permutation list prints");
  auto raw_id = static_cast<std::uint32_t>(pick % spec.raw_space());
  require(!shadergen::format_explanation(spec, plan, raw_id).empty(), "a raw ID explains");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  auto spec = shadergen::parse_domain(text, kFile);
  if (!spec) {
    check_errors_name_the_file(spec.errors());
    return 0;
  }
  // The fuzzer reads no files: a "variants_file" key is dropped, so every raw ID is enumerated.
  spec->variants_path.clear();
  auto plan = shadergen::expand(*spec);
  if (!plan) {
    check_errors_name_the_file(plan.errors());
    return 0;
  }
  check_plan(*spec, *plan, size);
  return 0;
}
