// The DDAA paper's speed protocol (its Table 3) on a directory of renders: per image, each
// method is run many times (interleaved with the others, see timing.hpp), the fastest and
// slowest quarter are dropped, and the mean of the rest is reported relative to blur = 100
// from the same run, with absolute medians and the machine.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ssfx/aa/registry.hpp"
#include "ssfx/core/image.hpp"
#include "ssfx/core/parallel.hpp"
#include "ssfx/core/progress.hpp"
#include "ssfx/eval/machine.hpp"
#include "ssfx/eval/timing.hpp"

namespace ssfx::eval {

struct SpeedOptions {
    std::vector<std::string> methods;  //!< empty = the quality table's order; blur is always timed
    std::vector<std::string> images;   //!< empty = findRenderSets(dir)
    int repetitions = 40, warmup = 3;
    Exec exec;
    ProgressFn progress;
};

struct SpeedTable {
    std::vector<std::string> images, methods;
    std::vector<std::vector<TimingResult>> results;  //!< [image][method]
    MachineInfo machine;
    int repetitions = 0;
};

SpeedTable measureSpeed(const std::string& dir, const SpeedOptions& options);

//! The protocol on one image, what measureSpeed runs per image and `ssfx bench` on its
//! input: `ids` (blur added when missing, as the baseline) timed interleaved with their
//! outputs allocated once; `input(scale)` gives the image at scale 1, 2 or 4, each asked for
//! once and only when a method needs it. `rounds(r, n)` reports progress.
std::vector<TimingResult> timeMethodsOn(std::vector<std::string>& ids,
                                        const std::function<ImageRgba8(int scale)>& input, int repetitions, int warmup,
                                        const Exec& exec, const std::function<void(int, int)>& rounds = {});

//! One timed row: a method under its settings, reported as `name` (e.g. "ddaa2:srgb").
struct MethodVariant {
    std::string id, name;
    MethodSettings settings;
};
//! timeMethodsOn for variants, with `baseline` (a variant's name) as 100.
std::vector<TimingResult> timeVariantsOn(const std::vector<MethodVariant>& variants,
                                         const std::function<ImageRgba8(int scale)>& input, int repetitions, int warmup,
                                         const Exec& exec, const std::string& baseline,
                                         const std::function<void(int, int)>& rounds = {});

//! Markdown: relative table (blur = 100) and median table (ms), image rows plus a mean row.
std::string speedMarkdown(const SpeedTable& t);
std::string speedJson(const SpeedTable& t);

}  // namespace ssfx::eval
