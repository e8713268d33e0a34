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

//! Items through three stages with at most `inFlight` items alive at once (bounded memory;
//! the caller keeps them, e.g. in `inFlight` slots indexed by i % inFlight):
//! produce(i) for i = 0, 1, ... in order on one thread at a time, until it returns false;
//! work(i) on several items in parallel; consume(i) in order on one thread at a time. An
//! exception from any stage stops the pipeline and is rethrown. One from work(i) is
//! rethrown when item i's turn to be consumed comes, so that exactly the items before it
//! have been consumed, for any thread count and timing (a sequence with a bad frame k
//! writes frames 0..k-1). A producer that wants the items before it finished first
//! returns false and reports its error afterwards.
void orderedPipeline(int inFlight, const Exec& exec, const std::function<bool(int)>& produce,
                     const std::function<void(int)>& work, const std::function<void(int)>& consume);

}  // namespace ssfx
