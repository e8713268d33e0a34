// Highway body of fxaa3c across pixels (scalar oracle: fxaa3c.cpp). Diagonal lumas come
// from the luma plane (reads at pixel centres), the four taps are gathered GPU-model reads;
// every float operation mirrors the scalar code in order. Either texture encoding: the reads
// and the encode follow Texture::sample and toRgba8 (ppaa-inl.h's SampleGpu, EncodeByte).
#if defined(SSFX_AA_FXAA3C_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_FXAA3C_INL_H_
#undef SSFX_AA_FXAA3C_INL_H_
#else
#define SSFX_AA_FXAA3C_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "src/aa/ppaa-inl.h"
#include "ssfx/aa/fxaa.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// clamp(q, -2, 2) with std::fmax/fmin's NaN rule (the non-NaN operand), as the scalar code
// and GPU clamp give for 0/0: NaN becomes -2. x86's maxps (and Highway's scalar Max)
// already return -2 here; the rule is spelled out for targets whose Max propagates NaN
// (e.g. NEON's vmaxq_f32).
HWY_INLINE VF ClampTwo(VF q) {
    const DF df;
    const VF m2 = hn::Set(df, -2.0f);
    return hn::IfThenElse(hn::Ne(q, q), m2, hn::Min(hn::Max(q, m2), hn::Set(df, 2.0f)));
}

// The early exit of pixels [x, x + N) of row y (1 <= x, x + N <= W - 1): true where the
// diagonal contrast is below the threshold (the pixel is copied).
HWY_INLINE hn::Mask<DF> Fxaa3cExit(const LumaRows& L, int x, int y, const Fxaa3cParams& p) {
    const DF df;
    const float* ra = L.row(y - 1);
    const float* rc = L.row(y);
    const float* rb = L.row(y + 1);
    const VF lumaNW = hn::LoadU(df, ra + x - 1), lumaSW = hn::LoadU(df, rb + x - 1);
    const VF lumaSE = hn::LoadU(df, rb + x + 1);
    const VF lumaNE = hn::Add(hn::LoadU(df, ra + x + 1), hn::Set(df, 1.0f / 384.0f));
    const VF lumaM = hn::LoadU(df, rc + x);
    const VF lumaMax = hn::Max(hn::Max(lumaNE, lumaSE), hn::Max(lumaNW, lumaSW));
    const VF lumaMin = hn::Min(hn::Min(lumaNE, lumaSE), hn::Min(lumaNW, lumaSW));
    return hn::Lt(hn::Sub(hn::Max(lumaMax, lumaM), hn::Min(lumaMin, lumaM)),
                  hn::Max(hn::Set(df, p.edgeThresholdMin), hn::Mul(lumaMax, hn::Set(df, p.edgeThreshold))));
}

// fxaa3c for the pixels xv (N columns of row y, each 1 <= x <= W - 2, repeats allowed) that
// do not exit early; diagonals at +-1 pixel, so the diagonal lumas are luma-plane lookups.
// Lumas are gathered, the result scattered: the pixels need not be adjacent.
HWY_INLINE void Fxaa3cPixels(const Texture& tex, const LumaRows& L, VI xv, int y, const Fxaa3cParams& p,
                             const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DI di;
    const DU du;
    const float* ra = L.row(y - 1);
    const float* rb = L.row(y + 1);
    const VI one = hn::Set(di, 1);
    const VI west = hn::Sub(xv, one), east = hn::Add(xv, one);
    // Lottes' names (y down): NW = (-1, -1), NE = (+1, -1), SW = (-1, +1), SE = (+1, +1).
    const VF lumaNW = hn::GatherIndex(df, ra, west), lumaSW = hn::GatherIndex(df, rb, west);
    const VF lumaSE = hn::GatherIndex(df, rb, east);
    const VF lumaNE = hn::Add(hn::GatherIndex(df, ra, east), hn::Set(df, 1.0f / 384.0f));
    const VF lumaMax = hn::Max(hn::Max(lumaNE, lumaSE), hn::Max(lumaNW, lumaSW));
    const VF lumaMin = hn::Min(hn::Min(lumaNE, lumaSE), hn::Min(lumaNW, lumaSW));
    const VF swMinusNe = hn::Sub(lumaSW, lumaNE), seMinusNw = hn::Sub(lumaSE, lumaNW);
    const VF dirX = hn::Add(swMinusNe, seMinusNw), dirY = hn::Sub(swMinusNe, seMinusNw);
    const VF len = hn::Sqrt(hn::Add(hn::Mul(dirX, dirX), hn::Mul(dirY, dirY)));
    const auto keep = hn::Not(hn::Gt(len, hn::Zero(df)));  // no direction: unchanged
    const VF d1x = hn::Div(dirX, len), d1y = hn::Div(dirY, len);

    // The pixel centre (x + 0.5) / W, the same float operations as Texture::centreU.
    const VF u = hn::Div(hn::Add(hn::ConvertTo(df, xv), hn::Set(df, 0.5f)), hn::Set(df, float(tex.width())));
    const VF v = hn::Set(df, tex.centreV(y));
    const VF invW = hn::Set(df, tex.invW()), invH = hn::Set(df, tex.invH());
    const VF half = hn::Set(df, 0.5f), two = hn::Set(df, 2.0f), quarter = hn::Set(df, 0.25f);
    const VF s1x = hn::Mul(hn::Mul(d1x, half), invW), s1y = hn::Mul(hn::Mul(d1y, half), invH);
    // An sRGB texture's reads come from the band's decoded rows where they lie in the band.
    const bool srgb = tex.format() == TextureFormat::Srgb;
    auto read = [&](VF ru, VF rv) {
        RgbV c;
        if (!srgb || !SampleDecodedRows(tex, L, ru, rv, &c)) c = SampleGpu(tex, ru, rv);
        return c;
    };
    const RgbV n1 = read(hn::Sub(u, s1x), hn::Sub(v, s1y));
    const RgbV p1 = read(hn::Add(u, s1x), hn::Add(v, s1y));
    const VF minAbs = hn::Mul(hn::Min(hn::Abs(d1x), hn::Abs(d1y)), hn::Set(df, p.edgeSharpness));
    const VF d2x = ClampTwo(hn::Div(d1x, minAbs)), d2y = ClampTwo(hn::Div(d1y, minAbs));
    const VF s2x = hn::Mul(hn::Mul(d2x, two), invW), s2y = hn::Mul(hn::Mul(d2y, two), invH);
    const RgbV n2 = read(hn::Sub(u, s2x), hn::Sub(v, s2y));
    const RgbV p2 = read(hn::Add(u, s2x), hn::Add(v, s2y));

    const RgbV A{hn::Add(n1.r, p1.r), hn::Add(n1.g, p1.g), hn::Add(n1.b, p1.b)};
    const RgbV B{hn::Add(hn::Mul(hn::Add(n2.r, p2.r), quarter), hn::Mul(A.r, quarter)),
                 hn::Add(hn::Mul(hn::Add(n2.g, p2.g), quarter), hn::Mul(A.g, quarter)),
                 hn::Add(hn::Mul(hn::Add(n2.b, p2.b), quarter), hn::Mul(A.b, quarter))};
    const VF lumaB = hn::Sqrt(hn::Add(hn::Add(hn::Mul(hn::Set(df, 0.299f), B.r), hn::Mul(hn::Set(df, 0.587f), B.g)),
                                      hn::Mul(hn::Set(df, 0.114f), B.b)));
    const auto twoTap = hn::Or(hn::Lt(lumaB, lumaMin), hn::Gt(lumaB, lumaMax));
    const RgbV result{hn::IfThenElse(twoTap, hn::Mul(A.r, half), B.r), hn::IfThenElse(twoTap, hn::Mul(A.g, half), B.g),
                      hn::IfThenElse(twoTap, hn::Mul(A.b, half), B.b)};
    const auto* src32 = reinterpret_cast<const std::uint32_t*>(src);
    const VU srcV = hn::GatherIndex(du, src32, xv);
    const VU rgb = hn::Or(hn::Or(hn::BitCast(du, EncodeByte(result.r, srgb)),
                                 hn::ShiftLeft<8>(hn::BitCast(du, EncodeByte(result.g, srgb)))),
                          hn::ShiftLeft<16>(hn::BitCast(du, EncodeByte(result.b, srgb))));
    const VU out = hn::Or(rgb, hn::And(srcV, hn::Set(du, 0xFF000000u)));
    hn::ScatterIndex(hn::IfThenElse(hn::RebindMask(du, keep), srcV, out), du, reinterpret_cast<std::uint32_t*>(dst),
                     xv);
}

// The interior of row y, [1, returned): every pixel copied, then the pixels that do not exit
// early listed and run N at a time. Listing first keeps the expensive part (four filtered
// reads a pixel) off the lanes that would only copy, which on photographs, where edge pixels
// are scattered, is most lanes of a chunk that holds one. The caller does x = 0 and
// [returned, W) with the scalar kernel.
inline int Fxaa3cRowSimd(const Texture& tex, const LumaRows& L, int y, const Fxaa3cParams& p, const Rgba8* src,
                         Rgba8* dst) {
    const DI di;
    const int n = int(hn::Lanes(DF())), w = L.width;
    int end = 1;
    while (end + n <= w - 1) end += n;
    if (end == 1) return 1;
    std::memcpy(dst + 1, src + 1, std::size_t(end - 1) * sizeof(Rgba8));
    thread_local std::vector<std::int32_t> listed;
    if (listed.size() < std::size_t(w + n)) listed.resize(std::size_t(w + n));
    std::int32_t* xs = listed.data();
    std::size_t count = 0;
    // Compress in registers, then a whole-vector store (the list has n spare entries):
    // CompressStore's masked compress to memory is microcoded and slow on Zen 4.
    for (int x = 1; x < end; x += n) {
        const auto edge = hn::RebindMask(di, hn::Not(Fxaa3cExit(L, x, y, p)));
        hn::StoreU(hn::Compress(IotaFrom(di, x), edge), di, xs + count);
        count += hn::CountTrue(di, edge);
    }
    for (std::size_t i = 0; i < count; i += std::size_t(n)) {
        // The last group repeats its last pixel (the same value written again).
        for (std::size_t k = count; k < i + std::size_t(n); ++k) xs[k] = xs[count - 1];
        Fxaa3cPixels(tex, L, hn::LoadU(di, xs + i), y, p, src, dst);
    }
    return end;
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
