// The whole frame on one device as a report section (docs/frame.md): a camera path through a scene
// rendered by gpu::FrameRenderer (render, adaptive shading with AO, anti-aliasing), its
// per-pass profile as a table and a stacked-bar chart (one bar per frame), and the animation.
// Needs a build with the GPU backend (ssfx_gpu_deferred); the report adds it when it can.
#pragma once

#include <string>
#include <vector>

#include "ssfx/core/progress.hpp"
#include "ssfx/eval/section.hpp"
#include "ssfx/gpu/frame.hpp"

namespace ssfx::eval {

struct FrameExperimentOptions {
    std::string outDir;  //!< anim/frame.png (APNG), plots/frame_profile.png, data/frame.{json,md}
    std::string scene = "atrium";
    int width = 640, height = 360;
    int m = 4;  //!< supersampling
    int frames = 24;
    //! The scene's named views the camera passes through (a CameraPath with them as keyframes,
    //! one second apart); empty: the built-in orbit (ssfx frame without --view and --path),
    //! which leaves an interior scene like the atrium.
    std::vector<std::string> tour = {"nave", "colonnade", "curtain", "stairs"};
    std::string ao = "sao", aa = "ddaa2";
    int aoGuardBand = 32;
    std::string device;  //!< Vulkan device (ssfx devices)
    bool quick = false;  //!< 160x90, 4 frames (tests)
    ProgressFn progress;
};

//! The pass times of several frames (ssfx frame --profile, the report's section): per pass
//! its time in each frame and its median, per frame the sum of its passes.
struct FrameProfile {
    std::vector<std::string> passes;      //!< in the frame's order
    std::vector<std::vector<double>> ms;  //!< [pass][frame]
    std::vector<double> medians;          //!< per pass
    std::vector<double> totals;           //!< per frame
    double frameMedian = 0;
    //! A pass's median as a share (0..1) of the median frame.
    double share(std::size_t pass) const { return frameMedian > 0 ? medians[pass] / frameMedian : 0.0; }
};
//! Throws ssfx::Error for no frames or frames whose passes differ.
FrameProfile frameProfile(const std::vector<gpu::FrameResult>& frames);

//! Renders the orbit (after one untimed warm-up frame), writes the outputs and returns the
//! section (paths relative to outDir). Throws ssfx::Error where there is no Vulkan device.
Section runFrameExperiment(const FrameExperimentOptions& options);

}  // namespace ssfx::eval
