// The camera of a depth buffer and the depth formats: shared by the AO passes, the depth
// files (io), the renderer and the evaluation (SAO paper section 2.1; spec sao.md).
//
// Conventions: camera space is right-handed and the camera looks down -z, so visible points
// have z < 0; zNear and zFar are negative (zFar = -infinity allowed). Hardware depth d is in
// [0, 1], 0 at the near plane.
#pragma once

#include <cmath>

namespace ssfx {

//! A symmetric perspective camera for the *whole* depth buffer (guard band included).
struct Camera {
    double zNear = -0.1;               //!< m, < 0: the near plane
    double zFar = -INFINITY;           //!< m, < zNear, or -infinity (infinite far plane)
    double fovY = 1.0471975511965976;  //!< rad, (0, pi): vertical field of view (default 60 deg)
};

//! What the passes need from a camera and a buffer size, derived once.
struct Projection {
    double c0, c1, c2;  //!< z(d) = c0 / (d * c1 + c2) (paper eq. 2)
    float p00, p11;     //!< projection matrix P[0][0], P[1][1] (OpenGL convention)
    int width, height;
    float pixelsPerMeter;  //!< S: pixel size of a 1 m object at z = -1 m, h / (2 tan(fovY / 2)) (eq. 5)
};

//! Throws ssfx::Error for a camera that is not as documented or a non-positive size.
Projection projection(const Camera& camera, int width, int height);

//! Depth buffer formats of the precision experiment (paper section 2.1, Figure 3).
enum class DepthFormat {
    D16,   //!< 16-bit unorm: round(d * 65535) / 65535
    D24,   //!< 24-bit unorm: round(d * (2^24 - 1)) / (2^24 - 1)
    D32F,  //!< 32-bit float: d rounded to float32
};
//! The value a depth buffer of `format` stores for the exact depth d, exactly (in double;
//! a float32 view of a 24-bit value would add its own rounding).
double quantizeDepth(double d, DepthFormat format);

}  // namespace ssfx
