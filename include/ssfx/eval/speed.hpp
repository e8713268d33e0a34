// The DDAA paper's speed protocol (its Table 3) on a directory of renders: per image, each
// method is run many times (interleaved with the others, see timing.hpp), the fastest and
// slowest quarter are dropped, and the mean of the rest is reported relative to blur = 100
// from the same run, with absolute medians and the machine.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ssfx/core/parallel.hpp"
#include "ssfx/eval/machine.hpp"
#include "ssfx/eval/timing.hpp"

namespace ssfx::eval {

struct SpeedOptions {
    std::vector<std::string> methods;  //!< empty = the quality table's order; blur is always timed
    std::vector<std::string> images;   //!< empty = findRenderSets(dir)
    int repetitions = 40, warmup = 3;
    Exec exec;
    std::function<void(const std::string&)> progress;
};

struct SpeedTable {
    std::vector<std::string> images, methods;
    std::vector<std::vector<TimingResult>> results;  //!< [image][method]
    MachineInfo machine;
    int repetitions = 0;
};

SpeedTable measureSpeed(const std::string& dir, const SpeedOptions& options);

//! Markdown: relative table (blur = 100) and median table (ms), image rows plus a mean row.
std::string speedMarkdown(const SpeedTable& t);
std::string speedJson(const SpeedTable& t);

}  // namespace ssfx::eval
