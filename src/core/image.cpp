#include "ssfx/core/image.hpp"

#include <fmt/format.h>

namespace ssfx {

void checkDimensions(std::int64_t width, std::int64_t height, const std::string& what) {
    if (width <= 0 || height <= 0)
        throw Error(fmt::format("{}: invalid size {}x{} (width and height must be at least 1)", what, width, height));
    if (width > kMaxDimension || height > kMaxDimension || width * height > kMaxPixels)
        throw Error(fmt::format("{}: size {}x{} exceeds the limit ({} pixels per side, {} pixels in all)", what, width,
                                height, kMaxDimension, kMaxPixels));
}

}  // namespace ssfx
