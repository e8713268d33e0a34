// Highway body of blur (compiled once per SIMD target; see blur.cpp).
//
// Rows are converted once to float (v / 255, the IEEE quotient by DivExact, as RGBA rows;
// an sRGB texture's decoded values, kSrgb8, as R, G and B rows) with one pixel of clamped
// padding at both ends, so the vector loop also covers the borders. Each lane is one
// channel of one pixel; the sums run in blurChannel()'s order (no FMA), so every lane
// equals the scalar reference; each vector is quantised as soon as it is computed.
#if defined(SSFX_AA_BLUR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_BLUR_INL_H_
#undef SSFX_AA_BLUR_INL_H_
#else
#define SSFX_AA_BLUR_INL_H_
#endif

#include <hwy/aligned_allocator.h>
#include <hwy/highway.h>

#include "src/aa/blur_kernel.hpp"
#include "src/core/exact_div-inl.h"
#include "src/core/srgb_encode-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[0..4] = pixel 0 (left padding), out[4 + 4x + c] = channel c of pixel x, then pixel w-1.
// Each byte's texel value: v / 255 (the IEEE quotient by DivExact).
inline void ToFloatRow(const Rgba8* HWY_RESTRICT in, int w, float* HWY_RESTRICT out) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::Rebind<std::uint8_t, decltype(df)> d8;
    const int n = int(hn::Lanes(df));
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(in);
    const int count = 4 * w;
    const ssfx::HWY_NAMESPACE::ExactDivisor<decltype(df)> k255(df, 255.0f);
    int i = 0;
    for (; i + n <= count; i += n) {
        const auto v = hn::PromoteTo(di, hn::LoadU(d8, bytes + i));
        hn::StoreU(ssfx::HWY_NAMESPACE::DivExact(hn::ConvertTo(df, v), k255), df, out + 4 + i);
    }
    for (; i < count; ++i) out[4 + i] = kUnorm8[bytes[i]];
    for (int c = 0; c < 4; ++c) out[c] = out[4 + c], out[4 + count + c] = out[count + c];
}

// blurChannel() per lane for the channels at a, c, b (above, centre, below; the neighbours
// `step` floats, one pixel, either side: 4 in RGBA rows, 1 in channel rows), in its order.
template <int step, class DF>
HWY_INLINE hn::Vec<DF> BlurSum(DF df, const float* a, const float* c, const float* b, hn::Vec<DF> w1, hn::Vec<DF> w2,
                               hn::Vec<DF> norm) {
    const auto horizontal = hn::Add(hn::LoadU(df, c - step), hn::LoadU(df, c + step));    // w + e
    const auto vertical = hn::Add(hn::LoadU(df, a), hn::LoadU(df, b));                    // s + n
    const auto cornersAbove = hn::Add(hn::LoadU(df, a - step), hn::LoadU(df, a + step));  // sw + se
    const auto cornersBelow = hn::Add(hn::LoadU(df, b - step), hn::LoadU(df, b + step));  // nw + ne
    const auto direct = hn::Mul(hn::Add(horizontal, vertical), w1);
    const auto corner = hn::Mul(hn::Add(cornersAbove, cornersBelow), w2);
    return hn::Mul(hn::Add(hn::Add(hn::LoadU(df, c), direct), corner), norm);
}

// BlurRowQuantized for an sRGB texture, on channel rows (DecodeSrgbRowPadded): the same sums,
// lane by lane, one lane per pixel, each channel's vector encoded by EncodeSrgb8 (exact, so no
// ties to take lane by lane), the three levels and the source's alpha packed into the lane's
// RGBA word. Channel rows decode and encode three values a pixel, not four.
inline void BlurRowSrgb(const float* HWY_RESTRICT fa, const float* HWY_RESTRICT fc, const float* HWY_RESTRICT fb,
                        std::size_t stride, int w, const BlurWeights& k, const Rgba8* HWY_RESTRICT src,
                        Rgba8* HWY_RESTRICT dst) {
    const hn::ScalableTag<float> df;
    const hn::RebindToUnsigned<decltype(df)> du;
    const int n = int(hn::Lanes(df));
    const auto w1 = hn::Set(df, k.w1), w2 = hn::Set(df, k.w2), norm = hn::Set(df, k.norm);
    auto channel = [&](int c, int x) {
        const std::size_t at = std::size_t(c) * stride + 1 + std::size_t(x);
        return hn::BitCast(
            du, ssfx::HWY_NAMESPACE::EncodeSrgb8(df, BlurSum<1>(df, fa + at, fc + at, fb + at, w1, w2, norm)));
    };
    const auto* src32 = reinterpret_cast<const std::uint32_t*>(src);
    auto* dst32 = reinterpret_cast<std::uint32_t*>(dst);
    int x = 0;
    for (; x + n <= w; x += n) {
        const auto alpha = hn::And(hn::LoadU(du, src32 + x), hn::Set(du, 0xFF000000u));
        const auto rgb =
            hn::Or(hn::Or(channel(0, x), hn::ShiftLeft<8>(channel(1, x))), hn::ShiftLeft<16>(channel(2, x)));
        hn::StoreU(hn::Or(rgb, alpha), du, dst32 + x);
    }
    for (; x < w; ++x) {
        std::uint8_t q[3];
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = std::size_t(c) * stride + 1 + std::size_t(x);
            const float* a = fa + at;
            const float* m = fc + at;
            const float* b = fb + at;
            q[c] = encodeSrgb8(blurChannel(m[0], m[-1], m[1], a[0], b[0], a[-1], a[1], b[-1], b[1], k));
        }
        dst[x] = {q[0], q[1], q[2], src[x].a};
    }
}

// One output row from three padded float rows (above, centre, below), quantised as it is
// computed: toUnorm8()'s rounding of the exact product v * 255 (the float product is within
// 2^-17 of it, so it rounds the same way unless it lands on a tie: such (rare) vectors take
// toUnorm8() lane by lane). Alpha comes from the source pixel.
inline void BlurRowQuantized(const float* HWY_RESTRICT fa, const float* HWY_RESTRICT fc, const float* HWY_RESTRICT fb,
                             int w, const BlurWeights& k, const Rgba8* HWY_RESTRICT src, Rgba8* HWY_RESTRICT dst) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::Rebind<std::uint8_t, decltype(df)> d8;
    const int n = int(hn::Lanes(df));
    const int count = 4 * w;
    const auto w1 = hn::Set(df, k.w1), w2 = hn::Set(df, k.w2), norm = hn::Set(df, k.norm);
    const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), k255 = hn::Set(df, 255.0f), half = hn::Set(df, 0.5f);
    const auto tieBand = hn::Set(df, 1.0f / 65536.0f);
    const auto three = hn::Set(d8, std::uint8_t{3});
    auto* bytes = reinterpret_cast<std::uint8_t*>(dst);
    const auto* srcBytes = reinterpret_cast<const std::uint8_t*>(src);
    auto scalar = [&](int i) {
        const float* a = fa + 4 + i;
        const float* c = fc + 4 + i;
        const float* b = fb + 4 + i;
        return blurChannel(c[0], c[-4], c[4], a[0], b[0], a[-4], a[4], b[-4], b[4], k);
    };
    // Lane j of a vector at i is channel (i + j) mod 4: with n a multiple of 4 (every
    // target but scalar) the alpha lanes are the same in every vector.
    const auto alphaAt0 = hn::Eq(hn::And(hn::Iota(d8, 0), three), three);
    int i = 0;
    for (; i + n <= count; i += n) {
        const auto v = BlurSum<4>(df, fa + 4 + i, fc + 4 + i, fb + 4 + i, w1, w2, norm);
        const auto t = hn::Add(hn::Mul(hn::Min(hn::Max(v, zero), one), k255), half);
        const auto fl = hn::Floor(t);
        if (!hn::AllFalse(df, hn::Lt(hn::Sub(t, fl), tieBand))) {
            for (int j = 0; j < n; ++j) bytes[i + j] = (i + j) % 4 == 3 ? srcBytes[i + j] : toUnorm8(scalar(i + j));
            continue;
        }
        const auto q = hn::DemoteTo(d8, hn::ConvertTo(di, fl));
        const auto isAlpha = n % 4 == 0 ? alphaAt0 : hn::Eq(hn::And(hn::Iota(d8, std::uint8_t(i & 3)), three), three);
        hn::StoreU(hn::IfThenElse(isAlpha, hn::LoadU(d8, srcBytes + i), q), d8, bytes + i);
    }
    for (; i < count; ++i) bytes[i] = i % 4 == 3 ? srcBytes[i] : toUnorm8(scalar(i));
}

inline void BlurRows(ImageView<const Rgba8> in, ImageView<Rgba8> out, int y0, int y1, const BlurWeights& k,
                     TextureFormat format) {
    const int w = in.width(), h = in.height();
    const bool srgb = format == TextureFormat::Srgb;
    // sRGB: three channel rows of w + 2 floats; unorm: one RGBA row of 4 w + 8.
    const std::size_t channelStride = std::size_t(w + 2);
    const std::size_t stride = srgb ? 3 * channelStride : std::size_t(4 * w + 8);
    const auto toFloat = [&](const Rgba8* row, float* rowOut) {
        if (srgb)
            ssfx::HWY_NAMESPACE::DecodeSrgbRowPadded(row, w, rowOut);
        else
            ToFloatRow(row, w, rowOut);
    };
    // Rolling window of three converted rows.
    const auto buf = hwy::AllocateAligned<float>(3 * stride);
    float* rows[3] = {buf.get(), buf.get() + stride, buf.get() + 2 * stride};
    auto clampY = [h](int y) { return y < 0 ? 0 : (y >= h ? h - 1 : y); };
    toFloat(in.row(clampY(y0 - 1)), rows[0]);
    toFloat(in.row(y0), rows[1]);
    for (int y = y0; y < y1; ++y) {
        toFloat(in.row(clampY(y + 1)), rows[2]);
        if (srgb)
            BlurRowSrgb(rows[0], rows[1], rows[2], channelStride, w, k, in.row(y), out.row(y));
        else
            BlurRowQuantized(rows[0], rows[1], rows[2], w, k, in.row(y), out.row(y));
        float* t = rows[0];
        rows[0] = rows[1], rows[1] = rows[2], rows[2] = t;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
