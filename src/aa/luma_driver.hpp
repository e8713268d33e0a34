// Driver shared by fxaa3d, ddaa1 and ddaa2: luma plane, early exit (spec section 1), then
// the method's per-pixel kernel for the pixels that pass it.
//
// The reference path evaluates everything one pixel at a time. The fast path computes the
// luma plane and the early-exit mask with Highway (same float operations per lane, so the
// same bits) and runs the kernel only where the mask says so, in parallel row blocks.
#pragma once

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <vector>

#include "ppaa_common.hpp"

namespace ssfx::aa::detail {

//! The luma plane of `in` for the fast path: computed into a buffer kept per calling thread
//! and reused while the size stays the same (a frame loop then allocates nothing; the
//! buffer is 4 bytes per pixel). The reference path computes a fresh plane pixel by pixel.
const ImageF& scratchLumaPlane(ImageView<const Rgba8> in, const Exec& exec);

//! exitMask[x] = 1 where pixel (x, y) is below the edge threshold (SIMD, in early_exit.cpp).
void earlyExitRow(const ImageF& L, int y, float thresholdMin, float threshold, std::uint8_t* exitMask);

//! No vector row kernel: every edge pixel goes through the scalar kernel.
struct NoRowKernel {
    void operator()(int, const std::uint8_t*, const Rgba8*, Rgba8*, std::uint8_t*) const {}
};

//! `rowKernel(y, exitMask, src, dst, handled)` may write any pixels of row y itself (a
//! vector kernel across pixels) and marks them in `handled`; the rest is done here.
template <class PixelFn, class RowKernel = NoRowKernel>
void runLumaMethod(ImageView<const Rgba8> in, ImageView<Rgba8> out, const ImageF& L, float thresholdMin,
                   float threshold, const Exec& exec, bool reference, const PixelFn& pixel,
                   const RowKernel& rowKernel = {}) {
    parallelRows(in.height(), exec, [&](int y0, int y1) {
        std::vector<std::uint8_t> mask(std::size_t(in.width())), handled(std::size_t(in.width()));
        for (int y = y0; y < y1; ++y) {
            const Rgba8* src = in.row(y);
            Rgba8* dst = out.row(y);
            if (!reference) {
                earlyExitRow(L, y, thresholdMin, threshold, mask.data());
                std::fill(handled.begin(), handled.end(), std::uint8_t{0});
                rowKernel(y, mask.data(), src, dst, handled.data());
                // Copy runs of unchanged pixels at once; run the kernel on the others.
                const std::uint8_t* m = mask.data();
                const std::uint8_t* done = handled.data();
                int x = 0;
                while (x < in.width()) {
                    int end = x;
                    while (end < in.width() && m[end] && !done[end]) ++end;
                    std::memcpy(dst + x, src + x, std::size_t(end - x) * sizeof(Rgba8));
                    for (x = end; x < in.width() && (!m[x] || done[x]); ++x) {
                        if (done[x]) continue;
                        const Luma3x3 n = neighbourhood(L, x, y);
                        float range;
                        belowEdgeThreshold(n, thresholdMin, threshold, &range);
                        dst[x] = toRgba8(pixel(x, y, n, range), src[x].a);
                    }
                }
                continue;
            }
            for (int x = 0; x < in.width(); ++x) {
                const Luma3x3 n = neighbourhood(L, x, y);
                float range;
                if (belowEdgeThreshold(n, thresholdMin, threshold, &range)) {
                    dst[x] = src[x];
                    continue;
                }
                dst[x] = toRgba8(pixel(x, y, n, range), src[x].a);
            }
        }
    });
}

}  // namespace ssfx::aa::detail
