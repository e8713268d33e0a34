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
// bytes (one gather per channel and vector; alpha is never filtered, so not decoded).
inline void DecodeSrgbRowPlanar(const Rgba8* HWY_RESTRICT in, int w, float* HWY_RESTRICT r, float* HWY_RESTRICT g,
                                float* HWY_RESTRICT b) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::RebindToUnsigned<decltype(df)> du;
    const int n = int(hn::Lanes(df));
    const float* table = kSrgb8.data();
    const auto mask = hn::Set(du, 0xFFu);
    auto decode = [&](auto t, int shift) {
        return hn::GatherIndex(df, table, hn::BitCast(di, hn::And(hn::ShiftRightSame(t, shift), mask)));
    };
    int x = 0;
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
