// Fuzzes the still-PNG reader: any bytes must decode or throw ssfx::Error, nothing else.
#include <cstddef>
#include <cstdint>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto img = ssfx::io::decodePng({data, size}, "fuzz");
        if (img.width() <= 0 || img.height() <= 0) __builtin_trap();
    } catch (const ssfx::Error&) {
    }
    return 0;
}
