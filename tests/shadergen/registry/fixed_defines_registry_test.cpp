// The fixed-defines fixture built by the CMake function with TARGET_ENV and DEFINES
// (tests/shadergen/CMakeLists.txt: shadergen_add_permutations(fixed_defines_permutations ...
// TARGET_ENV vulkan1.1 DEFINES MAX_LIGHTS=2 GROUP_SIZE=16)): the arguments reach shadergen as
// --target-env and --define, and every shader is compiled with them.
#include <gtest/gtest.h>

#include "registry_digests.h"
#include "registry_lookups.h"

#include <fixed_defines_permutations.h>

namespace {

TEST(FixedDefinesRegistry, LookupsByRawIdAreChecked) {
  const registry_lookups::Counts counts = registry_lookups::expect_checked_lookups(
      fixed::registry(),
      {fixed::kRawCount, fixed::kRawPruned, fixed::kRawToOptimised, fixed::is_valid_raw_id, fixed::optimised_id});
  EXPECT_EQ(counts.valid, 2u);
}

TEST(FixedDefinesRegistry, CMakeDefinesReachEveryShader) {
  const shadergen::Registry& r = fixed::registry();
  ASSERT_EQ(r.push_constants.size(), 1u);
  EXPECT_EQ(r.push_constants[0].size, 2u * 16u) << "DEFINES MAX_LIGHTS=2 replaced the spec's 4";
  const shadergen::CompanionShader* prepass = r.companion("prepass");
  const shadergen::CompanionShader* cull = r.companion("cull");
  ASSERT_TRUE(prepass && cull);
  EXPECT_EQ(prepass->shader.reflection.local_size[0], 16u) << "DEFINES GROUP_SIZE=16 replaced the spec's 64";
  EXPECT_EQ(cull->shader.reflection.local_size[0], 256u) << "the companion's own GROUP_SIZE still wins";
}

TEST(FixedDefinesRegistry, CMakeTargetEnvSetsTheSpirvVersion) {
  const shadergen::Registry& r = fixed::registry();
  std::size_t blobs = 0;
  for (const shadergen::Permutation& p : r.raw) {
    ASSERT_GT(p.spirv.size(), 1u);
    EXPECT_EQ(p.spirv[1], 0x00010300u) << "TARGET_ENV vulkan1.1 means SPIR-V 1.3";
    ++blobs;
  }
  for (const shadergen::CompanionShader& c : r.companions) EXPECT_EQ(c.shader.spirv[1], 0x00010300u) << c.name;
  EXPECT_EQ(blobs, 2u);
}

// Every hash in the generated code is the SHA-256 of its words, by coreutils' implementation.
TEST(FixedDefinesRegistry, HashesAreTheSha256OfTheirWords) {
  EXPECT_GT(registry_digests::expect_hashes_are_sha256_of_words(fixed::registry()), 0u);
}

}  // namespace
