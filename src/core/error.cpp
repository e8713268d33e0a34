#include "ssfx/core/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ssfx {

int wholeNumber(double v, const std::string& what, double lo, double hi) {
    if (std::isfinite(v) && v == std::floor(v) && v >= lo && v <= hi) return int(v);
    const bool ranged = lo != -2147483648.0 || hi != 2147483647.0;
    throw Error(ranged ? fmt::format("{} = {} is not an integer in [{}, {}]", what, v, lo, hi)
                       : fmt::format("{} = {} is not an integer", what, v));
}

void assertFailed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "ssfx internal error: assertion '%s' failed at %s:%d\n", expr, file, line);
    std::abort();
}

}  // namespace ssfx
