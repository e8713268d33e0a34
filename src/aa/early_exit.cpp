// Early-exit mask of a row (spec ppaa.md section 1), vectorised with Highway. Same
// comparisons as belowEdgeThreshold(); max/min and the one multiply are exact per lane.
// Also the fast path's luma rows per band, which the mask reads.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/early_exit.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/luma_driver.hpp"
#include "src/core/srgb_encode-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ExitRow(const float* HWY_RESTRICT above, const float* HWY_RESTRICT row, const float* HWY_RESTRICT below, int w,
             float thresholdMin, float threshold, std::uint8_t* HWY_RESTRICT mask) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::Rebind<std::uint8_t, decltype(df)> d8;
    const int n = int(hn::Lanes(df));
    const auto tMin = hn::Set(df, thresholdMin), t = hn::Set(df, threshold);
    const auto one = hn::Set(di, 1);
    auto scalar = [&](int x) {
        const int xm = x > 0 ? x - 1 : 0, xp = x + 1 < w ? x + 1 : w - 1;
        const Luma3x3 nb{row[x], row[xm], row[xp], above[x], below[x], 0, 0, 0, 0};
        float range;
        mask[x] = belowEdgeThreshold(nb, thresholdMin, threshold, &range);
    };
    scalar(0);
    int x = 1;
    for (; x + n <= w - 1; x += n) {
        const auto c = hn::LoadU(df, row + x);
        const auto lw = hn::LoadU(df, row + x - 1), le = hn::LoadU(df, row + x + 1);
        const auto ls = hn::LoadU(df, above + x), ln = hn::LoadU(df, below + x);
        const auto mx = hn::Max(hn::Max(hn::Max(ls, ln), hn::Max(lw, le)), c);
        const auto mn = hn::Min(hn::Min(hn::Min(ls, ln), hn::Min(lw, le)), c);
        const auto below_ = hn::Lt(hn::Sub(mx, mn), hn::Max(tMin, hn::Mul(mx, t)));
        hn::StoreU(hn::DemoteTo(d8, hn::IfThenElseZero(hn::RebindMask(di, below_), one)), d8, mask + x);
    }
    for (; x < w; ++x) scalar(x);
}

// An sRGB texture's rows for the fast path: each texel decoded once into the channel rows of
// `decoded` (three rows of w + 2 floats per image row, LumaRows' layout: the padding floats
// repeat the edge texels), the luma rows from those values (the same float operations as the
// luma plane's, so the same bits).
void DecodedLumaRows(const Rgba8* HWY_RESTRICT in, std::size_t stride, int w, int rows, float* HWY_RESTRICT decoded,
                     float* HWY_RESTRICT lumas) {
    const hn::ScalableTag<float> df;
    const int n = int(hn::Lanes(df));
    const auto wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    const std::size_t padded = std::size_t(w) + 2;
    for (int y = 0; y < rows; ++y) {
        float* row = decoded + std::size_t(y) * DecodedBand::rowFloats(w);
        ssfx::HWY_NAMESPACE::DecodeSrgbRowPadded(in + std::size_t(y) * stride, w, row);
        const float* r = row + 1;
        const float* g = r + padded;
        const float* b = g + padded;
        float* out = lumas + std::size_t(y) * std::size_t(w);
        int x = 0;
        for (; x + n <= w; x += n) {
            const auto sum = hn::Add(hn::Add(hn::Mul(wr, hn::LoadU(df, r + x)), hn::Mul(wg, hn::LoadU(df, g + x))),
                                     hn::Mul(wb, hn::LoadU(df, b + x)));
            hn::StoreU(hn::Sqrt(sum), df, out + x);
        }
        for (; x < w; ++x) out[x] = luma(r[x], g[x], b[x]);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <algorithm>
#include <vector>

namespace ssfx::aa::detail {

HWY_EXPORT(ExitRow);
HWY_EXPORT(DecodedLumaRows);

LumaRows bandLumaRows(ImageView<const Rgba8> in, int y0, int y1, TextureFormat format) {
    thread_local std::vector<float> buffer, decoded;
    const int first = std::max(0, y0 - 1), last = std::min(in.height(), y1 + 1);
    buffer.resize(std::size_t(last - first) * std::size_t(in.width()));
    if (format == TextureFormat::Srgb) {
        decoded.resize(std::size_t(last - first) * DecodedBand::rowFloats(in.width()));
        HWY_DYNAMIC_DISPATCH(DecodedLumaRows)
        (in.row(first), std::size_t(in.stride()), in.width(), last - first, decoded.data(), buffer.data());
        return {buffer.data(), in.width(), in.height(), first, decoded.data(), last - first};
    }
    const ImageView<const Rgba8> rows(in.row(first), in.width(), last - first, in.stride());
    lumaPlane(rows, ImageView<float>(buffer.data(), in.width(), last - first), Exec{1}, format);
    return {buffer.data(), in.width(), in.height(), first, nullptr, last - first};
}

void earlyExitRow(const LumaRows& L, int y, float thresholdMin, float threshold, std::uint8_t* exitMask) {
    HWY_DYNAMIC_DISPATCH(ExitRow)(L.row(y - 1), L.row(y), L.row(y + 1), L.width, thresholdMin, threshold, exitMask);
}

}  // namespace ssfx::aa::detail
#endif
