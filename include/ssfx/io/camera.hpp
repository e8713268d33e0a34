// Camera description files (JSON), the companion of a depth buffer:
//   {"fov_y_deg": 60, "z_near": -0.1, "z_far": null}
// fov_y_deg: vertical field of view of the whole buffer (guard band included), degrees;
// z_near, z_far: camera-space planes in metres (negative; z_far null or "-inf" for an
// infinite far plane). The keys `ssfx render` adds for other consumers (width, height,
// guard, projection, view) are accepted and ignored; any other key is rejected, so a typo
// is an error, not a default.
#pragma once

#include <string>

#include "ssfx/ao/depth.hpp"

namespace ssfx::io {

ao::Camera parseCameraJson(const std::string& text, const std::string& name);
ao::Camera readCameraJson(const std::string& path);
std::string cameraJson(const ao::Camera& camera);
void writeCameraJson(const std::string& path, const ao::Camera& camera);

}  // namespace ssfx::io
