// The typed IDs and bits of a generated registry (the toy fixture's), used right, and used
// wrong one way per MIX_* case. compile_case.cmake compiles it once per case: the control (no
// case) must compile, each case must fail for the reason its test names. Were the types plain
// integers, every case would compile and draw a wrong shader.
#include <toy_permutations.h>

#include <cstdint>

namespace {

// A caller's function over raw bits: only raw_bit:: constants may be passed.
constexpr bool has(toy::RawId id, toy::RawBits bits) { return static_cast<bool>(id & bits); }

}  // namespace

int main() {
  const shadergen::Registry& r = toy::registry();
  const toy::RawId raw = toy::RawId(0) | toy::raw_bit::LIT | toy::raw_bit::SOFT;
  const toy::OptimisedId optimised = toy::optimised_id(raw).value_or(toy::OptimisedId(0));
#if defined(MIX_OPTIMISED_ID_AS_RAW_ID)
  return r.find_raw(optimised) != nullptr;
#elif defined(MIX_RAW_ID_AS_OPTIMISED_ID)
  return r.find_optimised(raw) != nullptr;
#elif defined(MIX_COMPARE_RAW_WITH_OPTIMISED)
  return raw == optimised;
#elif defined(MIX_INTEGER_AS_RAW_ID)
  return toy::is_valid_raw_id(5u);
#elif defined(MIX_RAW_ID_AS_INTEGER)
  const std::uint32_t value = raw;
  return static_cast<int>(value);
#elif defined(MIX_OPTIMISED_BIT_IN_RAW_ID)
  return (raw | toy::optimised_bit::SHADED) == raw;
#elif defined(MIX_OPTIMISED_BIT_AS_RAW_BIT)
  return has(raw, toy::optimised_bit::SAMPLED);
#elif defined(MISSPELT_COMPANION)
  // The spec's companion is "sort": a typed accessor of another name does not exist.
  return toy::companions::sorted().shader.spirv.empty();
#else
  // The control: the same calls with the types each wants.
  const bool found = r.find_raw(raw) != nullptr && r.find_optimised(optimised) != nullptr;
  const bool bits = has(raw, toy::raw_bit::SOFT) && (optimised & toy::optimised_bit::SHADED);
  const bool companion = &toy::companions::sort() == r.companion("sort");
  return found && bits && companion && toy::is_valid_raw_id(toy::RawId(5u)) && raw.value() == 5u ? 0 : 1;
#endif
}
