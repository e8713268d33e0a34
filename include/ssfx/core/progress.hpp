// How far a long job has got (frame sequences, evaluations, ray tracing), for a caller that
// shows it. The library only reports; drawing a progress line is the caller's business (the
// ssfx tool draws one on a terminal, apps/ssfx/console.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

namespace ssfx {

//! One report: the step `what` ("temporal", "ao: rendering sponza") has done `done` of `total`
//! `unit`s. total == 0: the count is not known ahead (a raw stream); done == total == 0: the
//! step has just begun.
struct Progress {
    std::string_view what;
    std::int64_t done = 0;
    std::int64_t total = 0;
    std::string_view unit = {};
};

//! Called from any thread, possibly from several at once: must be cheap and thread-safe.
using ProgressFn = std::function<void(const Progress&)>;

}  // namespace ssfx
