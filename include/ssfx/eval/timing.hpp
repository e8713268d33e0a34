// Timing protocol of the DDAA paper (section 3.4): run each method many times, drop the
// fastest and slowest quarter, report the mean of the rest and every method relative to
// blur (= 100), all measured in the same run with the methods interleaved so that slow
// drifts of the machine affect all of them alike.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace ssfx::eval {

struct TimedMethod {
    std::string id;
    std::function<void()> run;  //!< one complete application of the method
    //! When set, a repetition's time is what this returns after run() (e.g. the GPU
    //! timestamps of the pass), instead of run()'s wall-clock time.
    std::function<double()> measuredMs;
};

struct TimingResult {
    std::string id;
    std::vector<double> samplesMs;  //!< every repetition, in run order
    double medianMs = 0;
    double trimmedMeanMs = 0;  //!< mean after dropping the fastest and slowest quarter
    double relative = 0;       //!< trimmedMean / baseline's trimmedMean * 100
};

//! Runs warmup + repetitions rounds; each round runs every method once, in order.
//! `baseline` names the method that is 100 (must be in `methods`). `progress`, when set,
//! is called after each round with (round, rounds).
std::vector<TimingResult> timeInterleaved(const std::vector<TimedMethod>& methods, int repetitions, int warmup,
                                          const std::string& baseline,
                                          const std::function<void(int, int)>& progress = {});

double median(std::vector<double> v);
double trimmedMean(std::vector<double> v);  //!< drops floor(n/4) from each end

}  // namespace ssfx::eval
