// encodeSrgb8 (ssfx/core/color.hpp) per lane, for the Highway kernels of the sRGB-texture
// mode: the same table and rule, two gathers per vector, so the same bytes.
#if defined(SSFX_CORE_SRGB_ENCODE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_CORE_SRGB_ENCODE_INL_H_
#undef SSFX_CORE_SRGB_ENCODE_INL_H_
#else
#define SSFX_CORE_SRGB_ENCODE_INL_H_
#endif

#include <hwy/highway.h>

#include <bit>

#include "ssfx/core/color.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// encodeSrgb8 per lane, by its table (color.hpp): the bucket's level, plus one at or above
// the next threshold; 0 for v <= 0, NaN and v < 2^-14, 255 for v >= 1.
template <class DF>
HWY_INLINE hn::Vec<hn::RebindToSigned<DF>> EncodeSrgb8(DF df, hn::Vec<DF> v) {
    using T = ssfx::detail::SrgbEncodeTable;
    const hn::RebindToSigned<DF> di;
    const hn::RebindToUnsigned<DF> du;
    const T& t = ssfx::detail::srgbEncodeTable();
    const auto bits = hn::BitCast(du, v);
    // (v >= 2^-14 implies v > 0; NaN fails both comparisons.)
    const auto inRange =
        hn::And(hn::Ge(v, hn::Set(df, std::bit_cast<float>(T::kLowBits))), hn::Lt(v, hn::Set(df, 1.0f)));
    const auto index =
        hn::IfThenElseZero(hn::RebindMask(di, inRange),
                           hn::BitCast(di, hn::ShiftRight<T::kShift>(hn::Sub(bits, hn::Set(du, T::kLowBits)))));
    const auto k = hn::GatherIndex(di, t.first.data(), index);
    const auto up = hn::RebindMask(di, hn::Ge(v, hn::GatherIndex(df, t.next.data(), k)));
    const auto level = hn::Add(k, hn::IfThenElseZero(up, hn::Set(di, 1)));
    const auto outside = hn::IfThenElseZero(hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f))), hn::Set(di, 255));
    return hn::IfThenElse(hn::RebindMask(di, inRange), level, outside);
}

}  // namespace ssfx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
