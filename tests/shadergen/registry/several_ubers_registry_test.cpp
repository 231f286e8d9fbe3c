// The generated code of a spec with "uber_shaders" (tests/fixtures/several_ubers: a fragment and
// a compute uber-shader over one domain): one table and typed API, one registry per entry with
// the same permutations and its own blobs and layout, and typed companion accessors that return
// the entry registry's own records.
#include <gtest/gtest.h>

#include <string_view>

#include <several_ubers_permutations.h>

namespace {

using several_ubers::OptimisedId;
using several_ubers::RawId;

TEST(SeveralUbersRegistry, EachEntryHasItsStageAndTheDomainsOneTable) {
  const shadergen::Registry& raster = several_ubers::raster::registry();
  const shadergen::Registry& compute = several_ubers::compute::registry();
  EXPECT_EQ(raster.uber_stage, shadergen::Stage::fragment);
  EXPECT_EQ(compute.uber_stage, shadergen::Stage::compute);
  static_assert(several_ubers::kRawCount == 8 && several_ubers::kOptimisedCount == 5);
  for (const shadergen::Registry* r : {&raster, &compute}) {
    ASSERT_EQ(r->raw.size(), several_ubers::kRawCount);
    ASSERT_EQ(r->optimised.size(), several_ubers::kOptimisedCount);
    for (std::uint32_t id = 0; id < several_ubers::kRawCount; ++id) {
      EXPECT_EQ(r->optimised_id(RawId(id)), several_ubers::optimised_id(RawId(id))) << id;
      EXPECT_EQ(r->find_raw(RawId(id)) == nullptr, several_ubers::kRawPruned[id]) << id;
    }
  }
}

TEST(SeveralUbersRegistry, EveryPermutationHasABlobPerEntryAndTheyDiffer) {
  const shadergen::Registry& raster = several_ubers::raster::registry();
  const shadergen::Registry& compute = several_ubers::compute::registry();
  for (std::uint32_t id = 0; id < several_ubers::kOptimisedCount; ++id) {
    const shadergen::Permutation* f = raster.find_optimised(OptimisedId(id));
    const shadergen::Permutation* c = compute.find_optimised(OptimisedId(id));
    ASSERT_NE(f, nullptr);
    ASSERT_NE(c, nullptr);
    EXPECT_FALSE(f->spirv.empty());
    EXPECT_FALSE(c->spirv.empty());
    EXPECT_NE(f->hash, c->hash) << id;
    // The same permutation: the same defines in both entries.
    ASSERT_EQ(f->defines.size(), c->defines.size()) << id;
    for (std::size_t i = 0; i < f->defines.size(); ++i) EXPECT_EQ(f->defines[i], c->defines[i]);
    EXPECT_EQ(c->reflection.local_size[0], 8u);
  }
  // Each entry's merged layout: the compute form adds its storage image.
  EXPECT_EQ(raster.pipeline_layout.size(), 1u);
  EXPECT_EQ(compute.pipeline_layout.size(), 2u);
}

TEST(SeveralUbersRegistry, TypedCompanionsAreTheirEntrysRecords) {
  const shadergen::Registry& raster = several_ubers::raster::registry();
  const shadergen::Registry& compute = several_ubers::compute::registry();
  EXPECT_EQ(&several_ubers::companions::full_screen(), raster.companion("full_screen"));
  EXPECT_EQ(&several_ubers::companions::clear(), compute.companion("clear"));
  EXPECT_EQ(&several_ubers::companions::histogram(), compute.companion("histogram"));
  EXPECT_EQ(raster.companion("clear"), nullptr);
  EXPECT_EQ(compute.companion("full_screen"), nullptr);
  EXPECT_EQ(several_ubers::companions::full_screen().stage, shadergen::Stage::vertex);
  EXPECT_EQ(several_ubers::companions::clear().name, std::string_view("clear"));
  EXPECT_FALSE(several_ubers::companions::histogram().shader.spirv.empty());
}

}  // namespace
