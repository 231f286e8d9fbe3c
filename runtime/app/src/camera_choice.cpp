#include "tilelight/app/camera_choice.h"

#include "tilelight/app/usage_error.h"
#include "tilelight/scene/view_fit.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace tilelight::app {
namespace {

glm::vec3 to_world(const Scene& scene, glm::vec3 p) { return glm::vec3(scene.world_from_file * glm::vec4(p, 1.0f)); }

std::array<double, 3> array_of(glm::vec3 v) { return {v.x, v.y, v.z}; }

CameraPose pose_of(const Scene& scene, const Camera& camera) {
  const glm::mat4 file_from_world = glm::inverse(scene.world_from_file);
  CameraPose pose;
  pose.eye = array_of(glm::vec3(file_from_world * glm::vec4(camera.position, 1.0f)));
  pose.target = array_of(glm::vec3(file_from_world * glm::vec4(camera.target, 1.0f)));
  pose.up = array_of(camera.up);
  pose.fov_deg = camera.vertical_fov_degrees;
  return pose;
}

// --eye/--target/--up/--fov, in the scene's own coordinates, as a camera in the renderer's.
Camera placed_camera(const CameraRequest& a, const Scene& scene) {
  const glm::vec3 eye = *parse_xyz(a.eye);  // the flags' checks ran at parse time
  const glm::vec3 target = *parse_xyz(a.target);
  const glm::vec3 up = a.up.empty() ? glm::vec3(0, 1, 0) : *parse_xyz(a.up);
  const glm::vec3 view = target - eye;
  if (!(glm::length(view) > 0.0f)) {
    throw UsageError("--target",
                     fmt::format("--target {}: the same point as --eye: the camera has no direction", a.target));
  }
  if (!(glm::length(glm::cross(glm::normalize(view), up)) > 1e-4f)) {
    throw UsageError("--up", fmt::format("--up {}: parallel to the view from --eye to --target; choose another up",
                                         a.up.empty() ? "0,1,0" : a.up));
  }
  Camera camera;
  camera.name = "eye";
  camera.description = "placed with --eye and --target";
  camera.position = to_world(scene, eye);
  camera.target = to_world(scene, target);
  camera.up = glm::normalize(up);
  camera.vertical_fov_degrees = static_cast<float>(a.fov_deg.value_or(60.0));
  return camera;
}

// The distances the flags set, in the renderer's units (a --scene file is scaled).
LightingDistances chosen_distances(const CameraRequest& a, const Scene& scene) {
  const double scale = glm::length(glm::vec3(glm::column(scene.world_from_file, 0)));
  const auto scaled = [scale](std::optional<double> v) -> std::optional<float> {
    if (!v) return std::nullopt;
    return static_cast<float>(*v * scale);
  };
  return {scaled(a.shadow_fade_start), scaled(a.shadow_fade_length), scaled(a.scattering_start)};
}

void refuse_procedural_name(const CameraRequest& a) {
  // "default" names the file's own default view too.
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = make_demo_scene().camera_names();
    all.erase(std::remove(all.begin(), all.end(), "default"), all.end());
    return all;
  }();
  if (std::find(names.begin(), names.end(), a.camera) == names.end()) return;
  throw UsageError("--camera",
                   fmt::format("--camera {}: the cameras {} belong to the procedural scene, not to --scene {}; place "
                               "one with --eye X,Y,Z --target X,Y,Z, or choose the file's own with --camera gltf:N "
                               "(--list-cameras)",
                               a.camera, fmt::join(names, ", "), a.scene_file));
}

const Camera& named_camera(const CameraRequest& a, const Scene& scene) {
  for (const Camera& c : scene.cameras) {
    if (c.name != a.camera) continue;
    if (!c.unusable.empty()) throw UsageError("--camera", fmt::format("--camera {}: {}", a.camera, c.unusable));
    return c;
  }
  const auto file_cameras = static_cast<std::size_t>(std::count_if(
      scene.cameras.begin(), scene.cameras.end(), [](const Camera& c) { return c.name.starts_with("gltf:"); }));
  if (a.camera.starts_with("gltf:") && !scene.source.empty()) {
    throw UsageError("--camera", file_cameras == 0
                                     ? fmt::format("--camera {}: {} has no cameras", a.camera, scene.source)
                                     : fmt::format("--camera {}: {} has {} camera(s), gltf:0 to gltf:{}", a.camera,
                                                   scene.source, file_cameras, file_cameras - 1));
  }
  throw UsageError("--camera", fmt::format("--camera {}: unknown camera (known: {}; --list-cameras)", a.camera,
                                           fmt::join(scene.camera_names(), ", ")));
}

// "X,Y,Z": three finite numbers; anything else is a usage error naming the flag and the value.
CLI::Validator xyz() {
  return CLI::Validator(
      [](std::string& input) {
        return parse_xyz(input) ? std::string() : input + " is not X,Y,Z (three finite numbers, comma-separated)";
      },
      "");  // the flag's type name says X,Y,Z
}

CLI::Validator vertical_fov() {
  return CLI::Validator(
      [](std::string& input) {
        char* end = nullptr;
        const double degrees = std::strtod(input.c_str(), &end);
        if (end == input.c_str() || *end != '\0' || !(degrees > 0.0 && degrees < 180.0)) {
          return input + " is not a vertical field of view (degrees, more than 0 and less than 180)";
        }
        return std::string();
      },
      "");
}

}  // namespace

void add_camera_options(CLI::App& cli, CameraRequest& a) {
  CLI::Option* eye = cli.add_option("--eye", a.eye,
                                    "place the camera at X,Y,Z (in the --scene file's own coordinates), looking at "
                                    "--target; overrides --camera. report.json's camera is then 'eye'")
                         ->check(xyz())
                         ->type_name("X,Y,Z");
  CLI::Option* target =
      cli.add_option("--target", a.target, "the point X,Y,Z a --eye camera looks at")->check(xyz())->type_name("X,Y,Z");
  eye->needs(target);
  target->needs(eye);
  cli.add_option("--up", a.up, "the --eye camera's up direction (default 0,1,0)")
      ->check(xyz())
      ->type_name("X,Y,Z")
      ->needs(eye);
  cli.add_option("--fov", a.fov_deg, "the --eye camera's vertical field of view in degrees (default 60)")
      ->check(vertical_fov())
      ->type_name("DEGREES")
      ->needs(eye);
  cli.add_option("--sun-direction", a.sun_direction, "the direction X,Y,Z towards the sun (default: the scene's)")
      ->check(xyz())
      ->check(CLI::Validator(
          [](std::string& input) {
            const auto v = parse_xyz(input);
            return v && glm::length(*v) > 0.0f ? std::string() : input + " has no direction (all zero)";
          },
          ""))
      ->type_name("X,Y,Z");
  cli.add_option("--shadow-fade-start", a.shadow_fade_start,
                 "view depth from the eye where sun shadows begin to fade out (scene units; default: 55 for the "
                 "procedural scene, the far side of a --scene file as the camera sees it)")
      ->check(CLI::NonNegativeNumber);
  cli.add_option("--shadow-fade-length", a.shadow_fade_length,
                 "depth over which the shadows fade (default: 30, or a quarter of a --scene file's diagonal)")
      ->check(CLI::PositiveNumber);
  cli.add_option("--scattering-start", a.scattering_start,
                 "view depth from the eye where light scattering (fog) begins (default: 75, or a --scene file's far "
                 "side as the camera sees it)")
      ->check(CLI::NonNegativeNumber);
}

std::optional<glm::vec3> parse_xyz(const std::string& text) {
  glm::vec3 v{};
  const char* at = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    const float value = std::strtof(at, &end);
    if (end == at || !std::isfinite(value)) return std::nullopt;
    v[i] = value;
    if (i < 2 && *end != ',') return std::nullopt;
    at = end + (i < 2 ? 1 : 0);
  }
  if (*at != '\0') return std::nullopt;
  return v;
}

ChosenCamera choose_camera(const CameraRequest& a, Scene& scene, float aspect) {
  const bool loaded = !scene.source.empty();
  if (!a.sun_direction.empty()) scene.sun.sun_direction = glm::normalize(*parse_xyz(a.sun_direction));
  if (a.eye.empty() && loaded) refuse_procedural_name(a);
  Camera camera = a.eye.empty() ? named_camera(a, scene) : placed_camera(a, scene);
  LightingDistances distances = chosen_distances(a, scene);
  if (!loaded) {
    // The procedural scene keeps its own distances (its field is larger than any view of it).
    distances.shadow_fade_start = distances.shadow_fade_start.value_or(scene.sun.shadow_fade_start);
    distances.shadow_fade_length = distances.shadow_fade_length.value_or(scene.sun.shadow_fade_length);
    distances.scattering_start = distances.scattering_start.value_or(scene.sun.scattering_start);
  }
  const WorldBox box = world_box(scene);
  fit_lighting_distances(scene.sun, camera, box, distances);
  ChosenCamera chosen{camera.name, std::nullopt, {}};
  // A named procedural camera is drawn as it always was: its planes and shadow map are hand-set.
  if (loaded || !a.eye.empty()) {
    // A file camera keeps its own znear and zfar (gltf_cameras.h).
    if (!camera.name.starts_with("gltf:")) fit_clip_planes(camera, box);
    fit_shadow_map(scene.sun, camera, box, aspect);
    chosen.placed = camera;
  }
  chosen.pose = pose_of(scene, camera);
  return chosen;
}

}  // namespace tilelight::app
