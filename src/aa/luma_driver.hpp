// Driver shared by fxaa3d, ddaa1 and ddaa2: luma plane, early exit (spec section 1), then
// the method's kernel for the pixels that pass it.
//
// The reference path evaluates everything one pixel at a time with the scalar kernel. The
// fast path works in bands of rows: it computes the band's luma rows, for each row the
// luma-plane rows the method's searches reach that this thread does not hold yet (a ring
// per thread, luma_planes.hpp), and the early-exit mask with Highway (same float operations
// per lane, so the same bits), lets the method's vector kernel write the 16-pixel chunks
// that hold edge pixels, copies the runs of unchanged pixels and gives the few remaining
// edge pixels (image borders) to the scalar kernel; bands in parallel.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "src/aa/luma_planes.hpp"
#include "src/aa/ppaa_common.hpp"

namespace ssfx::aa::detail {

//! Luma plane rows from `first` on: one band and one row either side (fast path), or the
//! whole plane (first = 0, scalar path). row(y) clamps y to the image, as the 3x3
//! neighbourhood does.
struct LumaRows {
    const float* data = nullptr;
    int width = 0, height = 0, first = 0;
    //! Fast path, sRGB texture: the same rows' texels decoded (kSrgb8), three channel rows
    //! (r, g, b) per image row, each `width` floats with one float of clamped padding either
    //! side (decodedStride() apart); null otherwise.
    const float* decoded = nullptr;
    int count = 0;  //!< the rows held: first .. first + count - 1
    int clampRow(int y) const { return y < 0 ? 0 : (y >= height ? height - 1 : y); }
    const float* row(int y) const { return data + std::size_t(clampRow(y) - first) * std::size_t(width); }
    std::size_t decodedStride() const { return std::size_t(width) + 2; }
    //! The decoded rows (DecodedBand's layout; empty unless sRGB), also for the luma planes.
    DecodedBand decodedBand() const { return {decoded, first, decoded != nullptr ? count : 0}; }
    //! Channel c (0 r, 1 g, 2 b) of image row y, clamped; [-1] and [width] are the padding.
    const float* decodedRow(int y, int c) const {
        return decodedBand().row(clampRow(y), width) + std::size_t(c) * decodedStride();
    }
};

//! Luma rows [y0 - 1, y1 + 1) of `in` (clamped; SIMD, same bits as the reference plane)
//! in a buffer kept per calling thread, valid until its next call (in early_exit.cpp).
//! `format`: the texels as the texture reads them (sRGB: the decoded values' luma, and the
//! decoded texels themselves in LumaRows::decoded, for the vector kernels' reads).
LumaRows bandLumaRows(ImageView<const Rgba8> in, int y0, int y1, TextureFormat format = TextureFormat::Unorm);

//! exitMask[x] = 1 where pixel (x, y) is below the edge threshold (SIMD, in early_exit.cpp).
void earlyExitRow(const LumaRows& L, int y, float thresholdMin, float threshold, std::uint8_t* exitMask);

inline Luma3x3 neighbourhood(const LumaRows& L, int x, int y) {
    const int w = L.width;
    const int xm = x > 0 ? x - 1 : 0, xp = x + 1 < w ? x + 1 : w - 1;
    const float* ra = L.row(y - 1);
    const float* rc = L.row(y);
    const float* rb = L.row(y + 1);
    return {rc[x], rc[xm], rc[xp], ra[x], rb[x], ra[xm], rb[xm], ra[xp], rb[xp]};
}

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

//! The luma planes a method's vector kernel reads (luma_planes.hpp): none, or the pair
//! planes (and the quad plane) of the rows its searches reach, at most `reach` rows away.
struct PlaneNeeds {
    bool planes = false, quad = false;
    int reach = 0;
};

//! Rows per band of the fast path: its luma rows stay in cache between being computed and
//! being read, and bands are small enough to share out evenly. Measured on the 2-core EPYC
//! VM at 1080p: frame-sized planes 17.3 ms (fxaa3d) / 18.2 ms (ddaa2) on one thread, the
//! same work in 60-120-row bands 11-14 ms; on 2 threads 48-row bands beat 96 (fxaa3d 6.0
//! vs 6.15 ms, ddaa2 6.05 vs 6.3 ms: finer load balance) and 32 (more halo rows). Since
//! the planes moved to per-thread rings (a thread's next band reuses the rows it reaches),
//! 24 and 48 tie and 96 is still slower (fxaa3d 5.9 / 5.9 / 6.2 ms).
inline constexpr int kBandRows = 48;

//! No vector row kernel: every edge pixel goes through the scalar kernel.
struct NoRowKernel {
    void operator()(int, const LumaRows&, const LumaPlanes&, std::uint8_t*, const Rgba8*, Rgba8*) const {}
};

//! Scalar path (the reference, or a colour-aware measure, chromaWeight > 0): the luma plane
//! pixel by pixel, then every pixel through the scalar kernel `pixel`. Fast path: per band of kBandRows
//! rows, in parallel, the band's luma rows, then per row the plane rows `needs` asks for
//! and the early-exit mask; `rowKernel(y, L, planes, mask, src, dst)` may write pixels of row y
//! itself (a vector kernel across pixels) and sets their mask bytes to kWritten; the
//! driver copies kExit runs and runs `pixel` on the kEdge pixels. An sRGB texture takes the
//! fast path with its decoded luma rows and planes (the row kernels read either encoding).
template <class PixelFn, class RowKernel = NoRowKernel>
void runLumaMethod(ImageView<const Rgba8> in, ImageView<Rgba8> out, bool scalar, float chromaWeight,
                   TextureFormat format, float thresholdMin, float threshold, const Exec& exec, const PlaneNeeds& needs,
                   const PixelFn& pixel, const RowKernel& rowKernel = {}) {
    const int w = in.width();
    if (scalar) {
        const ImageF plane = lumaPlaneReference(in, chromaWeight, format);
        const LumaRows L{plane.data(), w, in.height(), 0};
        parallelRows(in.height(), exec, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y) {
                const Rgba8* src = in.row(y);
                Rgba8* dst = out.row(y);
                for (int x = 0; x < w; ++x) {
                    const Luma3x3 n = neighbourhood(L, x, y);
                    float range;
                    dst[x] = belowEdgeThreshold(n, thresholdMin, threshold, &range)
                                 ? src[x]
                                 : toRgba8(pixel(x, y, n, range), src[x].a, format);
                }
            }
        });
        return;
    }
    const std::uint64_t call = needs.planes ? newPlaneCall() : 0;
    parallelRows(
        in.height(), exec,
        [&](int y0, int y1) {
            const LumaRows L = bandLumaRows(in, y0, y1, format);
            std::vector<std::uint8_t> mask(static_cast<std::size_t>(w));
            for (int y = y0; y < y1; ++y) {
                const LumaPlanes planes =
                    needs.planes ? planeRowsFor(in, call, y, needs.reach, needs.quad, format, L.decodedBand())
                                 : LumaPlanes{};
                const Rgba8* src = in.row(y);
                Rgba8* dst = out.row(y);
                std::uint8_t* m = mask.data();
                earlyExitRow(L, y, thresholdMin, threshold, m);
                rowKernel(y, L, planes, m, src, dst);
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
                            dst[i] = toRgba8(pixel(i, y, n, range), src[i].a, format);
                        }
                    }
                    x = end;
                }
            }
        },
        kBandRows);
}

}  // namespace ssfx::aa::detail
