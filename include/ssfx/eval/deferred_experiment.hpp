// The adaptive supersampling paper's Table 1 on our scenes (adaptive_ss.md "Evaluation to
// reproduce"): for m = 1 (plain and + fxaa3d), 2, 3, 4 the time per frame (G-buffer on the
// Vulkan device, shading on the CPU, total), the shading time with a stall that makes
// shading dominate, MSE and PSNR against brute-force supersampling at the same m, and the percentage of
// samples shaded; plus the images of the paper's figures (sample-count heat map, absolute
// error, the metrics' separate contributions). With backend "vulkan" the same rows on the
// GPU passes (gpu/deferred.hpp) from GPU timestamps, with the idle lanes of the rest pass and
// the distance to the CPU's image, in a table of their own. Built in ssfx_eval when the
// renderer is (it renders the G-buffers).
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
    std::string device;  //!< Vulkan device (the G-buffer's and, with backend "vulkan", the shading's)
    //! "cpu" (default) or "vulkan": also the GPU passes (needs a build with the GPU backend);
    //! `lookup` their texture lookups, "model" (default, the CPU's) or "hardware".
    std::string backend = "cpu", lookup = "model";
    Exec exec;
    ProgressFn progress;
};

//! Runs the experiment, writes its outputs and returns its section (paths relative to
//! outDir); data/deferred.md is markdown() of it.
Section runDeferredExperiment(const DeferredExperimentOptions& options);

}  // namespace ssfx::eval
