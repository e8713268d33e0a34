// See camera.hpp.
#include "ssfx/core/camera.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ssfx/core/error.hpp"

namespace ssfx {

Projection projection(const Camera& c, int width, int height) {
    if (!(c.zNear < 0) || !std::isfinite(c.zNear))
        throw Error(fmt::format("camera: zNear must be a finite negative number (got {})", c.zNear));
    if (!(c.zFar < c.zNear)) throw Error(fmt::format("camera: zFar ({}) must be below zNear ({})", c.zFar, c.zNear));
    if (!(c.fovY > 0 && c.fovY < std::numbers::pi))
        throw Error(fmt::format("camera: fovY must be in (0, pi) radians (got {})", c.fovY));
    if (width < 1 || height < 1) throw Error(fmt::format("camera: buffer size {}x{} is empty", width, height));
    Projection p{};
    // Paper eq. 2: c = (zn zf, zn - zf, zf) for a finite far plane, (zn, -1, +1) for an
    // infinite one; in double (section 2.1: compose the projection in double precision).
    if (std::isinf(c.zFar)) {
        p.c0 = c.zNear, p.c1 = -1.0, p.c2 = 1.0;
    } else {
        p.c0 = c.zNear * c.zFar, p.c1 = c.zNear - c.zFar, p.c2 = c.zFar;
    }
    const double t = std::tan(c.fovY / 2);
    p.p11 = float(1.0 / t);
    p.p00 = float(1.0 / (t * double(width) / double(height)));
    p.width = width, p.height = height;
    p.pixelsPerMeter = float(double(height) / (2.0 * t));
    return p;
}

double quantizeDepth(double d, DepthFormat f) {
    d = std::clamp(d, 0.0, 1.0);
    switch (f) {
        case DepthFormat::D16: return std::nearbyint(d * 65535.0) / 65535.0;
        case DepthFormat::D24: return std::nearbyint(d * 16777215.0) / 16777215.0;
        default: return double(float(d));
    }
}

}  // namespace ssfx
