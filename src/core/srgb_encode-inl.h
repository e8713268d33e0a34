// encodeSrgb8 (ssfx/core/color.hpp) per lane, for the Highway kernels of the sRGB-texture
// mode: the same table and rule, two gathers per vector, so the same bytes. Also the decode
// of a row of texels into channel rows (kSrgb8's values), which those kernels read.
#if defined(SSFX_CORE_SRGB_ENCODE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_CORE_SRGB_ENCODE_INL_H_
#undef SSFX_CORE_SRGB_ENCODE_INL_H_
#else
#define SSFX_CORE_SRGB_ENCODE_INL_H_
#endif

#include <hwy/highway.h>

#include <bit>
#include <cstddef>
#include <type_traits>

#include "ssfx/core/color.hpp"
#include "ssfx/core/sample.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// encodeSrgb8 per lane, by its table (color.hpp): the bucket's level, plus one at or above
// the bucket's threshold (one gather of the packed word); 0 for v <= 0, NaN and v < 2^-14,
// 255 for v >= 1.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> EncodeSrgb8ByTable(DF df, hn::Vec<DF> v) {
    using T = ssfx::detail::SrgbEncodeTable;
    const hn::RebindToSigned<DF> di;
    const hn::RebindToUnsigned<DF> du;
    // (Held here: srgbEncodeTable() is an out-of-line call, once per vector otherwise.)
    static const T& t = ssfx::detail::srgbEncodeTable();
    // (v >= 2^-14 implies v > 0; NaN fails both comparisons.)
    const auto inRange =
        hn::And(hn::Ge(v, hn::Set(df, std::bit_cast<float>(T::kLowBits))), hn::Lt(v, hn::Set(df, 1.0f)));
    const auto offset = hn::BitCast(di, hn::Sub(hn::BitCast(du, v), hn::Set(du, T::kLowBits)));
    const auto index = hn::IfThenElseZero(hn::RebindMask(di, inRange), hn::ShiftRight<T::kShift>(offset));
    const auto e = hn::GatherIndex(di, t.packed.data(), index);
    const auto up =  // offset in the bucket >= the threshold's (no signed Ge in Highway 1.0)
        hn::Not(hn::Lt(hn::And(offset, hn::Set(di, std::int32_t(T::kOffsetMask))), hn::And(e, hn::Set(di, 0xFFFF))));
    const auto level = hn::Add(hn::ShiftRight<16>(e), hn::IfThenElseZero(up, hn::Set(di, 1)));
    const auto outside = hn::IfThenElseZero(hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f))), hn::Set(di, 255));
    return hn::IfThenElse(hn::RebindMask(di, inRange), level, outside);
}

// The real-valued encode e(v) = 255 (1.055 v^(1/2.4) - 0.055), or 255 * 12.92 v below the
// curve's knee, is the exact inverse of the decode whose half-levels are encodeSrgb8's
// thresholds, so encodeSrgb8(v) = floor(e(v) + 0.5) (e(v) + 0.5 is never an integer for a
// float v: the thresholds are never floats). This computes e(v) to within 7.7e-5 levels
// (measured over every float in range): v = 2^E m with m in [1, 2), v^(5/12) = 2^(5E/12)
// m^(5/12), the first factor a table of the 14 exponents in range (one register), the second
// a degree-6 polynomial in m - 1.5 (Chebyshev interpolation at 7 nodes; relative error at most
// 3.4e-7 evaluated in float). Lanes whose e(v) + 0.5 lies within 4e-4 of an integer are
// ambiguous (0.08 % of floats); a vector holding one takes the table. Test
// Color.VectorSrgbEncodeGivesTheScalarLevels checks every float in [2^-14, 1] against
// encodeSrgb8, so a lane that is not flagged but wrong would fail it. Used where a vector is
// 16 floats (AVX-512): a gather of 16 lanes costs about 26 cycles on Zen 4, this a fraction
// of that. (With a degree-5 polynomial and a band of 1/500, 9 % of blur's vectors took the
// table and the branch cost blur:srgb a third of its time.)
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> EncodeSrgb8(DF df, hn::Vec<DF> v) {
#if HWY_ARCH_X86 && (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL)
    if constexpr (std::is_same_v<DF, hn::ScalableTag<float>>) {
        using T = ssfx::detail::SrgbEncodeTable;
        const hn::RebindToSigned<DF> di;
        const hn::RebindToUnsigned<DF> du;
        // float(255 * 1.055 * 2^(5E / 12)) for E = -14 .. -1 (then two unused entries).
        alignas(64) static constexpr float kScale[16] = {
            4.71828676f, 6.29815721f, 8.40703125f, 11.2220404f, 14.9796267f, 19.9954028f, 26.6906605f, 35.6277574f,
            47.5573505f, 63.4814467f, 84.7375651f, 113.111079f, 150.985176f, 201.541031f, 0.0f,        0.0f};
        const auto inRange =
            hn::And(hn::Ge(v, hn::Set(df, std::bit_cast<float>(T::kLowBits))), hn::Lt(v, hn::Set(df, 1.0f)));
        const auto bits = hn::BitCast(du, v);
        const auto exponent =
            hn::Min(hn::Max(hn::Sub(hn::BitCast(di, hn::ShiftRight<23>(bits)), hn::Set(di, 127 - 14)), hn::Zero(di)),
                    hn::Set(di, 15));
        const auto m = hn::BitCast(df, hn::Or(hn::And(bits, hn::Set(du, 0x7FFFFFu)), hn::Set(du, 0x3F800000u)));
        const auto t = hn::Sub(m, hn::Set(df, 1.5f));
        auto p = hn::Set(df, -0.00269152573f);
        p = hn::MulAdd(p, t, hn::Set(df, 0.0052354401f));
        p = hn::MulAdd(p, t, hn::Set(df, -0.00964535028f));
        p = hn::MulAdd(p, t, hn::Set(df, 0.0224240758f));
        p = hn::MulAdd(p, t, hn::Set(df, -0.0639548749f));
        p = hn::MulAdd(p, t, hn::Set(df, 0.328906238f));
        p = hn::MulAdd(p, t, hn::Set(df, 1.18405354f));
        const auto scale = hn::TableLookupLanes(hn::Load(df, kScale), hn::IndicesFromVec(df, exponent));
        const auto power = hn::MulAdd(scale, p, hn::Set(df, -255.0f * 0.055f));
        const auto linear = hn::Mul(v, hn::Set(df, 255.0f * 12.92f));
        const auto e = hn::IfThenElse(hn::Lt(v, hn::Set(df, 0.0031308f)), linear, power);
        const auto f = hn::Add(e, hn::Set(df, 0.5f));
        const auto fl = hn::Floor(f);
        const auto d = hn::Sub(f, fl);
        const auto near = hn::Or(hn::Lt(d, hn::Set(df, 0.0004f)), hn::Gt(d, hn::Set(df, 0.9996f)));
        if (hn::AllFalse(df, hn::And(inRange, near))) {
            const auto outside = hn::IfThenElseZero(hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f))), hn::Set(di, 255));
            return hn::IfThenElse(hn::RebindMask(di, inRange), hn::ConvertTo(di, fl), outside);
        }
    }
#endif
    return EncodeSrgb8ByTable(df, v);
}

// A row of w sRGB texels decoded channel by channel: r[x], g[x], b[x] = kSrgb8 of the texel's
// bytes (alpha is never filtered, so not decoded).
//  - AVX-512: a lookup in registers, 32 texels a channel at a time. The table's floats are
//    held as their low and high 16-bit halves (SrgbDecodeHalves), 256 words each = four
//    register pairs; vpermt2w looks up 64 entries of a pair by the index's low 6 bits, and
//    bits 6 and 7 pick the pair. The indices of two 16-texel vectors are packed to 16-bit
//    words (packus interleaves them by 128-bit block), and unpacking the halves' low and
//    high words restores the two vectors' order. On Zen 4 (1080p rows, one thread) this
//    took 0.4 ns a texel against 1.0 for three 16-lane gathers a vector.
//  - Elsewhere: one gather per channel and vector.
inline void DecodeSrgbRowPlanar(const Rgba8* HWY_RESTRICT in, int w, float* HWY_RESTRICT r, float* HWY_RESTRICT g,
                                float* HWY_RESTRICT b) {
    const float* table = kSrgb8.data();
    int x = 0;
#if HWY_ARCH_X86 && (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL)
    {
        static const ssfx::detail::SrgbDecodeHalves& halves = ssfx::detail::srgbDecodeHalves();
        __m512i low[8], high[8];  // entries 32 k .. 32 k + 31 in register k
        for (int k = 0; k < 8; ++k) {
            low[k] = _mm512_load_si512(halves.low.data() + 32 * k);
            high[k] = _mm512_load_si512(halves.high.data() + 32 * k);
        }
        const __m512i byte = _mm512_set1_epi32(0xFF);
        const __m512i bit6 = _mm512_set1_epi16(0x40), bit7 = _mm512_set1_epi16(0x80);
        auto lookup = [](const __m512i* t, __m512i idx, __mmask32 b6, __mmask32 b7) {
            const __m512i below = _mm512_mask_blend_epi16(b6, _mm512_permutex2var_epi16(t[0], idx, t[1]),
                                                          _mm512_permutex2var_epi16(t[2], idx, t[3]));
            const __m512i above = _mm512_mask_blend_epi16(b6, _mm512_permutex2var_epi16(t[4], idx, t[5]),
                                                          _mm512_permutex2var_epi16(t[6], idx, t[7]));
            return _mm512_mask_blend_epi16(b7, below, above);
        };
        float* out[3] = {r, g, b};
        for (; x + 32 <= w; x += 32) {
            const __m512i t0 = _mm512_loadu_si512(in + x), t1 = _mm512_loadu_si512(in + x + 16);
            for (int c = 0; c < 3; ++c) {
                const __m512i i0 = _mm512_and_si512(_mm512_srli_epi32(t0, unsigned(8 * c)), byte);
                const __m512i i1 = _mm512_and_si512(_mm512_srli_epi32(t1, unsigned(8 * c)), byte);
                const __m512i idx = _mm512_packus_epi32(i0, i1);
                const __mmask32 b6 = _mm512_test_epi16_mask(idx, bit6), b7 = _mm512_test_epi16_mask(idx, bit7);
                const __m512i lo = lookup(low, idx, b6, b7), hi = lookup(high, idx, b6, b7);
                _mm512_storeu_si512(out[c] + x, _mm512_unpacklo_epi16(lo, hi));
                _mm512_storeu_si512(out[c] + x + 16, _mm512_unpackhi_epi16(lo, hi));
            }
        }
    }
#endif
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::RebindToUnsigned<decltype(df)> du;
    const int n = int(hn::Lanes(df));
    const auto mask = hn::Set(du, 0xFFu);
    auto decode = [&](auto t, int shift) {
        return hn::GatherIndex(df, table, hn::BitCast(di, hn::And(hn::ShiftRightSame(t, shift), mask)));
    };
    for (; x + n <= w; x += n) {
        const auto t = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(in + x));
        hn::StoreU(decode(t, 0), df, r + x);
        hn::StoreU(decode(t, 8), df, g + x);
        hn::StoreU(decode(t, 16), df, b + x);
    }
    for (; x < w; ++x) r[x] = table[in[x].r], g[x] = table[in[x].g], b[x] = table[in[x].b];
}

// A row of w sRGB texels decoded into the padded channel-row layout the kernels share: three
// rows (r, g, b) of w + 2 floats, pixel x of channel c at out[c (w + 2) + 1 + x], and the
// padding floats repeating the edge texels (clamp to edge).
inline void DecodeSrgbRowPadded(const Rgba8* HWY_RESTRICT in, int w, float* HWY_RESTRICT out) {
    const std::size_t stride = std::size_t(w) + 2;
    float* r = out + 1;
    float* g = r + stride;
    float* b = g + stride;
    DecodeSrgbRowPlanar(in, w, r, g, b);
    for (float* c : {r, g, b}) c[-1] = c[0], c[w] = c[w - 1];
}

}  // namespace ssfx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
