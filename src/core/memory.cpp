#include "ssfx/core/memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ssfx {

void tuneAllocatorForImages() {
#if defined(__GLIBC__)
    // 32 MiB is glibc's upper bound for the mmap threshold on 64-bit (a 4K RGBA8 frame is
    // 33 MiB and stays mmapped); below it, freed blocks are reused without page faults.
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
#endif
}

}  // namespace ssfx
