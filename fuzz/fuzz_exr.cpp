// Fuzzes the EXR reader (our header check, then OpenEXR): any bytes must decode or throw
// ssfx::Error, nothing else, and never allocate what a header merely claims (-rss_limit_mb).
#include <cstddef>
#include <cstdint>

#include "ssfx/core/error.hpp"
#include "ssfx/io/exr.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto img = ssfx::io::decodeExr({data, size}, "fuzz");
        if (img.width() <= 0 || img.height() <= 0) __builtin_trap();
    } catch (const ssfx::Error&) {
    }
    return 0;
}
