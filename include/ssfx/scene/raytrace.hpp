// A scene's triangles as ray-traceable geometry (Embree 3) in the camera space of a view:
// the geometry behind the ray-traced AO ground truth (ssfx/ao/raytraced.hpp) for real
// scenes, consistent with the renderer's depth buffers of the same view.
#pragma once

#include <memory>

#include "ssfx/ao/raytraced.hpp"
#include "ssfx/scene/camera.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

//! The scene's triangles transformed (in double, stored as float) by the camera's view
//! matrix, in an Embree BVH. Thread-safe for concurrent intersect() calls.
std::unique_ptr<ao::RayScene> cameraSpaceRayScene(const Scene& scene, const CameraSetup& camera);

}  // namespace ssfx::scene
