// Luma plane, vectorised with Highway (runtime dispatch to the best SIMD target).
// Per lane the same float32 operations as ssfx::luma(): v / 255 (the IEEE quotient, by
// DivExact: exact_div-inl.h),
// then ((0.299 r + 0.587 g) + 0.114 b) without fused multiply-add, then sqrt; so the
// plane equals the scalar reference bit for bit (tests/core/test_color.cpp).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/core/color.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "src/core/exact_div-inl.h"
#include "src/core/srgb_encode-inl.h"
#include "ssfx/core/color.hpp"
#include "ssfx/core/parallel.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void LumaRow(const Rgba8* HWY_RESTRICT in, float* HWY_RESTRICT out, int w) {
    const hn::ScalableTag<float> df;
    const hn::RebindToUnsigned<decltype(df)> du;
    const hn::RebindToSigned<decltype(df)> di;
    const int n = int(hn::Lanes(df));
    const auto mask = hn::Set(du, 0xFFu);
    const ExactDivisor<decltype(df)> k255(df, 255.0f);
    const auto wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    int x = 0;
    for (; x + n <= w; x += n) {
        // One pixel per 32-bit lane, little-endian: r in the low byte.
        const auto v = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(in + x));
        const auto r = DivExact(hn::ConvertTo(df, hn::BitCast(di, hn::And(v, mask))), k255);
        const auto g = DivExact(hn::ConvertTo(df, hn::BitCast(di, hn::And(hn::ShiftRight<8>(v), mask))), k255);
        const auto b = DivExact(hn::ConvertTo(df, hn::BitCast(di, hn::And(hn::ShiftRight<16>(v), mask))), k255);
        const auto y = hn::Add(hn::Add(hn::Mul(wr, r), hn::Mul(wg, g)), hn::Mul(wb, b));
        hn::StoreU(hn::Sqrt(y), df, out + x);
    }
    for (; x < w; ++x) out[x] = luma(kUnorm8[in[x].r], kUnorm8[in[x].g], kUnorm8[in[x].b]);
}

// The same for an sRGB texture: each channel decoded by a gather from kSrgb8 (256 floats).
void LumaRowSrgb(const Rgba8* HWY_RESTRICT in, float* HWY_RESTRICT out, int w) {
    const hn::ScalableTag<float> df;
    const hn::RebindToUnsigned<decltype(df)> du;
    const hn::RebindToSigned<decltype(df)> di;
    const int n = int(hn::Lanes(df));
    const auto mask = hn::Set(du, 0xFFu);
    const auto wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    const float* table = kSrgb8.data();
    auto decode = [&](auto byte) { return hn::GatherIndex(df, table, hn::BitCast(di, byte)); };
    int x = 0;
    for (; x + n <= w; x += n) {
        const auto v = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(in + x));
        const auto r = decode(hn::And(v, mask));
        const auto g = decode(hn::And(hn::ShiftRight<8>(v), mask));
        const auto b = decode(hn::And(hn::ShiftRight<16>(v), mask));
        const auto y = hn::Add(hn::Add(hn::Mul(wr, r), hn::Mul(wg, g)), hn::Mul(wb, b));
        hn::StoreU(hn::Sqrt(y), df, out + x);
    }
    for (; x < w; ++x) out[x] = luma(kSrgb8[in[x].r], kSrgb8[in[x].g], kSrgb8[in[x].b]);
}

// Number of k in [0, kMax] where DivExact(k, divisor) differs from the IEEE quotient.
std::int64_t DivExactMismatches(float divisor, int kMax) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const int n = int(hn::Lanes(df));
    const ExactDivisor<decltype(df)> div(df, divisor);
    std::vector<float> got(static_cast<std::size_t>(n));
    std::int64_t mismatches = 0;
    for (int k0 = 0; k0 <= kMax; k0 += n) {
        hn::StoreU(DivExact(hn::ConvertTo(df, hn::Iota(di, k0)), div), df, got.data());
        for (int i = 0; i < n && k0 + i <= kMax; ++i) {
            const float want = float(k0 + i) / divisor;
            if (std::memcmp(&got[std::size_t(i)], &want, sizeof want) != 0) ++mismatches;
        }
    }
    return mismatches;
}

std::int64_t EncodeSrgb8Mismatches(const float* values, std::int64_t count) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const auto n = std::int64_t(hn::Lanes(df));
    std::vector<float> in(static_cast<std::size_t>(n));
    std::vector<std::int32_t> got(static_cast<std::size_t>(n));
    std::int64_t mismatches = 0;
    for (std::int64_t i0 = 0; i0 < count; i0 += n) {
        const std::int64_t m = std::min(n, count - i0);
        std::fill(in.begin(), in.end(), 0.0f);
        std::copy(values + i0, values + i0 + m, in.begin());
        hn::StoreU(EncodeSrgb8(df, hn::LoadU(df, in.data())), di, got.data());
        for (std::int64_t i = 0; i < m; ++i) mismatches += got[std::size_t(i)] != encodeSrgb8(in[std::size_t(i)]);
    }
    return mismatches;
}

std::int64_t EncodeSrgb8RangeMismatches(std::uint32_t lowBits, std::uint32_t highBits) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const hn::RebindToUnsigned<decltype(df)> du;
    const auto n = std::uint32_t(hn::Lanes(df));
    std::vector<std::int32_t> got(n);
    std::int64_t mismatches = 0;
    for (std::uint32_t b0 = lowBits; b0 < highBits; b0 += n) {
        const auto bits = hn::Iota(du, b0);
        hn::StoreU(EncodeSrgb8(df, hn::BitCast(df, bits)), di, got.data());
        for (std::uint32_t i = 0; i < n && b0 + i < highBits; ++i)
            mismatches += got[i] != encodeSrgb8(std::bit_cast<float>(b0 + i));
    }
    return mismatches;
}

std::int64_t DecodeSrgbRowMismatches(int w) {
    std::vector<Rgba8> row(static_cast<std::size_t>(w));
    for (int x = 0; x < w; ++x) {
        const auto i = unsigned(x);
        row[std::size_t(x)] = {std::uint8_t(i), std::uint8_t(255u - i * 3u), std::uint8_t(i * 7u + i / 256u), 0};
    }
    std::vector<float> r(row.size()), g(row.size()), b(row.size());
    DecodeSrgbRowPlanar(row.data(), w, r.data(), g.data(), b.data());
    std::int64_t mismatches = 0;
    for (std::size_t x = 0; x < row.size(); ++x) {
        mismatches += std::bit_cast<std::uint32_t>(r[x]) != std::bit_cast<std::uint32_t>(kSrgb8[row[x].r]);
        mismatches += std::bit_cast<std::uint32_t>(g[x]) != std::bit_cast<std::uint32_t>(kSrgb8[row[x].g]);
        mismatches += std::bit_cast<std::uint32_t>(b[x]) != std::bit_cast<std::uint32_t>(kSrgb8[row[x].b]);
    }
    return mismatches;
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "src/core/exact_div_hooks.hpp"

namespace ssfx {

static_assert(std::endian::native == std::endian::little, "LumaRow assumes little-endian pixels");
HWY_EXPORT(LumaRow);
HWY_EXPORT(LumaRowSrgb);
HWY_EXPORT(DivExactMismatches);
HWY_EXPORT(EncodeSrgb8Mismatches);
HWY_EXPORT(DecodeSrgbRowMismatches);
HWY_EXPORT(EncodeSrgb8RangeMismatches);

namespace detail {
std::int64_t divExactMismatches(float divisor, int kMax) {
    return HWY_DYNAMIC_DISPATCH(DivExactMismatches)(divisor, kMax);
}
std::int64_t encodeSrgb8Mismatches(const float* values, std::int64_t count) {
    return HWY_DYNAMIC_DISPATCH(EncodeSrgb8Mismatches)(values, count);
}
std::int64_t encodeSrgb8RangeMismatches(std::uint32_t lowBits, std::uint32_t highBits) {
    return HWY_DYNAMIC_DISPATCH(EncodeSrgb8RangeMismatches)(lowBits, highBits);
}
std::int64_t decodeSrgbRowMismatches(int w) { return HWY_DYNAMIC_DISPATCH(DecodeSrgbRowMismatches)(w); }
}  // namespace detail

void lumaPlane(ImageView<const Rgba8> in, ImageView<float> out, const Exec& exec, TextureFormat format) {
    SSFX_ASSERT(out.width() == in.width() && out.height() == in.height());
    const bool srgb = format == TextureFormat::Srgb;
    parallelRows(in.height(), exec, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            if (srgb)
                HWY_DYNAMIC_DISPATCH(LumaRowSrgb)(in.row(y), out.row(y), in.width());
            else
                HWY_DYNAMIC_DISPATCH(LumaRow)(in.row(y), out.row(y), in.width());
        }
    });
}

ImageF lumaPlane(ImageView<const Rgba8> in, const Exec& exec, TextureFormat format) {
    ImageF L(in.width(), in.height());
    lumaPlane(in, L.view(), exec, format);
    return L;
}

const std::array<float, 255>& srgbEncodeThresholds() {
    // t = srgbToLinear((k + 0.5) / 255) in double, where the nearest level changes from k to
    // k + 1. It is never a float, so the float v reaches level k + 1 exactly when v >= the
    // smallest float above t: that float is kept.
    static const std::array<float, 255> thresholds = [] {
        std::array<float, 255> a{};
        for (int k = 0; k < 255; ++k) {
            const double t = srgbToLinear((k + 0.5) / 255.0);
            float f = static_cast<float>(t);
            if (double(f) <= t) f = std::nextafter(f, 2.0f);
            a[std::size_t(k)] = f;
        }
        return a;
    }();
    return thresholds;
}

namespace detail {
const SrgbEncodeTable& srgbEncodeTable() {
    static const SrgbEncodeTable table = [] {
        using T = SrgbEncodeTable;
        const std::array<float, 255>& t = srgbEncodeThresholds();
        // The defining rule: the number of thresholds at or below v.
        auto level = [&](float v) { return std::int32_t(std::upper_bound(t.begin(), t.end(), v) - t.begin()); };
        T built{};
        for (std::uint32_t j = 0; j < T::kBuckets; ++j) {
            const std::uint32_t lowest = T::kLowBits + (j << T::kShift), highest = lowest + (1u << T::kShift) - 1;
            built.first[j] = level(std::bit_cast<float>(lowest));
            // At most one threshold in the bucket (see the header).
            SSFX_ASSERT(level(std::bit_cast<float>(highest)) <= built.first[j] + 1);
            const std::uint32_t above = std::bit_cast<std::uint32_t>(t[std::size_t(std::min(built.first[j], 254))]);
            const std::uint32_t offset =
                built.first[j] < 255 && above <= highest ? above - lowest : std::uint32_t(T::kNoThreshold);
            built.packed[j] = std::int32_t((std::uint32_t(built.first[j]) << 16) | offset);
        }
        SSFX_ASSERT(level(std::bit_cast<float>(T::kLowBits - 1)) == 0);
        std::copy(t.begin(), t.end(), built.next.begin());
        built.next[255] = std::numeric_limits<float>::infinity();
        return built;
    }();
    return table;
}

const SrgbDecodeHalves& srgbDecodeHalves() {
    static const SrgbDecodeHalves halves = [] {
        SrgbDecodeHalves h{};
        for (std::size_t i = 0; i < 256; ++i) {
            const auto bits = std::bit_cast<std::uint32_t>(kSrgb8[i]);
            h.low[i] = std::uint16_t(bits & 0xFFFFu);
            h.high[i] = std::uint16_t(bits >> 16);
        }
        return h;
    }();
    return halves;
}
}  // namespace detail

}  // namespace ssfx
#endif
