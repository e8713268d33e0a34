// The adaptive supersampling paper's Table 1 on our scenes (adaptive_ss.md "Evaluation to
// reproduce"): for m = 1 (plain and + fxaa3d), 2, 3, 4 the time per frame (G-buffer on the
// Vulkan device, shading on the CPU, total), the shading time with a stall that makes
// shading dominate, MSE and PSNR against brute-force supersampling at the same m, and the percentage of
// samples shaded; plus the images of the paper's figures (sample-count heat map, absolute
// error, the metrics' separate contributions). Built in the ssfx_deferred library (it
// needs the renderer).
#pragma once

#include <functional>
#include <string>

#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/deferred/adaptive.hpp"
#include "ssfx/eval/section.hpp"

namespace ssfx::eval {

struct DeferredExperimentOptions {
    std::string outDir;  //!< images/ and data/deferred.{json,md} are written here
    std::string scene = "atrium", view = "nave";
    int width = 1024, height = 768;
    int stall = 400;      //!< the stalled columns' ShadingParams::stall
    int repetitions = 3;  //!< timed runs per row (median)
    bool quick = false;   //!< 256x192, one repetition (tests)
    deferred::AdaptiveParams params;
    std::string device;  //!< Vulkan device
    Exec exec;
    ProgressFn progress;
};

//! Runs the experiment, writes its outputs and returns its section (paths relative to
//! outDir); data/deferred.md is markdown() of it.
Section runDeferredExperiment(const DeferredExperimentOptions& options);

}  // namespace ssfx::eval
