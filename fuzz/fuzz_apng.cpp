// Fuzzes the APNG chunk layer and frame composition; re-encodes what decodes.
#include <cstddef>
#include <cstdint>

#include "ssfx/core/error.hpp"
#include "ssfx/io/png.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto anim = ssfx::io::decodeApng({data, size}, "fuzz");
        if (anim.frames.empty()) __builtin_trap();
        if (anim.width() * anim.height() <= 4096) {
            const auto again = ssfx::io::decodeApng(ssfx::io::encodeApng(anim), "again");
            if (again.frames.size() != anim.frames.size()) __builtin_trap();
        }
    } catch (const ssfx::Error&) {
    }
    return 0;
}
