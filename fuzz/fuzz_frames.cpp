// Fuzzes the frame-sequence parsers of `ssfx aa` (io/sequence.hpp): a numbered pattern on the
// input's first line, a --frames range on the rest. Either gives a value that keeps its
// promises or throws ssfx::Error.
#include <cstddef>
#include <cstdint>
#include <string>

#include "ssfx/core/error.hpp"
#include "ssfx/io/sequence.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::size_t newline = text.find('\n');
    const std::string pattern = text.substr(0, newline),
                      range = newline == std::string::npos ? "" : text.substr(newline + 1);
    try {
        const ssfx::io::FramePattern p(pattern);
        if (!ssfx::io::FramePattern::isPattern(pattern)) __builtin_trap();  // a pattern holds a conversion
        for (int n : {0, 1, 9, 10, 12345, 999999999}) {
            const std::string path = p.path(n);
            const std::size_t slash = path.rfind('/');
            // Every frame's file name reads back as its number.
            if (p.frameOf(slash == std::string::npos ? path : path.substr(slash + 1)) != n) __builtin_trap();
        }
    } catch (const ssfx::Error&) {
    }
    if (!ssfx::io::FramePattern::isPattern(pattern) && ssfx::io::FramePattern::plain(pattern).size() > pattern.size())
        __builtin_trap();  // %% only ever shortens
    try {
        const ssfx::io::FrameRange r = ssfx::io::FrameRange::parse(range);
        if (r.first < 0 || r.last < r.first || r.last > 999999999 || r.count() < 1 || r.count() > 1000000000)
            __builtin_trap();
    } catch (const ssfx::Error&) {
    }
    return 0;
}
