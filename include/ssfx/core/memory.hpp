// Process-wide allocator tuning for applications that process large images repeatedly.
#pragma once

namespace ssfx {

//! Keeps freed image-sized blocks in the heap instead of returning them to the OS, so a
//! loop that allocates an image per call does not page-fault it in every time (glibc:
//! raises M_MMAP_THRESHOLD to its maximum and disables trimming). Process-global, so the
//! library never calls it itself; the ssfx tool and the benchmarks do. No-op elsewhere.
void tuneAllocatorForImages();

}  // namespace ssfx
