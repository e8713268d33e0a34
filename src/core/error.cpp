#include "ssfx/core/error.hpp"

#include <cstdio>
#include <cstdlib>

namespace ssfx {

void assertFailed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "ssfx internal error: assertion '%s' failed at %s:%d\n", expr, file, line);
    std::abort();
}

}  // namespace ssfx
