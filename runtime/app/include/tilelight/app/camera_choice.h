#pragma once
// Which camera a run draws, and the lighting fitted to it: a procedural camera by name, a
// --scene file's "default" or "gltf:N" camera, or one placed with --eye/--target/--up/--fov.
// A placed camera and every view of a --scene file get clip planes, shadow-fade and
// scattering distances and a shadow map fitted to what they see (tilelight/scene/view_fit.h);
// the procedural scene's named cameras are drawn exactly as they always were. tilelight and
// tilelight_sweep take the same flags (add_camera_options).

#include "tilelight/app/report.h"
#include "tilelight/scene/scene.h"

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace tilelight::app {

// The camera and lighting flags as typed; the flags' validators have checked every X,Y,Z.
struct CameraRequest {
  std::string camera = "default";
  std::string eye{}, target{}, up{};  // "X,Y,Z"; empty: not given
  std::optional<double> fov_deg{};
  std::string sun_direction{};  // towards the sun; empty: the scene's own
  std::optional<double> shadow_fade_start{}, shadow_fade_length{}, scattering_start{};  // scene units
  std::string scene_file{};  // --scene as typed, for messages
};

// --eye, --target, --up, --fov, --sun-direction, --shadow-fade-start, --shadow-fade-length and
// --scattering-start, into `request`.
void add_camera_options(CLI::App& cli, CameraRequest& request);

struct ChosenCamera {
  std::string name;              // report.json's "camera": a procedural name, "gltf:N" or "eye"
  std::optional<Camera> placed;  // RendererOptions::camera_pose; empty: the named procedural camera
  CameraPose pose;               // report.json's "camera_pose"
};

// Chooses the camera and fits `scene`'s sun to it. Throws UsageError (usage_error.h) naming the
// flag where the choice cannot be drawn: a procedural camera's name with a --scene file, an
// unknown or unusable camera, --eye equal to --target, --up along the view. `aspect`: the
// frame's width / height.
ChosenCamera choose_camera(const CameraRequest& request, Scene& scene, float aspect);

// "X,Y,Z" as three finite numbers, or nullopt.
std::optional<glm::vec3> parse_xyz(const std::string& text);

}  // namespace tilelight::app
