#pragma once
// The file's own cameras (glTF "cameras"), as Scene cameras named "gltf:N" after the default
// one. Each is placed by the first node in the file that references it, in the renderer's
// world (Scene::world_from_file), with its perspective projection: yfov, znear and zfar (scaled
// with the scene; no zfar: the far plane fits the scene). aspectRatio is not used: the frame's
// own is. A camera the renderer cannot draw (orthographic, no node places it, a bad yfov or
// znear) is listed with Camera::unusable saying why, so that choosing it is the error, not
// loading the file.

#include "tilelight/scene/scene.h"
#include "tinygltf.h"

namespace tilelight::gltf_detail {

// Appends the model's cameras to scene.cameras. Precondition: fit_scene() has run.
void add_file_cameras(const tinygltf::Model& model, Scene& scene);

}  // namespace tilelight::gltf_detail
