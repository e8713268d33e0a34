// Row-block parallelism on oneTBB.
//
// Work is split into fixed blocks of kRowBlock rows, never by thread count, so every
// block computes the same bytes whatever the number of threads (STYLE.md section 4).
#pragma once

#include <functional>

namespace ssfx {

//! Execution settings. Never changes the bytes an effect produces.
struct Exec {
    int threads = 0;  //!< worker threads; 0 = all hardware threads, 1 = run inline
};

inline constexpr int kRowBlock = 16;

//! Calls fn(y0, y1) for consecutive row ranges [y0, y1) covering [0, height), in parallel:
//! blocks of rowsPerBlock rows (the last one shorter).
void parallelRows(int height, const Exec& exec, const std::function<void(int, int)>& fn, int rowsPerBlock = kRowBlock);

//! Number of threads Exec resolves to on this machine.
int resolvedThreads(const Exec& exec);

}  // namespace ssfx
