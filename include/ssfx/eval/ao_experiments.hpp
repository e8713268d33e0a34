// The SAO paper's experiments (spec sao.md "Experiments to reproduce"), on the analytic
// scenes of scene/analytic.hpp and, for the accuracy table, on scenes rendered by the Vulkan
// renderer (supplied by the caller, which links it):
//   Figure 3  z precision: camera-space z error vs distance for D16 / D24 / D32F depth,
//             each with a finite and an infinite far plane;
//   Figure 4  normal precision: angle between reconstructed (quad-pair) and true face
//             normals, within faces;
//   Table 1   z pyramid filters: AO images and x4 difference images, with their error
//             against the ray-traced truth;
//   Figure 5  AO sample-pass time vs world-space radius (AlchemyAO, SAO without and with
//             the pyramid);
//   Table 3   per-pass times at 1280x720 ... 2560x1600 with the paper's guard bands;
//   accuracy  SAO and AlchemyAO against the ray-traced ground truth (MSE, PSNR);
//   methods   AlchemyAO, SAO (paper, released) and GTAO (low..ultra, ideal, paper) against
//             two truths (obscurance, binary visibility) at R = 0.5, 1, 2 m: PSNR, MAE, the
//             images and signed error images in a viewer per scene, a generated verdict.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/raytraced.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/eval/section.hpp"

namespace ssfx::eval {

//! A depth buffer made elsewhere (the Vulkan scene renderer) with the geometry behind it
//! (camera space), for the accuracy table. `depth` includes the guard band.
struct AoRenderedScene {
    std::string name;
    ImageF depth;
    Camera camera;
    std::shared_ptr<const ao::RayScene> geometry;
};
//! Called with the accuracy experiment's image size and guard band.
using AoSceneSource = std::function<std::vector<AoRenderedScene>(int width, int height, int guard)>;

struct AoExperimentOptions {
    std::string outDir;  //!< images/, plots/, data/ are written here
    bool quick = false;  //!< small sizes and few repetitions (tests)
    Exec exec;
    ProgressFn progress;
    AoSceneSource renderedScenes;  //!< optional: real scenes joining the accuracy table
    //! "cpu" (default) or "vulkan": also run SAO and AlchemyAO as the GPU passes
    //! (ssfx/gpu/ao.hpp) on `device`: their accuracy beside the CPU's, the radius sweep and the
    //! per-pass table from GPU timestamps. Needs a build with the GPU backend.
    std::string backend = "cpu";
    std::string device;
    //! Only the speed experiments (Figure 5, Table 3 and, with vulkan, their GPU forms).
    bool speedOnly = false;
};

//! Runs every experiment, writes the images, plots and data/ao.json, data/ao.md, and
//! returns the section (tables, figures; paths relative to outDir). data/ao.md is
//! markdown() of it.
Section runAoExperiments(const AoExperimentOptions& options);

//! Figure 3 alone: the largest |z error| (mm) at each distance, per series
//! ("D16 finite", "D16 infinite", ...), near plane 0.1 m, finite far plane 1000 m.
struct ZPrecision {
    std::vector<double> distances;  //!< m
    std::vector<std::string> series;
    std::vector<std::vector<double>> errorMm;  //!< [series][distance]
};
ZPrecision zPrecisionExperiment();

}  // namespace ssfx::eval
