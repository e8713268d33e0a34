// Camera paths for animated frames (ssfx frame; docs/frame.md): keyframes of position,
// target and field of view read from JSON and interpolated, or a built-in orbit.
//
// The file:
//   {"keyframes": [{"position": [x, y, z], "target": [x, y, z], "fov": 60, "time": 0}, ...]}
// position and target in the scene's units (world space), fov the vertical field of view in
// degrees (0 < fov < 180); "time" (seconds, strictly increasing) is optional on every keyframe
// or on none (then keyframe i is at time i). At least two keyframes; any other key is an
// error, so that a typo is not a default. The near and far planes and the up vector are the
// scene's first view's.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ssfx/scene/scene.hpp"

namespace ssfx::scene {

struct Keyframe {
    glm::dvec3 position{0.0}, target{0.0, 0.0, -1.0};
    double fovYDeg = 60.0;
    double time = 0;
};

class CameraPath {
public:
    //! Throws ssfx::Error naming the keyframe and the field for fewer than two keyframes, a
    //! value that is not finite, a position equal to its target, a fov outside (0, 180) or
    //! times that do not increase.
    CameraPath(std::vector<Keyframe> keyframes, const View& base);
    //! The view at `time` (clamped to the first and last keyframe's): position and target on
    //! a Catmull-Rom spline through the keyframes (tangents from the neighbours, scaled to
    //! uneven times), fov interpolated linearly.
    View at(double time) const;
    //! `frames` views at evenly spaced times from the first keyframe to the last (frames >= 1;
    //! one frame: the first keyframe).
    std::vector<View> sample(int frames) const;
    const std::vector<Keyframe>& keyframes() const { return keys_; }

private:
    std::vector<Keyframe> keys_;
    View base_;
};

//! Parses a camera path file's text (`name` in the messages); base as for CameraPath.
CameraPath parseCameraPath(std::string_view text, const std::string& name, const View& base);
//! Reads a camera path file (JSON, at most io::kMaxJsonFileBytes).
CameraPath readCameraPath(const std::string& path, const View& base);

//! The built-in orbit: `frames` views around the vertical axis through `base`'s target, at
//! `base`'s distance, height and fov, starting at `base`'s eye and turning a full circle
//! (frame i at 360 i / frames degrees, so that the animation loops).
std::vector<View> orbit(const View& base, int frames);

}  // namespace ssfx::scene
