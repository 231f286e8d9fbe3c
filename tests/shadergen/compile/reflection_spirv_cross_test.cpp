// Reflection against a second opinion: each shader below is compiled through shadergen's own
// path, reflected by shadergen, and the same blob is given to `spirv-cross --reflect` (Debian
// package spirv-cross). Every descriptor kind glslang produces, aliased bindings, interface
// blocks' member locations, arrayed interfaces (mesh outputs) and an NV task block must agree.
// Also the layout rules that build on reflection: only fragment outputs are attachments, one
// push-constant rule per stage, and the stage of a `name.<stage>.glsl` file.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "compile/glsl_compiler.h"
#include "compile/layout_check.h"
#include "compile/reflection.h"
#include "compile/spirv_passes.h"
#include "spec/stages.h"
#include "test_helpers.h"

namespace {

using nlohmann::json;
using shadergen::DescriptorKind;
using shadergen::Stage;

struct Reflected {
  shadergen::Result<shadergen::ReflectionInfo> ours = shadergen::make_error("not compiled");
  json spirv_cross;  // spirv-cross --reflect of the same blob
};

// Compiles `body` as `stage` (Vulkan 1.2), reflects the optimised blob and asks spirv-cross.
Reflected reflect_both(const std::string& body, Stage stage) {
  sgtest::TempDir dir("reflect-cross");
  sgtest::write_file(dir / "shader.glsl", body);
  shadergen::GlslSource source{dir / "shader.glsl", stage, {}, {}, {}, shadergen::TargetEnv::vulkan1_2};
  Reflected out;
  auto words = shadergen::compile(source);
  EXPECT_TRUE(words.ok()) << (words.ok() ? "" : words.errors().front().to_string());
  if (!words.ok()) return out;
  auto optimised = shadergen::optimise_and_validate(std::move(words).value(), shadergen::TargetEnv::vulkan1_2);
  EXPECT_TRUE(optimised.ok()) << (optimised.ok() ? "" : optimised.errors().front().to_string());
  if (!optimised.ok()) return out;
  out.ours = shadergen::reflect(optimised->words, stage);
  const std::vector<std::uint32_t>& w = optimised->words;
  sgtest::write_file(dir / "blob.spv", std::string(reinterpret_cast<const char*>(w.data()), w.size() * 4));
  sgtest::ProcessResult cross = sgtest::run_process(
      "spirv-cross", {(dir / "blob.spv").string(), "--reflect", "--output", (dir / "reflect.json").string()});
  EXPECT_EQ(cross.exit_code, 0) << "spirv-cross (Debian package spirv-cross) failed: " << cross.err;
  if (cross.exit_code == 0) out.spirv_cross = json::parse(sgtest::read_file(dir / "reflect.json"));
  return out;
}

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// spirv-cross's resource lists as Vulkan descriptor kinds. A texel buffer is listed with the
// images (its type "samplerBuffer" or "imageBuffer"); aliases are listed once per declaration
// and counted once here, as a set layout holds them.
std::map<std::pair<std::uint32_t, std::uint32_t>, DescriptorKind> kinds_of(const json& cross) {
  const std::vector<std::tuple<std::string, DescriptorKind, DescriptorKind>> lists = {
      {"textures", DescriptorKind::combined_image_sampler, DescriptorKind::uniform_texel_buffer},
      {"separate_images", DescriptorKind::sampled_image, DescriptorKind::uniform_texel_buffer},
      {"separate_samplers", DescriptorKind::sampler, DescriptorKind::sampler},
      {"images", DescriptorKind::storage_image, DescriptorKind::storage_texel_buffer},
      {"ubos", DescriptorKind::uniform_buffer, DescriptorKind::uniform_buffer},
      {"ssbos", DescriptorKind::storage_buffer, DescriptorKind::storage_buffer},
      {"subpass_inputs", DescriptorKind::input_attachment, DescriptorKind::input_attachment},
      {"acceleration_structures", DescriptorKind::acceleration_structure, DescriptorKind::acceleration_structure}};
  std::map<std::pair<std::uint32_t, std::uint32_t>, DescriptorKind> out;
  for (const auto& [key, kind, texel_kind] : lists) {
    if (!cross.contains(key)) continue;
    for (const json& r : cross[key])
      out[{r["set"].get<std::uint32_t>(), r["binding"].get<std::uint32_t>()}] =
          ends_with(r["type"].get<std::string>(), "Buffer") ? texel_kind : kind;
  }
  return out;
}

std::map<std::pair<std::uint32_t, std::uint32_t>, DescriptorKind> kinds_of(const shadergen::ReflectionInfo& info) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, DescriptorKind> out;
  for (const shadergen::BindingInfo& b : info.bindings) out[{b.set, b.binding}] = b.kind;
  return out;
}

// "vec3" -> {1 location, 3 components}, "mat2" -> {2, 2}, "float" -> {1, 1}.
std::pair<std::uint32_t, std::uint32_t> footprint(const std::string& type) {
  if (type.rfind("mat", 0) == 0) return {type[3] - '0', type.back() - '0'};
  if (type.size() == 4 && (type.rfind("vec", 0) == 0)) return {1, type[3] - '0'};
  if (type.size() == 5 && type.find("vec") == 1) return {1, type[4] - '0'};
  return {1, 1};
}

// spirv-cross's inputs or outputs as (location, components) pairs: a block's members one after
// another from the block's location; an array a location per element unless `arrayed` (the
// array is the per-vertex one of a mesh, geometry or tessellation interface); variables
// without a location take none.
std::vector<std::pair<std::uint32_t, std::uint32_t>> locations_of(const json& cross, const std::string& key,
                                                                  bool arrayed = false) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  if (!cross.contains(key)) return out;
  for (const json& v : cross[key]) {
    if (!v.contains("location")) continue;
    std::uint32_t location = v["location"];
    std::string type = v["type"];
    if (cross["types"].contains(type)) {
      for (const json& member : cross["types"][type]["members"]) {
        auto [taken, components] = footprint(member["type"]);
        for (std::uint32_t i = 0; i < taken; ++i) out.push_back({location++, components});
      }
      continue;
    }
    auto [taken, components] = footprint(type);
    std::uint32_t elements = 1;
    if (v.contains("array") && !arrayed)
      for (const json& size : v["array"]) elements *= size.get<std::uint32_t>();
    for (std::uint32_t i = 0; i < taken * elements; ++i) out.push_back({location + i, components});
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> locations_of(const std::vector<shadergen::VariableInfo>& list) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const shadergen::VariableInfo& v : list) out.push_back({v.location, v.components});
  std::sort(out.begin(), out.end());
  return out;
}

const char* kEveryKind = R"(#version 460
layout(set = 0, binding = 0) uniform samplerBuffer combined_texels;
layout(set = 0, binding = 1) uniform textureBuffer texels;
layout(set = 0, binding = 2, rgba32f) uniform readonly imageBuffer storage_texels;
layout(set = 0, binding = 3) uniform sampler2D combined;
layout(set = 0, binding = 4) uniform texture2D image;
layout(set = 0, binding = 5) uniform sampler linear;
layout(set = 0, binding = 6, rgba8) uniform readonly image2D storage;
layout(set = 0, binding = 7) uniform Uniforms { vec4 v; } uniforms;
layout(set = 0, binding = 8) readonly buffer Floats { vec4 v[]; } floats;
layout(set = 0, binding = 8) readonly buffer Uints { uvec4 w[]; } uints;
layout(input_attachment_index = 0, set = 1, binding = 0) uniform subpassInput previous;
layout(location = 0) out vec4 colour;
void main() {
  colour = texelFetch(combined_texels, 0) + texelFetch(texels, 1) + imageLoad(storage_texels, 2) +
           texture(combined, vec2(0.5)) + texture(sampler2D(image, linear), vec2(0.5)) +
           imageLoad(storage, ivec2(0)) + uniforms.v + floats.v[0] + vec4(uints.w[1]) + subpassLoad(previous);
}
)";

TEST(ReflectionAgainstSpirvCross, EveryDescriptorKindOfAFragmentShader) {
  Reflected r = reflect_both(kEveryKind, Stage::fragment);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  EXPECT_EQ(kinds_of(*r.ours), kinds_of(r.spirv_cross));
  // The texel buffers by name: samplerBuffer was once reported as a combined image sampler.
  const auto& b = r.ours->bindings;
  ASSERT_EQ(b.size(), 10u) << "the two aliased storage buffers are one binding";
  EXPECT_EQ(b[0].kind, DescriptorKind::uniform_texel_buffer);
  EXPECT_EQ(b[0].name, "combined_texels");
  EXPECT_EQ(b[1].kind, DescriptorKind::uniform_texel_buffer);
  EXPECT_EQ(b[2].kind, DescriptorKind::storage_texel_buffer);
  EXPECT_EQ(b[8].kind, DescriptorKind::storage_buffer);
  EXPECT_EQ(b[8].binding, 8u);
  EXPECT_EQ(b[8].name, "Floats") << "an alias keeps the first declaration's name";
}

TEST(ReflectionAgainstSpirvCross, AccelerationStructuresOfARayGenerationShader) {
  Reflected r = reflect_both(
      "#version 460\n#extension GL_EXT_ray_tracing : require\n"
      "layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;\n"
      "layout(set = 0, binding = 1, rgba8) uniform writeonly image2D target;\n"
      "layout(set = 0, binding = 2) uniform samplerBuffer rays;\n"
      "layout(location = 0) rayPayloadEXT vec4 payload;\n"
      "void main() {\n  traceRayEXT(scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, texelFetch(rays, 0).xyz, 0.0, "
      "vec3(0, 0, 1), 100.0, 0);\n  imageStore(target, ivec2(gl_LaunchIDEXT.xy), payload);\n}\n",
      Stage::ray_generation);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  EXPECT_EQ(kinds_of(*r.ours), kinds_of(r.spirv_cross));
  EXPECT_EQ(r.ours->bindings.size(), 3u);
}

TEST(ReflectionAgainstSpirvCross, AliasesOfAnotherKindAreAnError) {
  Reflected r = reflect_both(
      "#version 460\nlayout(set = 2, binding = 1) uniform U { vec4 v; } u;\n"
      "layout(set = 2, binding = 1) readonly buffer S { vec4 v[]; } s;\nlayout(location = 0) out vec4 colour;\n"
      "void main() { colour = u.v + s.v[0]; }\n",
      Stage::fragment);
  ASSERT_FALSE(r.ours.ok());
  EXPECT_EQ(r.ours.errors().front().message,
            "set 2 binding 1 is declared as uniform_buffer \"U\" and as storage_buffer \"S\"; aliased declarations "
            "must have one descriptor kind and count");
  EXPECT_EQ(kinds_of(r.spirv_cross).size(), 1u);
}

TEST(ReflectionAgainstSpirvCross, InterfaceBlocksTakeTheirMembersLocations) {
  Reflected r = reflect_both(
      "#version 460\nlayout(location = 1) in Varyings { vec2 uv; vec4 tint; mat2 frame; float fade; } v;\n"
      "layout(location = 0) in vec3 normal;\nlayout(location = 0) out vec4 colour;\n"
      "void main() { colour = vec4(v.uv, v.frame[1]) * v.tint * v.fade + vec4(normal, 0); }\n",
      Stage::fragment);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  using P = std::pair<std::uint32_t, std::uint32_t>;
  EXPECT_EQ(locations_of(r.ours->inputs), (std::vector<P>{{0, 3}, {1, 2}, {2, 4}, {3, 2}, {4, 2}, {5, 1}}));
  EXPECT_EQ(locations_of(r.ours->inputs), locations_of(r.spirv_cross, "inputs"));
  EXPECT_EQ(r.ours->inputs[1].name, "Varyings.uv");
  EXPECT_EQ(r.ours->inputs[5].name, "Varyings.fade");
}

TEST(ReflectionAgainstSpirvCross, MeshOutputsAreOneLocationPerVertexArray) {
  Reflected r = reflect_both(
      "#version 460\n#extension GL_EXT_mesh_shader : require\nlayout(local_size_x = 1) in;\n"
      "layout(triangles, max_vertices = 3, max_primitives = 1) out;\n"
      "layout(location = 0) out vec4 colour[];\nlayout(location = 1) out Extra { vec2 uv; vec3 n; } extra[];\n"
      "void main() {\n  SetMeshOutputsEXT(3, 1);\n  for (uint i = 0; i < 3; ++i) {\n"
      "    gl_MeshVerticesEXT[i].gl_Position = vec4(float(i));\n    colour[i] = vec4(1);\n"
      "    extra[i].uv = vec2(i);\n    extra[i].n = vec3(i);\n  }\n"
      "  gl_PrimitiveTriangleIndicesEXT[0] = uvec3(0, 1, 2);\n}\n",
      Stage::mesh);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  using P = std::pair<std::uint32_t, std::uint32_t>;
  EXPECT_EQ(locations_of(r.ours->outputs), (std::vector<P>{{0, 4}, {1, 2}, {2, 3}}));
  EXPECT_EQ(locations_of(r.ours->outputs), locations_of(r.spirv_cross, "outputs", true));
}

TEST(ReflectionAgainstSpirvCross, AnArrayOutsideAnArrayedInterfaceTakesALocationPerElement) {
  Reflected r = reflect_both(
      "#version 460\nlayout(location = 2) out vec2 weights[3];\n"
      "void main() { for (int i = 0; i < 3; ++i) weights[i] = vec2(i); gl_Position = vec4(0); }\n",
      Stage::vertex);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  using P = std::pair<std::uint32_t, std::uint32_t>;
  EXPECT_EQ(locations_of(r.ours->outputs), (std::vector<P>{{2, 2}, {3, 2}, {4, 2}}));
  EXPECT_EQ(locations_of(r.ours->outputs), locations_of(r.spirv_cross, "outputs"));
}

TEST(ReflectionAgainstSpirvCross, AnNvTaskBlockHasNoLocation) {
  Reflected r = reflect_both(
      "#version 460\n#extension GL_NV_mesh_shader : require\nlayout(local_size_x = 32) in;\n"
      "taskNV out Task { uint meshlets[32]; } task_out;\n"
      "void main() {\n  task_out.meshlets[gl_LocalInvocationID.x] = gl_GlobalInvocationID.x;\n"
      "  if (gl_LocalInvocationID.x == 0) gl_TaskCountNV = 32;\n}\n",
      Stage::task);
  ASSERT_TRUE(r.ours.ok()) << r.ours.errors().front().to_string();
  EXPECT_TRUE(r.ours->outputs.empty()) << "\"location " << r.ours->outputs.front().location << "\"";
  EXPECT_EQ(locations_of(r.spirv_cross, "outputs"), locations_of(r.ours->outputs));
}

// ---- The layout rules over those reflections ----

shadergen::ReflectionInfo with_outputs(std::vector<shadergen::VariableInfo> outputs, std::uint32_t push = 0) {
  shadergen::ReflectionInfo info;
  info.outputs = std::move(outputs);
  info.push_constant_size = push;
  return info;
}

TEST(SharedLayoutRules, OnlyFragmentOutputsAreAttachments) {
  auto a = with_outputs({{0, 4, "colour"}}), b = with_outputs({{0, 4, "colour"}, {1, 2, "uv"}});
  std::vector<shadergen::LabelledReflection> mesh = {{"raw 0", Stage::mesh, true, &a},
                                                     {"raw 1", Stage::mesh, true, &b}};
  EXPECT_TRUE(shadergen::merge_layouts(mesh).ok()) << "mesh outputs are the program interface's business";
  std::vector<shadergen::LabelledReflection> fragment = {{"raw 0", Stage::fragment, true, &a},
                                                         {"raw 1", Stage::fragment, true, &b}};
  auto merged = shadergen::merge_layouts(fragment);
  ASSERT_FALSE(merged.ok());
  EXPECT_EQ(merged.errors().front().message,
            "permutations disagree on their outputs: raw 0 writes location 0 vec4, raw 1 writes location 0 vec4, "
            "location 1 vec2 (the spec's \"layout\" is \"shared\"; \"layout\": \"per_permutation\" gives each "
            "permutation a layout of its own)");
}

// The program form's vertex half follows the uber-shader's rule: its permutations agree on the
// push-constant size; the two stages may differ, and the range covers the larger.
TEST(SharedLayoutRules, OnePushConstantRuleForEveryPermutedStage) {
  auto f16 = with_outputs({}, 16), v64 = with_outputs({}, 64), v32 = with_outputs({}, 32);
  std::vector<shadergen::LabelledReflection> agreeing = {{"raw 0", Stage::fragment, true, &f16},
                                                         {"raw 0 vertex", Stage::vertex, true, &v64},
                                                         {"raw 1 vertex", Stage::vertex, true, &v64}};
  auto merged = shadergen::merge_layouts(agreeing);
  ASSERT_TRUE(merged.ok());
  ASSERT_EQ(merged->push_constants.size(), 1u);
  EXPECT_EQ(merged->push_constants[0].size, 64u);
  EXPECT_EQ(merged->push_constants[0].stages, 0x11u);
  std::vector<shadergen::LabelledReflection> disagreeing = {{"raw 0 vertex", Stage::vertex, true, &v64},
                                                            {"raw 1 vertex", Stage::vertex, true, &v32}};
  auto refused = shadergen::merge_layouts(disagreeing);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.errors().front().message,
            "permutations disagree on the push-constant block: raw 0 vertex has 64 bytes, raw 1 vertex has 32 "
            "(the spec's \"layout\" is \"shared\"; \"layout\": \"per_permutation\" gives each permutation a layout "
            "of its own)");
}

TEST(StageInference, FromTheLastExtensionOrTheOneBeforeGlsl) {
  const std::vector<std::pair<std::string, std::optional<Stage>>> cases = {
      {"shade.frag", Stage::fragment},     {"shade.frag.glsl", Stage::fragment},
      {"cull.task.glsl", Stage::task},     {"cull.mesh.glsl", Stage::mesh},
      {"a.b.vert.glsl", Stage::vertex},    {"shade.glsl", std::nullopt},
      {"shade.common.glsl", std::nullopt}, {"glsl", std::nullopt},
      {"dir.frag/x.glsl", std::nullopt},   {"hit.rchit.glsl", Stage::closest_hit}};
  for (const auto& [file, stage] : cases) EXPECT_EQ(shadergen::stage_for_extension(file), stage) << file;
}

}  // namespace
