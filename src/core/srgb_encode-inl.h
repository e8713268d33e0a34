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

#include "ssfx/core/color.hpp"
#include "ssfx/core/sample.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// encodeSrgb8 per lane, by its table (color.hpp): the bucket's level, plus one at or above
// the bucket's threshold (one gather of the packed word); 0 for v <= 0, NaN and v < 2^-14,
// 255 for v >= 1.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> EncodeSrgb8(DF df, hn::Vec<DF> v) {
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

}  // namespace ssfx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
