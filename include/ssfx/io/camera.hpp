// Camera description files (JSON), the companion of a depth buffer:
//   {"fov_y_deg": 60, "z_near": -0.1, "z_far": null}
// fov_y_deg: vertical field of view of the whole buffer (guard band included), degrees;
// z_near, z_far: camera-space planes in metres (negative; z_far null or "-inf" for an
// infinite far plane); all three are required. The keys `ssfx render` adds (width, height,
// guard: the buffer's size, checked against the depth buffer by `ssfx ao`; projection,
// view for other consumers) are accepted; any other key is rejected, so a typo is an
// error, not a default.
#pragma once

#include <string>

#include "ssfx/core/camera.hpp"

namespace ssfx::io {

//! The buffer size a camera file states, when it states one (`ssfx render` writes width,
//! height and guard: the depth buffer is (width + 2 guard) x (height + 2 guard)).
struct CameraBuffer {
    int width = 0, height = 0, guard = 0;
    bool stated = false;
};

Camera parseCameraJson(const std::string& text, const std::string& name, CameraBuffer* buffer = nullptr);
Camera readCameraJson(const std::string& path, CameraBuffer* buffer = nullptr);
std::string cameraJson(const Camera& camera);
void writeCameraJson(const std::string& path, const Camera& camera);

}  // namespace ssfx::io
