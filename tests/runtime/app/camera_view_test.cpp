// Cameras placed anywhere: a glTF file's own camera (--camera gltf:N) inside an atrium, and
// --eye/--target views of the procedural scene and of a file. Each frame is classified ==
// naive per pixel under the validation layer, with the clip planes, shadow map and distances
// fitted to the view (tilelight/scene/view_fit.h, tilelight/app/camera_choice.h).
#include "frame_support.h"
#include "tilelight/app/camera_choice.h"
#include "tilelight/app/usage_error.h"
#include "tilelight/gltf/load_gltf.h"
#include "tilelight_testing/test_support.h"

#include "tilelight_testing/raw_bit_masks.h"

#include <split_second_shaders.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>

namespace tilelight::test {
namespace {

namespace fs = std::filesystem;
namespace bit = tilelight::raw_bit_masks;
const fs::path kFixtures = TILELIGHT_GLTF_FIXTURES;

constexpr double kYfov = 0.9;  // radians: about 51.6 degrees
constexpr float kZnear = 0.05f;

// An open-topped room built from the fixture box: a floor, three walls (none behind the
// camera), a pillar; cameras[0] stands inside looking at the far wall, pitched down 10
// degrees; cameras[1] is orthographic and cameras[2] is placed by no node.
fs::path write_atrium(const fs::path& folder) {
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kFixtures / "box.gltf"));
  const auto box = [](std::array<double, 3> at, std::array<double, 3> size) {
    return nlohmann::json{{"mesh", 0}, {"translation", at}, {"scale", size}};
  };
  const double s = std::sin(-5.0 * 3.14159265358979 / 180.0), c = std::cos(-5.0 * 3.14159265358979 / 180.0);
  gltf["nodes"] = nlohmann::json::array({
      box({0, -0.1, 0}, {10, 0.2, 10}),  // floor
      box({-5, 2, 0}, {0.2, 4, 10}),
      box({5, 2, 0}, {0.2, 4, 10}),
      box({0, 2, -5}, {10, 4, 0.2}),  // walls
      box({0, 1, -2}, {1, 2, 1}),     // pillar
      {{"camera", 0}, {"translation", {0.0, 1.6, 3.0}}, {"rotation", {s, 0.0, 0.0, c}}},
      {{"camera", 1}, {"translation", {0.0, 8.0, 0.0}}},
  });
  gltf["scenes"] = nlohmann::json::array({{{"nodes", {0, 1, 2, 3, 4, 5, 6}}}});
  gltf["cameras"] = nlohmann::json::array({
      {{"type", "perspective"},
       {"name", "inside"},
       {"perspective", {{"yfov", kYfov}, {"znear", kZnear}, {"zfar", 100.0}}}},
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 5.0}, {"ymag", 5.0}, {"znear", 0.1}, {"zfar", 20.0}}}},
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
  });
  fs::path file = folder / "atrium.gltf";
  std::ofstream(file) << gltf.dump();
  return file;
}

struct View {
  std::uint32_t tiles = 0, sky = 0, solid_shadow = 0, sun_light = 0, faded = 0;
};

// Renders `scene` from `camera` (its pose, or the named one) at 256x192 and checks classified ==
// naive; returns the tile counts of the properties the tests look at.
View render_and_compare(const Context& context, const Scene& scene, const app::ChosenCamera& camera) {
  RendererOptions options;
  options.width = 256;
  options.height = 192;
  options.camera = camera.name;
  options.camera_pose = camera.placed;
  TileRenderer renderer(context, scene, options);
  const FrameResult frame = renderer.render_frame();
  const FrameComparison classified = compare(renderer.read_classified(), renderer.read_naive(), kEquivalenceTolerance);
  EXPECT_EQ(classified.magenta_pixels, 0u) << "tiles left undrawn";
  EXPECT_EQ(classified.pixels_over_tolerance, 0u)
      << classified.first_difference << " (max difference " << classified.max_abs_difference << ")";
  EXPECT_EQ(std::accumulate(frame.stats.class_tiles.begin(), frame.stats.class_tiles.end(), 0u),
            renderer.grid().tile_count());
  View v;
  for (std::uint8_t id : renderer.raw_tile_ids()) {
    ++v.tiles;
    v.sky += (id & bit::SKY) != 0 ? 1 : 0;
    v.solid_shadow += (id & bit::SHADOW_SOLID) != 0 ? 1 : 0;
    v.sun_light += (id & bit::SUN_LIGHT) != 0 ? 1 : 0;
    v.faded += (id & bit::SHADOW_FADE) != 0 ? 1 : 0;
  }
  return v;
}

app::ChosenCamera choose(Scene& scene, const app::CameraRequest& request) {
  return app::choose_camera(request, scene, 256.0f / 192.0f);
}

class CameraViews : public VulkanTest {};

TEST_F(CameraViews, TheFilesCameraIsPlacedByItsNodeWithItsProjectionAndSeesTheInterior) {
  Scene scene = load_gltf_scene(write_atrium(scratch_dir()));
  ASSERT_EQ(scene.camera_names(), (std::vector<std::string>{"default", "gltf:0", "gltf:1", "gltf:2"}));
  EXPECT_NE(scene.camera("gltf:1").unusable.find("orthographic"), std::string::npos) << scene.camera("gltf:1").unusable;
  EXPECT_NE(scene.camera("gltf:2").unusable.find("no node references it"), std::string::npos);

  const app::ChosenCamera file = choose(scene, {.camera = "gltf:0"});
  ASSERT_TRUE(file.placed);
  EXPECT_EQ(file.name, "gltf:0");
  // Placed by nodes[5] in the file's coordinates, looking down its -z pitched 10 degrees down.
  EXPECT_NEAR(file.pose.eye[0], 0.0, 1e-4);
  EXPECT_NEAR(file.pose.eye[1], 1.6, 1e-4);
  EXPECT_NEAR(file.pose.eye[2], 3.0, 1e-4);
  const glm::vec3 forward = glm::normalize(file.placed->target - file.placed->position);
  EXPECT_NEAR(forward.y, -std::sin(glm::radians(10.0f)), 1e-4f);
  EXPECT_NEAR(forward.z, -std::cos(glm::radians(10.0f)), 1e-4f);
  EXPECT_NEAR(file.pose.fov_deg, kYfov * 180.0 / 3.14159265358979, 1e-3);
  const float scale = glm::length(glm::vec3(scene.world_from_file[0]));
  EXPECT_NEAR(file.placed->near_plane, kZnear * scale, 1e-5f);
  // The shadow map covers what the camera sees, not the whole room.
  EXPECT_LT(scene.sun.shadow_half_extent, 10.0f);

  const View inside = render_and_compare(context(), scene, file);
  EXPECT_LT(inside.sky * 20, inside.tiles) << "the walls fill the view: under 5 % sky";
  EXPECT_GT(inside.solid_shadow, 0u) << "the walls and the pillar shade the floor";
  EXPECT_GT(inside.sun_light, 0u);
  EXPECT_EQ(inside.faded, 0u) << "shadows fade beyond the room, measured from the eye";

  Scene outside_scene = load_gltf_scene(write_atrium(scratch_dir()));  // the same file, written again
  const View outside = render_and_compare(context(), outside_scene, choose(outside_scene, {}));
  EXPECT_GT(outside.sky, inside.sky * 4) << "the default view from outside shows far more sky";
}

TEST_F(CameraViews, FileCamerasThatCannotBeDrawnAreUsageErrors) {
  Scene scene = load_gltf_scene(write_atrium(scratch_dir()));
  for (const char* name : {"gltf:1", "gltf:2", "gltf:3", "street"}) {
    EXPECT_THROW((void)choose(scene, {.camera = name, .scene_file = "atrium.gltf"}), app::UsageError) << name;
  }
}

struct EyeCase {
  const char* name;
  bool file;  // the atrium, else the procedural scene
  app::CameraRequest request;
};

void PrintTo(const EyeCase& c, std::ostream* os) { *os << c.name; }

std::string eye_case_name(const ::testing::TestParamInfo<EyeCase>& info) { return info.param.name; }

class EyeViews : public VulkanTest, public ::testing::WithParamInterface<EyeCase> {};

TEST_P(EyeViews, ClassifiedEqualsNaiveAndThePoseIsReportedAsGiven) {
  const EyeCase& c = GetParam();
  Scene scene = c.file ? load_gltf_scene(write_atrium(scratch_dir())) : make_demo_scene();
  const app::ChosenCamera eye = choose(scene, c.request);
  ASSERT_TRUE(eye.placed);
  EXPECT_EQ(eye.name, "eye");
  const glm::vec3 given = *app::parse_xyz(c.request.eye);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(eye.pose.eye[static_cast<std::size_t>(i)], given[i], 1e-3) << i;
  EXPECT_NEAR(eye.pose.fov_deg, c.request.fov_deg.value_or(60.0), 1e-4);
  // The clip planes hold the whole scene in front of the eye, and the near plane is close.
  EXPECT_LT(eye.placed->near_plane, 0.5f);
  const View v = render_and_compare(context(), scene, eye);
  EXPECT_GT(v.sun_light, 0u);
  EXPECT_GT(v.solid_shadow, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Views, EyeViews,
    ::testing::Values(
        // Down the procedural street at eye height, as the street camera stands.
        EyeCase{"procedural_street", false, {.eye = "3.5,1.7,-9", .target = "3.5,-8.9,-59"}},
        EyeCase{"procedural_low_wide", false, {.eye = "-30,1.8,5", .target = "10,3,-60", .fov_deg = 80.0}},
        // Inside the atrium, from a corner towards the pillar, in the file's coordinates.
        EyeCase{"atrium_corner", true, {.eye = "-4,1.5,4", .target = "0,1,-2", .up = "0,1,0", .fov_deg = 70.0}}),
    eye_case_name);

}  // namespace
}  // namespace tilelight::test
