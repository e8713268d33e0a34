// The renderer's camera: view and projection matrices composed in double precision on
// the host and cast to float once (McGuire et al., "Scalable Ambient Obscurance", HPG
// 2012, section 2.1: float error in a composed matrix shows up as depth error), with a
// finite or infinite far plane and an optional guard band.
//
// Clip space is Vulkan's: depth d = z_clip / w_clip in [0, 1] with d = 0 at the near
// plane, and y_ndc = -1 at the top row of the image (y down, as the AO code's pixels).
// For camera-space z < 0 (the camera looks down -z), d is exactly the inverse of the SAO
// spec's reconstruction z(d) = c0 / (d c1 + c2) (sao.md pass 1).
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "ssfx/core/camera.hpp"
#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

struct CameraSetup {
    int width = 0, height = 0;   //!< the image without guard band
    int guard = 0;               //!< pixels added on every side of the rendered buffer
    glm::dmat4 view{1.0};        //!< world -> camera space
    glm::dmat4 projection{1.0};  //!< camera -> Vulkan clip space, for the whole buffer
    Camera camera;               //!< z planes (negative) and the *whole buffer's* vertical fov

    int bufferWidth() const { return width + 2 * guard; }
    int bufferHeight() const { return height + 2 * guard; }
    //! projection * view, composed in double and rounded to float once.
    glm::mat4 viewProjectionF() const;
};

//! Right-handed look-at (camera looks down -z, +y up). Throws ssfx::Error for a zero
//! direction or an up vector parallel to it.
glm::dmat4 lookAt(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);

//! Symmetric perspective into Vulkan clip space with y down; zNear > 0, zFar > zNear or infinity.
glm::dmat4 perspective(double fovY, double aspect, double zNear, double zFar);

//! The camera of `view` for a width x height image with a guard band of `guard` pixels: the
//! buffer is (width + 2 guard) x (height + 2 guard) and its field of view is widened so the
//! inner image is exactly what the view shows without a guard band. Throws ssfx::Error for
//! a bad size, fov, near/far or guard.
CameraSetup cameraSetup(const View& view, int width, int height, int guard = 0);

//! camera.json beside a depth buffer: the AO camera keys (fov_y_deg, z_near, z_far; read by
//! io::readCameraJson) plus width, height, guard and the projection and view matrices
//! (row-major, as written).
std::string cameraSetupJson(const CameraSetup& setup);

}  // namespace ssfx::scene
