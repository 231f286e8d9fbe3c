// Exact reflection, one case per descriptor kind and per special shape: each case compiles a
// small shader of its own (through shadergen's own preprocess/compile/optimise path) and
// asserts the one binding it declares, so a kind that goes missing or comes out wrong fails
// here by name. Also runtime-sized and specialization-sized arrays, input attachment indices,
// specialization constants and a work-group size given by local_size_x_id.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "compile/glsl_compiler.h"
#include "compile/reflection.h"
#include "compile/spirv_passes.h"
#include "test_helpers.h"

namespace {

using shadergen::DescriptorKind;
using shadergen::Stage;

// Compiles `body` (a whole shader) as `stage` for Vulkan 1.2 and reflects the optimised blob.
shadergen::ReflectionInfo compile_and_reflect(const std::string& body, Stage stage,
                                              shadergen::TargetEnv env = shadergen::TargetEnv::vulkan1_2) {
  sgtest::TempDir dir("reflect");
  sgtest::write_file(dir / "shader.glsl", body);
  shadergen::GlslSource source{dir / "shader.glsl", stage, {}, {}, {}, env};
  auto words = shadergen::compile(source);
  EXPECT_TRUE(words.ok()) << (words.ok() ? "" : words.errors().front().to_string());
  if (!words.ok()) return {};
  auto optimised = shadergen::optimise_and_validate(std::move(words).value(), env);
  EXPECT_TRUE(optimised.ok()) << (optimised.ok() ? "" : optimised.errors().front().to_string());
  if (!optimised.ok()) return {};
  auto info = shadergen::reflect(optimised->words, stage);
  EXPECT_TRUE(info.ok()) << (info.ok() ? "" : info.errors().front().to_string());
  return info.ok() ? *info : shadergen::ReflectionInfo{};
}

struct KindCase {
  const char* name;
  std::string declaration;  // at file scope
  std::string use;          // an expression of type vec4 that keeps the binding alive
  DescriptorKind kind;
  std::uint32_t count;
  bool runtime_sized;
  std::string resource_name = "r";  // a block is named by its type
  std::size_t bindings = 1;         // in the whole shader
};

void PrintTo(const KindCase& c, std::ostream* os) { *os << c.name; }

#define kSampler "\nlayout(set = 0, binding = 0) uniform sampler s;"

class ReflectionKind : public ::testing::TestWithParam<KindCase> {};

TEST_P(ReflectionKind, TheOneBindingHasItsKindAndCount) {
  const KindCase& c = GetParam();
  std::string shader = "#version 460\n#extension GL_EXT_nonuniform_qualifier : require\n" + c.declaration +
                       "\nlayout(location = 0) flat in int index;\nlayout(location = 0) out vec4 colour;\n"
                       "void main() { colour = " +
                       c.use + "; }\n";
  shadergen::ReflectionInfo info = compile_and_reflect(shader, Stage::fragment);
  auto found = std::find_if(info.bindings.begin(), info.bindings.end(),
                            [](const shadergen::BindingInfo& b) { return b.set == 1 && b.binding == 3; });
  ASSERT_NE(found, info.bindings.end()) << "set 1, binding 3 is missing from the reflection of\n" << shader;
  EXPECT_EQ(info.bindings.size(), c.bindings) << shader;
  const shadergen::BindingInfo& b = *found;
  EXPECT_EQ(b.kind, c.kind);
  EXPECT_EQ(b.count, c.count);
  EXPECT_EQ(b.runtime_sized, c.runtime_sized);
  EXPECT_EQ(b.stages, static_cast<std::uint32_t>(Stage::fragment));
  EXPECT_EQ(b.name, c.resource_name);
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, ReflectionKind,
    ::testing::Values(
        KindCase{"sampler",
                 "layout(set = 1, binding = 3) uniform sampler r;\nlayout(set = 0, binding = 0) uniform texture2D t;",
                 "texture(sampler2D(t, r), vec2(0.5))", DescriptorKind::sampler, 1, false, "r", 2},
        KindCase{"combined_image_sampler", "layout(set = 1, binding = 3) uniform sampler2D r;", "texture(r, vec2(0.5))",
                 DescriptorKind::combined_image_sampler, 1, false},
        KindCase{"sampled_image", "layout(set = 1, binding = 3) uniform texture2D r;" kSampler,
                 "texelFetch(sampler2D(r, s), ivec2(0), 0)", DescriptorKind::sampled_image, 1, false, "r", 2},
        KindCase{"storage_image", "layout(set = 1, binding = 3, rgba8) uniform readonly image2D r;",
                 "imageLoad(r, ivec2(0))", DescriptorKind::storage_image, 1, false},
        KindCase{"uniform_texel_buffer", "layout(set = 1, binding = 3) uniform textureBuffer r;", "texelFetch(r, 0)",
                 DescriptorKind::uniform_texel_buffer, 1, false},
        KindCase{"storage_texel_buffer", "layout(set = 1, binding = 3, rgba32f) uniform readonly imageBuffer r;",
                 "imageLoad(r, 0)", DescriptorKind::storage_texel_buffer, 1, false},
        KindCase{"uniform_buffer", "layout(set = 1, binding = 3) uniform U { vec4 v; } r;", "r.v",
                 DescriptorKind::uniform_buffer, 1, false, "U"},
        KindCase{"storage_buffer", "layout(set = 1, binding = 3) readonly buffer S { vec4 v[]; } r;", "r.v[index]",
                 DescriptorKind::storage_buffer, 1, false, "S"},
        KindCase{"fixed_array", "layout(set = 1, binding = 3) uniform texture2D r[6];" kSampler,
                 "texelFetch(sampler2D(r[index], s), ivec2(0), 0)", DescriptorKind::sampled_image, 6, false, "r", 2},
        KindCase{"bindless_runtime_array", "layout(set = 1, binding = 3) uniform texture2D r[];" kSampler,
                 "texelFetch(sampler2D(r[nonuniformEXT(index)], s), ivec2(0), 0)", DescriptorKind::sampled_image, 0,
                 true, "r", 2},
        KindCase{
            "specialization_sized_array",
            "layout(constant_id = 9) const int N = 5;\nlayout(set = 1, binding = 3) uniform texture2D r[N];" kSampler,
            "texelFetch(sampler2D(r[index], s), ivec2(0), 0)", DescriptorKind::sampled_image, 5, false, "r", 2}),
    [](const ::testing::TestParamInfo<KindCase>& p) { return std::string(p.param.name); });

TEST(ReflectionExact, InputAttachmentsCarryTheirIndex) {
  shadergen::ReflectionInfo info = compile_and_reflect(
      "#version 450\nlayout(input_attachment_index = 0, set = 0, binding = 4) uniform subpassInput albedo;\n"
      "layout(input_attachment_index = 2, set = 0, binding = 5) uniform subpassInputMS depth;\n"
      "layout(location = 0) out vec4 colour;\n"
      "void main() { colour = subpassLoad(albedo) * subpassLoad(depth, 1).r; }\n",
      Stage::fragment);
  ASSERT_EQ(info.bindings.size(), 2u);
  EXPECT_EQ(info.bindings[0].kind, DescriptorKind::input_attachment);
  EXPECT_EQ(info.bindings[0].binding, 4u);
  EXPECT_EQ(info.bindings[0].input_attachment_index, 0u);
  EXPECT_EQ(info.bindings[0].name, "albedo");
  EXPECT_EQ(info.bindings[1].kind, DescriptorKind::input_attachment);
  EXPECT_EQ(info.bindings[1].input_attachment_index, 2u);
}

TEST(ReflectionExact, AccelerationStructuresAreTheirOwnKind) {
  shadergen::ReflectionInfo info = compile_and_reflect(
      "#version 460\n#extension GL_EXT_ray_tracing : require\n"
      "layout(set = 0, binding = 0) uniform accelerationStructureEXT scene;\n"
      "layout(set = 0, binding = 1, rgba8) uniform writeonly image2D target;\n"
      "layout(location = 0) rayPayloadEXT vec4 payload;\n"
      "void main() {\n  traceRayEXT(scene, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, vec3(0), 0.0, vec3(0, 0, 1), 100.0, "
      "0);\n"
      "  imageStore(target, ivec2(gl_LaunchIDEXT.xy), payload);\n}\n",
      Stage::ray_generation);
  ASSERT_EQ(info.bindings.size(), 2u);
  EXPECT_EQ(info.bindings[0].kind, DescriptorKind::acceleration_structure);
  EXPECT_EQ(info.bindings[0].stages, static_cast<std::uint32_t>(Stage::ray_generation));
  EXPECT_EQ(info.bindings[1].kind, DescriptorKind::storage_image);
}

TEST(ReflectionExact, SpecializationConstantsAreListedWithTypeAndDefault) {
  shadergen::ReflectionInfo info = compile_and_reflect(
      "#version 450\nlayout(constant_id = 3) const float EXPOSURE = 1.5;\n"
      "layout(constant_id = 1) const bool TONEMAP = true;\nlayout(constant_id = 2) const int BIAS = -4;\n"
      "layout(constant_id = 7) const uint SAMPLES = 16u;\nlayout(location = 0) out vec4 colour;\n"
      "void main() { colour = vec4(EXPOSURE * float(BIAS) * float(SAMPLES), TONEMAP ? 1.0 : 0.0, 0, 1); }\n",
      Stage::fragment);
  ASSERT_EQ(info.specialization_constants.size(), 4u);
  const auto& c = info.specialization_constants;
  float exposure = 1.5f;
  std::uint32_t exposure_bits = 0;
  std::memcpy(&exposure_bits, &exposure, 4);
  EXPECT_EQ(c[0], (shadergen::SpecConstantInfo{1, "TONEMAP", shadergen::ScalarType::boolean, 1}));
  EXPECT_EQ(c[1],
            (shadergen::SpecConstantInfo{2, "BIAS", shadergen::ScalarType::int32, static_cast<std::uint32_t>(-4)}));
  EXPECT_EQ(c[2], (shadergen::SpecConstantInfo{3, "EXPOSURE", shadergen::ScalarType::float32, exposure_bits}));
  EXPECT_EQ(c[3], (shadergen::SpecConstantInfo{7, "SAMPLES", shadergen::ScalarType::uint32, 16}));
}

// local_size_x_id: the size reports the default the SPIR-V holds (glslang gives the axis 1,
// the unspecialised size) and local_size_ids the constant's ID, on every target (SPIR-V 1.6
// has its own execution mode for it); the constant is listed once.
TEST(ReflectionExact, WorkGroupSizeFromASpecializationConstant) {
  const std::string shader =
      "#version 450\nlayout(local_size_x_id = 5, local_size_y = 2) in;\nlayout(constant_id = 6) const uint "
      "TAPS = 8u;\nlayout(set = 0, binding = 0) buffer B { float v[]; } b;\n"
      "void main() { b.v[gl_GlobalInvocationID.x] *= float(TAPS); }\n";
  for (auto env : {shadergen::TargetEnv::vulkan1_0, shadergen::TargetEnv::vulkan1_2, shadergen::TargetEnv::vulkan1_3}) {
    SCOPED_TRACE(std::string(shadergen::target_env_name(env)));
    shadergen::ReflectionInfo info = compile_and_reflect(shader, Stage::compute, env);
    EXPECT_EQ(info.local_size, (std::array<std::uint32_t, 3>{1, 2, 1}));
    EXPECT_EQ(info.local_size_ids[0], 5u);
    EXPECT_EQ(info.local_size_ids[1], shadergen::Reflection::kNoConstant);
    EXPECT_EQ(info.local_size_ids[2], shadergen::Reflection::kNoConstant);
    ASSERT_EQ(info.specialization_constants.size(), 2u);
    EXPECT_EQ(info.specialization_constants[0], (shadergen::SpecConstantInfo{5, "", shadergen::ScalarType::uint32, 1}));
    EXPECT_EQ(info.specialization_constants[1],
              (shadergen::SpecConstantInfo{6, "TAPS", shadergen::ScalarType::uint32, 8}));
  }
}

}  // namespace
