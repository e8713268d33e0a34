// z reconstruction and the z pyramid (see depth.hpp).
#include "ssfx/ao/depth.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <utility>

#include "src/ao/ao_simd.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::ao {

double zToDepth(double z, const Camera& c) {
    // Inverse of z = c0 / (d c1 + c2): d = (c0 / z - c2) / c1, in double.
    if (std::isinf(c.zFar)) return std::isinf(z) ? 1.0 : (c.zNear / z - 1.0) / -1.0;
    return (c.zNear * c.zFar / z - c.zFar) / (c.zNear - c.zFar);
}

ImageF depthToZ(ImageView<const float> depth, const Camera& camera, const Exec& exec) {
    projection(camera, depth.width(), depth.height());  // validates before allocating
    ImageF z(depth.width(), depth.height());
    depthToZ(depth, camera, z.view(), exec);
    return z;
}

void depthToZ(ImageView<const float> depth, const Camera& camera, ImageView<float> z, const Exec& exec) {
    const Projection p = projection(camera, depth.width(), depth.height());
    if (z.width() != depth.width() || z.height() != depth.height())
        throw Error(fmt::format("depthToZ: the z buffer is {}x{}, the depth {}x{}", z.width(), z.height(),
                                depth.width(), depth.height()));
    // The first bad pixel in row-major order is reported, whatever the thread count.
    std::atomic<std::int64_t> firstBad{std::int64_t{1} << 62};
    parallelRows(depth.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* d = depth.row(y);
            float* out = z.row(y);
            // The vector row (same bits); a row with a bad value takes the loop below.
            if (detail::depthToZRowSimd(d, out, depth.width(), p.c0, p.c1, p.c2)) continue;
            for (int x = 0; x < depth.width(); ++x) {
                const float v = d[x];
                if (!(v >= 0.0f && v <= 1.0f)) {  // also NaN
                    std::int64_t idx = std::int64_t(y) * depth.width() + x, cur = firstBad.load();
                    while (idx < cur && !firstBad.compare_exchange_weak(cur, idx)) {
                    }
                    out[x] = 0;
                    continue;
                }
                // Eq. 2. d = 1 is the cleared depth, nothing drawn: sky (z = -inf) for
                // any far plane, as the released SAO shader's depth test skips it (with a
                // finite far plane eq. 2 would put a wall at zFar there).
                out[x] = v == 1.0f ? -HUGE_VALF : float(p.c0 / (double(v) * p.c1 + p.c2));
            }
        }
    });
    if (firstBad.load() != std::int64_t{1} << 62) {
        const std::int64_t i = firstBad.load();
        const int x = int(i % depth.width()), y = int(i / depth.width());
        throw Error(fmt::format("depth at pixel ({}, {}) is {}, not in [0, 1]", x, y, depth(x, y)));
    }
}

std::vector<ImageF> zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter, const Exec& exec) {
    std::vector<ImageF> levels;
    zPyramid(z, maxMip, filter, levels, exec);
    return levels;
}

void zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter, std::vector<ImageF>& levels,
              const Exec& exec) {
    if (maxMip < 0 || maxMip > 16) throw Error(fmt::format("z pyramid: maxMip {} is not in [0, 16]", maxMip));
    levels.resize(std::size_t(maxMip) + 1);
    auto ensure = [](ImageF& img, int w, int h) {
        if (img.width() != w || img.height() != h) img = ImageF(w, h);
    };
    ensure(levels[0], z.width(), z.height());
    for (int y = 0; y < z.height(); ++y) std::copy(z.row(y), z.row(y) + z.width(), levels[0].view().row(y));
    for (int m = 1; m <= maxMip; ++m) {
        const ImageF& prev = levels[std::size_t(m) - 1];
        ensure(levels[std::size_t(m)], std::max(1, prev.width() / 2), std::max(1, prev.height() / 2));
        zPyramidLevel(prev.view(), levels[std::size_t(m)].view(), filter, exec);
    }
}

void zPyramid(ImageView<const float> z, int maxMip, PyramidFilter filter, ZPyramid& out, const Exec& exec) {
    if (maxMip < 0 || maxMip > 16) throw Error(fmt::format("z pyramid: maxMip {} is not in [0, 16]", maxMip));
    checkDimensions(z.width(), z.height(), "z buffer");
    out.shape(z.width(), z.height(), maxMip);
    const ImageView<float> l0 = out.level(0);
    parallelRows(z.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) std::copy(z.row(y), z.row(y) + z.width(), l0.row(y));
    });
    for (int m = 1; m <= maxMip; ++m) zPyramidLevel(std::as_const(out).level(m - 1), out.level(m), filter, exec);
}

void zPyramidLevel(ImageView<const float> pv, ImageView<float> next, PyramidFilter filter, const Exec& exec) {
    const int w = next.width(), h = next.height();
    if (w != std::max(1, pv.width() / 2) || h != std::max(1, pv.height() / 2))
        throw Error(fmt::format("z pyramid: a {}x{} level cannot follow a {}x{} one", w, h, pv.width(), pv.height()));
    parallelRows(h, exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                float v;
                if (filter == PyramidFilter::RotatedGrid) {
                    v = pv.clamped(2 * x + (y & 1), 2 * y + (x & 1));
                } else {
                    const float a = pv.clamped(2 * x, 2 * y), b = pv.clamped(2 * x + 1, 2 * y);
                    const float c = pv.clamped(2 * x, 2 * y + 1), d = pv.clamped(2 * x + 1, 2 * y + 1);
                    switch (filter) {
                        case PyramidFilter::Mean: v = (a + b + c + d) * 0.25f; break;
                        case PyramidFilter::HarmonicMean: v = 4.0f / (1.0f / a + 1.0f / b + 1.0f / c + 1.0f / d); break;
                        case PyramidFilter::Min: v = std::min(std::min(a, b), std::min(c, d)); break;
                        default: v = std::max(std::max(a, b), std::max(c, d)); break;
                    }
                }
                next(x, y) = v;
            }
    });
}

}  // namespace ssfx::ao
