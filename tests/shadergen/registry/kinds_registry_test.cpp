// The generated API of a domain with each kind (tests/fixtures/kinds/kinds.json: FOG and SHADING
// variants, SOFT a specialization constant, TAPS a branch): the specialization data and branch
// values of every raw ID agree with the manifest, the constant IDs with the blobs' reflection,
// and shadergen::vulkan::specialization_info() hands the data to Vulkan as it is.
#include <gtest/gtest.h>
#include <shadergen/vulkan.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include <kinds_permutations.h>

namespace {

using nlohmann::json;

json manifest() {
  std::ifstream in(KINDS_MANIFEST);
  return json::parse(in);
}

TEST(KindsRegistry, FeaturesSayTheirKinds) {
  ASSERT_EQ(kinds::kFeatures.size(), 4u);
  EXPECT_EQ(kinds::kFeatures[0].kind, shadergen::FeatureKind::variant);
  EXPECT_EQ(kinds::kFeatures[1].kind, shadergen::FeatureKind::specialization);
  EXPECT_EQ(kinds::kFeatures[2].kind, shadergen::FeatureKind::branch);
  EXPECT_EQ(kinds::kFeatures[3].kind, shadergen::FeatureKind::variant);
}

TEST(KindsRegistry, SpecializationAndBranchValuesMatchTheManifestForEveryRawId) {
  const json m = manifest();
  std::size_t checked = 0;
  for (const json& raw : m["raw"]) {
    if (raw["pruned"].get<bool>()) continue;
    const auto id = raw["id"].get<std::uint32_t>();
    ASSERT_TRUE(kinds::is_valid_raw_id(kinds::RawId(id))) << id;
    const shadergen::Specialization s = kinds::specialization(kinds::RawId(id)).value();
    EXPECT_EQ(s.data_size, 4u);
    EXPECT_EQ(s.data[0], raw["specialization"]["SOFT"].get<bool>() ? 1u : 0u) << id;
    const shadergen::BranchValues b = kinds::branch_values(kinds::RawId(id)).value();
    EXPECT_EQ(b.size, kinds::kBranchBlock.size);
    EXPECT_EQ(static_cast<std::int32_t>(b.words[0]), raw["branch_values"]["TAPS"].get<std::int32_t>()) << id;
    ++checked;
  }
  EXPECT_EQ(checked, 18u);  // 32 raw IDs less the 14 pruned (TAPS index 3, unlit with SOFT)
}

// A pruned or out-of-range raw ID gets no data that looks like a real pipeline's (issue 51).
TEST(KindsRegistry, PrunedAndOutOfRangeIdsHaveNoValuesAndSaySo) {
  const json m = manifest();
  std::size_t pruned = 0;
  for (const json& raw : m["raw"]) {
    if (!raw["pruned"].get<bool>()) continue;
    const kinds::RawId id(raw["id"].get<std::uint32_t>());
    EXPECT_FALSE(kinds::specialization(id).has_value()) << id.value();
    EXPECT_FALSE(kinds::branch_values(id).has_value()) << id.value();
    ++pruned;
  }
  EXPECT_EQ(pruned, 14u);
  const kinds::RawId past(kinds::kRawCount);
  EXPECT_FALSE(kinds::specialization(past).has_value());
  EXPECT_FALSE(kinds::branch_values(past).has_value());
  EXPECT_EQ(kinds::to_string(kinds::RawId(4000)), "RawId(4000): out of range");
  EXPECT_EQ(kinds::to_string(past), "RawId(" + std::to_string(kinds::kRawCount) + "): out of range");
  EXPECT_NE(kinds::to_string(kinds::RawId(kinds::kRawCount - 1)).find("SHADING"), std::string::npos)
      << "the last raw ID is in range";
}

TEST(KindsRegistry, TheBranchBlockIsTheManifestsAndEveryBlobsBinding) {
  const json block = manifest()["branch_block"];
  EXPECT_EQ(kinds::kBranchBlock.set, block["set"].get<std::uint32_t>());
  EXPECT_EQ(kinds::kBranchBlock.binding, block["binding"].get<std::uint32_t>());
  EXPECT_EQ(kinds::kBranchBlock.size, 16u);
  ASSERT_EQ(kinds::kBranchOffsets.size(), 1u);
  EXPECT_EQ(kinds::kBranchOffsets[0], block["members"][0]["offset"].get<std::uint32_t>());
  bool found = false;
  for (const shadergen::DescriptorBinding& b : kinds::registry().pipeline_layout)
    if (b.set == 1 && b.binding == 0) found = b.kind == shadergen::DescriptorKind::uniform_buffer;
  EXPECT_TRUE(found) << "the branch block is in the merged layout";
}

TEST(KindsRegistry, OneBlobServesEverySpecializationAndBranchValue) {
  std::set<const std::uint32_t*> blobs;
  for (const shadergen::Permutation& p : kinds::registry().raw)
    if (!p.pruned) blobs.insert(p.spirv.data());
  EXPECT_EQ(blobs.size(), 4u);  // FOG x SHADING: SOFT and TAPS take no permutation of their own
  for (const shadergen::Permutation& p : kinds::registry().optimised) {
    ASSERT_EQ(p.reflection.specialization_constants.size(), 1u);
    EXPECT_EQ(p.reflection.specialization_constants[0].id, kinds::kSpecializationMap[0].constant_id);
    EXPECT_EQ(p.reflection.specialization_constants[0].name, "SOFT");
  }
}

TEST(KindsRegistry, SpecializationInfoPointsAtTheData) {
  const shadergen::Specialization s = kinds::specialization(*kinds::find_raw_id("FOG|SOFT|TAPS=8|SHADING=PBR")).value();
  const VkSpecializationInfo info = shadergen::vulkan::specialization_info(s);
  ASSERT_EQ(info.mapEntryCount, 1u);
  EXPECT_EQ(info.pMapEntries[0].constantID, kinds::kSpecializationMap[0].constant_id);
  EXPECT_EQ(info.pMapEntries[0].offset, 0u);
  EXPECT_EQ(info.pMapEntries[0].size, 4u);
  EXPECT_EQ(info.dataSize, 4u);
  EXPECT_EQ(*static_cast<const std::uint32_t*>(info.pData), 1u);
}

}  // namespace
