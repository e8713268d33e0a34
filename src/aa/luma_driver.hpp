// Driver shared by fxaa3d, ddaa1 and ddaa2: luma plane, early exit (spec section 1), then
// the method's kernel for the pixels that pass it.
//
// The reference path evaluates everything one pixel at a time with the scalar kernel. The
// fast path computes the luma plane and the early-exit mask with Highway (same float
// operations per lane, so the same bits), lets the method's vector kernel write the
// 16-pixel chunks that hold edge pixels, copies the runs of unchanged pixels and gives
// the few remaining edge pixels (image borders) to the scalar kernel; rows in parallel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "ppaa_common.hpp"

namespace ssfx::aa::detail {

//! The luma plane of `in` for the fast path: computed into a buffer kept per calling thread
//! and reused while the size stays the same (a frame loop then allocates nothing; the
//! buffer is 4 bytes per pixel). The reference path computes a fresh plane pixel by pixel.
const ImageF& scratchLumaPlane(ImageView<const Rgba8> in, const Exec& exec);

//! The luma plane a method's run uses: computed pixel by pixel into `fresh` for the
//! reference path, else the SIMD plane in the per-thread scratch buffer. A non-zero
//! chromaWeight (colour-aware contrast) always takes the pixel-by-pixel plane.
inline const ImageF& methodLumaPlane(ImageView<const Rgba8> in, bool reference, const Exec& exec, ImageF& fresh,
                                     float chromaWeight = 0.0f) {
    if (!reference && chromaWeight == 0.0f) return scratchLumaPlane(in, exec);
    fresh = lumaPlaneReference(in, chromaWeight);
    return fresh;
}

//! exitMask[x] = 1 where pixel (x, y) is below the edge threshold (SIMD, in early_exit.cpp).
void earlyExitRow(const ImageF& L, int y, float thresholdMin, float threshold, std::uint8_t* exitMask);

//! Per-pixel states in a row's mask: early exit (copy), needs the scalar kernel, or
//! already written by a vector row kernel.
inline constexpr std::uint8_t kEdge = 0, kExit = 1, kWritten = 2;

//! First index in [x, end) whose byte differs from `value`, scanning 8 bytes at a time.
inline int skipBytes(const std::uint8_t* m, int x, int end, std::uint8_t value) {
    const std::uint64_t pattern = 0x0101010101010101ull * value;
    for (; x + 8 <= end; x += 8) {
        std::uint64_t word;
        std::memcpy(&word, m + x, 8);
        if (word != pattern) break;
    }
    while (x < end && m[x] == value) ++x;
    return x;
}

//! No vector row kernel: every edge pixel goes through the scalar kernel.
struct NoRowKernel {
    void operator()(int, std::uint8_t*, const Rgba8*, Rgba8*) const {}
};

//! `rowKernel(y, mask, src, dst)` may write pixels of row y itself (a vector kernel across
//! pixels) and sets their mask bytes to kWritten; the driver copies kExit runs and runs the
//! scalar `pixel` kernel on the kEdge pixels.
template <class PixelFn, class RowKernel = NoRowKernel>
void runLumaMethod(ImageView<const Rgba8> in, ImageView<Rgba8> out, const ImageF& L, float thresholdMin,
                   float threshold, const Exec& exec, bool reference, const PixelFn& pixel,
                   const RowKernel& rowKernel = {}) {
    const int w = in.width();
    parallelRows(in.height(), exec, [&](int y0, int y1) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(w));
        for (int y = y0; y < y1; ++y) {
            const Rgba8* src = in.row(y);
            Rgba8* dst = out.row(y);
            if (reference) {
                for (int x = 0; x < w; ++x) {
                    const Luma3x3 n = neighbourhood(L, x, y);
                    float range;
                    dst[x] = belowEdgeThreshold(n, thresholdMin, threshold, &range)
                                 ? src[x]
                                 : toRgba8(pixel(x, y, n, range), src[x].a);
                }
                continue;
            }
            std::uint8_t* m = mask.data();
            earlyExitRow(L, y, thresholdMin, threshold, m);
            rowKernel(y, m, src, dst);
            for (int x = 0; x < w;) {
                const std::uint8_t state = m[x];
                const int end = skipBytes(m, x + 1, w, state);
                if (state == kExit) {
                    std::memcpy(dst + x, src + x, std::size_t(end - x) * sizeof(Rgba8));
                } else if (state == kEdge) {
                    for (int i = x; i < end; ++i) {
                        const Luma3x3 n = neighbourhood(L, i, y);
                        float range;
                        belowEdgeThreshold(n, thresholdMin, threshold, &range);
                        dst[i] = toRgba8(pixel(i, y, n, range), src[i].a);
                    }
                }
                x = end;
            }
        }
    });
}

}  // namespace ssfx::aa::detail
