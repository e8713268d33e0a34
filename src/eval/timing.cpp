#include "ssfx/eval/timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <numeric>

#include "ssfx/core/error.hpp"

namespace ssfx::eval {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double trimmedMean(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t q = v.size() / 4;
    return std::accumulate(v.begin() + long(q), v.end() - long(q), 0.0) / double(v.size() - 2 * q);
}

std::vector<TimingResult> timeInterleaved(const std::vector<TimedMethod>& methods, int repetitions, int warmup,
                                          const std::string& baseline, const std::function<void(int, int)>& progress) {
    if (repetitions < 1) throw Error(fmt::format("timing: repetitions = {} must be at least 1", repetitions));
    std::vector<TimingResult> results(methods.size());
    for (std::size_t i = 0; i < methods.size(); ++i) results[i].id = methods[i].id;
    using Clock = std::chrono::steady_clock;
    for (int round = 0; round < warmup + repetitions; ++round) {
        for (std::size_t i = 0; i < methods.size(); ++i) {
            const auto t0 = Clock::now();
            methods[i].run();
            const auto t1 = Clock::now();
            if (round >= warmup)
                results[i].samplesMs.push_back(methods[i].measuredMs
                                                   ? methods[i].measuredMs()
                                                   : std::chrono::duration<double, std::milli>(t1 - t0).count());
        }
        if (progress) progress(round + 1, warmup + repetitions);
    }
    double base = 0;
    for (auto& r : results) {
        r.medianMs = median(r.samplesMs);
        r.trimmedMeanMs = trimmedMean(r.samplesMs);
        if (r.id == baseline) base = r.trimmedMeanMs;
    }
    if (base <= 0) throw Error(fmt::format("timing: baseline '{}' was not timed", baseline));
    for (auto& r : results) r.relative = r.trimmedMeanMs / base * 100.0;
    return results;
}

}  // namespace ssfx::eval
