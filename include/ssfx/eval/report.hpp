// The HTML report: a self-contained static site (relative paths only, no network at view
// time) with the evaluation's tables, plots, an image comparison viewer and the
// animations. `ssfx eval report --out DIR` and `make demo` write it.
//
//   DIR/index.html                 tables, plots, viewers, method notes
//   DIR/images/NAME*.png           renders (x1..x8), NAME_METHOD.png outputs, NAME_truth.png (x8 resolved)
//   DIR/anim/NAME_METHOD.png       animated outputs (APNG), NAME_truth.png, NAME_input.png
//   DIR/plots/*.png                charts (Cairo)
//   DIR/data/*.json, *.md          every table as data
//   DIR/methods/ID.html            each method's doc (embedded in the binary at build time)
//   DIR/ao/                        the ambient obscurance experiments (images, plots, data)
#pragma once

#include "ssfx/core/progress.hpp"
#include "ssfx/eval/ao_experiments.hpp"

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ssfx/core/parallel.hpp"
#include "ssfx/eval/section.hpp"

namespace ssfx::eval {

struct ReportOptions {
    std::string outDir;
    std::vector<std::string> methods;  //!< empty = the quality table's order
    int speedRepetitions = 20;         //!< per method and image
    //! The DDAA author's data (../shared/reference/ppaa); when it exists the report adds the
    //! reproduction of the paper's rows from the author's outputs and from ours.
    std::string authorDataDir;
    //! Fewer repetitions and every 4th animation frame: for tests of the report itself.
    bool quick = false;
    //! Also run the SAO experiments (eval/ao_experiments.hpp) into DIR/ao/ and show them.
    bool ambientObscurance = true;
    //! Rendered scenes for the AO accuracy table (optional; see ao_experiments.hpp).
    AoSceneSource renderedScenes;
    //! "vulkan": the AO experiments also run the GPU passes (AoExperimentOptions::backend),
    //! their accuracy and GPU timestamps beside the CPU columns, on `aoDevice`.
    std::string aoBackend = "cpu", aoDevice;
    //! Optional: runs the adaptive supersampling experiment into the given folder and returns
    //! its section, paths relative to that folder (it needs the renderer; see
    //! ssfx/eval/deferred_experiment.hpp).
    std::function<Section(const std::string& dir)> deferredExperiment;
    //! Optional: the whole frame on one device (ssfx/eval/frame_experiment.hpp, the GPU
    //! backend's), run into the given folder; its section, paths relative to that folder.
    std::function<Section(const std::string& dir)> frameExperiment;
    //! Optional: writes more render sets (NAME.png, NAMEx2/x4/x8.png; e.g. 3-D scenes from the
    //! Vulkan renderer) into the given folder before the quality table is computed, and
    //! returns their names with a one-line description each.
    std::function<std::vector<std::pair<std::string, std::string>>(const std::string& imagesDir)> addRenderSets;
    Exec exec;
    ProgressFn progress;
};

void writeReport(const ReportOptions& options);

}  // namespace ssfx::eval
