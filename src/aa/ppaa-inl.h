// Vector building blocks shared by the PPAA kernels across pixels (ddaa-inl.h,
// fxaa3d-inl.h): each lane is one pixel of a row, as in a GPU warp.
//
// Exactness: every float operation mirrors the scalar code (sample.cpp, ppaa_common.hpp)
// in the same order and without FMA; GPU-model bilinear reads are integer work on texels,
// giving levels k whose value is k / 4080, divided exactly where a float is needed (the
// IEEE quotient = the kSixteenthLevels table, by DivExact: src/core/exact_div-inl.h) and
// turned into output bytes in integers where the quantisation allows (ByteOfLevel,
// ByteOfMeanLevel).
#if defined(SSFX_AA_PPAA_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_PPAA_SIMD_INL_H_
#undef SSFX_AA_PPAA_SIMD_INL_H_
#else
#define SSFX_AA_PPAA_SIMD_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>
#include <vector>

#include "src/aa/luma_driver.hpp"
#include "src/aa/luma_planes.hpp"
#include "src/aa/ppaa_common.hpp"
#include "src/core/exact_div-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using VU = hn::Vec<DU>;
using ssfx::HWY_NAMESPACE::DivExact;
using ssfx::HWY_NAMESPACE::ExactDivisor;

struct RgbV {
    VF r, g, b;
};

// One axis of the GPU sampling model (Texture::axis + pair), per lane.
struct AxisV {
    VI i0, i1, w;
};
HWY_INLINE AxisV SplitAxis(VF coord, float size, int n) {
    const DF df;
    const DI di;
    const VF t = hn::Sub(hn::Mul(coord, hn::Set(df, size)), hn::Set(df, 0.5f));
    const VF fl = hn::Floor(t);
    const VF flc = hn::Min(hn::Max(fl, hn::Set(df, -4.0f)), hn::Set(df, float(n) + 4.0f));
    const VI i = hn::ConvertTo(di, flc);
    const VF frac = hn::Sub(t, fl);
    const VI w = hn::ConvertTo(di, hn::Add(hn::Mul(frac, hn::Set(df, 256.0f)), hn::Set(df, 0.5f)));
    const VI zero = hn::Zero(di), last = hn::Set(di, n - 1);
    const VI one = hn::Set(di, 1);
    return {hn::Min(hn::Max(i, zero), last), hn::Min(hn::Max(hn::Add(i, one), zero), last), w};
}

// Byte `shift` of each texel, as an int per lane.
HWY_INLINE VI TexelByte(VU t, int shift) {
    return hn::BitCast(DI(), hn::And(hn::ShiftRightSame(t, shift), hn::Set(DU(), 0xFFu)));
}

// (256 - w) a + w b, the GPU model's weighting of two values with weight w in [0, 256].
HWY_INLINE VI Lerp256(VI a, VI b, VI w) { return hn::Add(hn::ShiftLeft<8>(a), hn::Mul(w, hn::Sub(b, a))); }

// A read's level k in [0, 4080] as the float k / 4080 (the IEEE quotient).
HWY_INLINE VF Levels4080(VI k) {
    const DF df;
    // (Tried before DivExact: float(double(k) * (1 / 4080.0)), exact too but slower than
    // vdivps on Zen 4.)
    return DivExact(hn::ConvertTo(df, k), ExactDivisor<DF>(df, 4080.0f));
}

// k = (sum + 2048) >> 12 of one channel (byte `shift` of each texel): the read's level in
// [0, 4080], whose value is k / 4080 (Levels4080), where
// sum = (256 - wx)(256 - wy) t00 + wx (256 - wy) t10 + (256 - wx) wy t01 + wx wy t11.
// Evaluated as two lerps, (256 - wy) top + wy bottom with top = (256 - wx) t00 + wx t10:
// the same integer (no rounding in between, |sum| < 2^24), three multiplies instead of
// four plus the four weights'.
HWY_INLINE VI ChannelLevel(VU t00, VU t10, VU t01, VU t11, VI wx, VI wy, int shift) {
    const VI sum = Lerp256(Lerp256(TexelByte(t00, shift), TexelByte(t10, shift), wx),
                           Lerp256(TexelByte(t01, shift), TexelByte(t11, shift), wx), wy);
    return hn::ShiftRight<12>(hn::Add(sum, hn::Set(DI(), 2048)));
}

// A GPU-model read per lane as its three levels (value k / 4080 each).
struct RgbK {
    VI r, g, b;
};
HWY_INLINE RgbK ChannelLevels(VU t00, VU t10, VU t01, VU t11, VI wx, VI wy) {
    return {ChannelLevel(t00, t10, t01, t11, wx, wy, 0), ChannelLevel(t00, t10, t01, t11, wx, wy, 8),
            ChannelLevel(t00, t10, t01, t11, wx, wy, 16)};
}

// Bilinear GPU-model read at (u, v) per lane (Texture::sampleGpu), as levels.
HWY_INLINE RgbK SampleGpuLevels(const Texture& tex, VF u, VF v) {
    const DI di;
    const DU du;
    const AxisV ax = SplitAxis(u, float(tex.width()), tex.width());
    const AxisV ay = SplitAxis(v, float(tex.height()), tex.height());
    const VI stride = hn::Set(di, int(tex.image().stride()));
    const VI r0 = hn::Mul(ay.i0, stride), r1 = hn::Mul(ay.i1, stride);
    const auto* base = reinterpret_cast<const std::uint32_t*>(tex.image().data());
    const VU t00 = hn::GatherIndex(du, base, hn::Add(r0, ax.i0));
    const VU t10 = hn::GatherIndex(du, base, hn::Add(r0, ax.i1));
    const VU t01 = hn::GatherIndex(du, base, hn::Add(r1, ax.i0));
    const VU t11 = hn::GatherIndex(du, base, hn::Add(r1, ax.i1));
    return ChannelLevels(t00, t10, t01, t11, ax.w, ay.w);
}

// The same as floats (Texture::sampleGpu's values).
HWY_INLINE RgbV SampleGpu(const Texture& tex, VF u, VF v) {
    const RgbK k = SampleGpuLevels(tex, u, v);
    return {Levels4080(k.r), Levels4080(k.g), Levels4080(k.b)};
}

// A coordinate split as SplitAxis does (t = coord size - 0.5), relative to each lane's own
// texel `own`: whether floor(t) is the texel before it (`before`), or it or the one before
// (`near`: then the read's texel pair lies next to the lane's pixel), and the GPU weight
// of the pair's second texel.
struct NearSplit {
    hn::Mask<DF> before, near;
    VI w;
};
HWY_INLINE NearSplit SplitNear(VF coord, VF size, VF own) {
    const DF df;
    const DI di;
    const VF t = hn::Sub(hn::Mul(coord, size), hn::Set(df, 0.5f));
    const VF fl = hn::Floor(t);
    const VF rel = hn::Sub(fl, own);  // integers: exact
    const auto before = hn::Eq(rel, hn::Set(df, -1.0f));
    return {before, hn::Or(before, hn::Eq(rel, hn::Zero(df))),
            hn::ConvertTo(di, hn::Add(hn::Mul(hn::Sub(t, fl), hn::Set(df, 256.0f)), hn::Set(df, 0.5f)))};
}

// The GPU-model read at (u, v) per lane, as levels, from the 3 x 3 texels around each
// lane's pixel (row y, pixels x .. x + N - 1 with 1 <= x, x + N <= W - 1), loaded contiguously rather
// than gathered. Valid when every lane that counts (not in `skip`) reads within a texel of
// its pixel: floor(u W - 0.5) and floor(v H - 0.5) are its own column and row or the ones
// before. Otherwise returns false and writes nothing (the caller gathers). Same indices,
// clamping (rows only: columns stay inside) and weights as SampleGpu, so the same result.
HWY_INLINE bool NearSample(const Texture& tex, VF u, VF v, int x, int y, const hn::Mask<DF>& skip, RgbK* c) {
    const DF df;
    const DI di;
    const DU du;
    const NearSplit sx = SplitNear(u, hn::Set(df, float(tex.width())), hn::ConvertTo(df, hn::Iota(di, x)));
    const NearSplit sy = SplitNear(v, hn::Set(df, float(tex.height())), hn::Set(df, float(y)));
    if (!hn::AllTrue(df, hn::Or(hn::And(sx.near, sy.near), skip))) return false;
    const VI wx = sx.w, wy = sy.w;

    const auto image = tex.image();
    const int h = tex.height();
    const auto lx = hn::RebindMask(du, sx.before), ly = hn::RebindMask(du, sy.before);
    VU left[3], right[3];  // per row y - 1, y, y + 1: the texel pair (x0, x1) of each lane
    for (int r = 0; r < 3; ++r) {
        const int row = std::clamp(y - 1 + r, 0, h - 1);
        const auto* p = reinterpret_cast<const std::uint32_t*>(image.row(row)) + x;
        const VU a = hn::LoadU(du, p - 1), b = hn::LoadU(du, p), d = hn::LoadU(du, p + 1);
        left[r] = hn::IfThenElse(lx, a, b);
        right[r] = hn::IfThenElse(lx, b, d);
    }
    const VU t00 = hn::IfThenElse(ly, left[0], left[1]), t10 = hn::IfThenElse(ly, right[0], right[1]);
    const VU t01 = hn::IfThenElse(ly, left[1], left[2]), t11 = hn::IfThenElse(ly, right[1], right[2]);
    *c = ChannelLevels(t00, t10, t01, t11, wx, wy);
    return true;
}

// toUnorm8 per lane: floor(v * 255 + 0.5) of the *exact* product, in float32 only.
// v * 255 = v * 256 - v with v * 256 exact; Fast2Sum and TwoSum recover the rounding
// errors of the subtraction and of the + 0.5, and their sum E decides the two cases where
// the rounded t = fl(v * 255 + 0.5) lies on the other side of an integer than the exact
// value: t an integer with E < 0 (one lower), or E >= fl(t) + 1 - t (one higher).
// Averages of GPU-model reads sit on a 1/32-level grid, so such ties are common.
HWY_INLINE VI Quantize(VF v) {
    const DF df;
    const DI di;
    const VF c = hn::Min(hn::Max(v, hn::Zero(df)), hn::Set(df, 1.0f));
    const VF a = hn::Mul(c, hn::Set(df, 256.0f));  // exact
    const VF s = hn::Sub(a, c);                    // Fast2Sum(a, -c), |a| >= |c|
    const VF e1 = hn::Sub(hn::Neg(c), hn::Sub(s, a));
    const VF half = hn::Set(df, 0.5f);
    const VF t = hn::Add(s, half);  // TwoSum(s, 0.5)
    const VF bp = hn::Sub(t, s);
    const VF e2 = hn::Add(hn::Sub(s, hn::Sub(t, bp)), hn::Sub(half, bp));
    const VF err = hn::Add(e1, e2);  // its sign is exact
    const VF fl = hn::Floor(t);
    const VF one = hn::Set(df, 1.0f);
    const auto down = hn::And(hn::Eq(t, fl), hn::Lt(err, hn::Zero(df)));
    const auto up = hn::Ge(err, hn::Sub(hn::Add(fl, one), t));
    const VF r = hn::Add(hn::Sub(fl, hn::IfThenElseZero(down, one)), hn::IfThenElseZero(up, one));
    return hn::ConvertTo(di, r);
}

// The 3x3 luma neighbourhood of pixels [x, x + N) of row y (S = row above, N = row below).
struct NeighbourhoodV {
    VF C, W, E, S, N, SW, NW, SE, NE;
};
HWY_INLINE NeighbourhoodV LoadNeighbourhood(const float* ra, const float* rc, const float* rb, int x) {
    const DF df;
    return {hn::LoadU(df, rc + x),     hn::LoadU(df, rc + x - 1), hn::LoadU(df, rc + x + 1),
            hn::LoadU(df, ra + x),     hn::LoadU(df, rb + x),     hn::LoadU(df, ra + x - 1),
            hn::LoadU(df, rb + x - 1), hn::LoadU(df, ra + x + 1), hn::LoadU(df, rb + x + 1)};
}
HWY_INLINE NeighbourhoodV LoadNeighbourhood(const LumaRows& L, int x, int y) {
    return LoadNeighbourhood(L.row(y - 1), L.row(y), L.row(y + 1), x);
}

// edgeSides() per lane.
struct EdgeSidesV {
    hn::Mask<DF> horizontal;
    VF luma1, luma2, g1, g2;
};
HWY_INLINE EdgeSidesV EdgeSides(const NeighbourhoodV& n) {
    const DF df;
    const VF m2 = hn::Set(df, -2.0f), two = hn::Set(df, 2.0f);
    const VF edgeH = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, n.W), hn::Add(n.SW, n.NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, n.C), hn::Add(n.S, n.N))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, n.E), hn::Add(n.SE, n.NE))));
    const VF edgeV = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, n.N), hn::Add(n.NE, n.NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, n.C), hn::Add(n.W, n.E))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, n.S), hn::Add(n.SW, n.SE))));
    EdgeSidesV s;
    s.horizontal = hn::Ge(edgeH, edgeV);
    s.luma1 = hn::IfThenElse(s.horizontal, n.S, n.W);
    s.luma2 = hn::IfThenElse(s.horizontal, n.N, n.E);
    s.g1 = hn::Sub(s.luma1, n.C);
    s.g2 = hn::Sub(s.luma2, n.C);
    return s;
}

// (a < 0) != (b < 0)-style comparisons of two masks, as a mask.
HWY_INLINE hn::Mask<DF> MaskNe(hn::Mask<DF> a, hn::Mask<DF> b) {
    const DF df;
    const DI di;
    return hn::RebindMask(df, hn::Ne(hn::BitCast(di, hn::VecFromMask(df, a)), hn::BitCast(di, hn::VecFromMask(df, b))));
}

// Lanes whose early-exit flag is set.
HWY_INLINE hn::Mask<DF> ExitLanes(const std::uint8_t* exitMask, int x) {
    const DF df;
    const DI di;
    const hn::Rebind<std::uint8_t, DF> d8;
    return hn::RebindMask(df, hn::Ne(hn::PromoteTo(di, hn::LoadU(d8, exitMask + x)), hn::Zero(di)));
}

// Texture coordinate of the centres of pixels x .. x + N - 1 (Texture::centreU).
HWY_INLINE VF CentreU(const Texture& tex, int x) {
    const DF df;
    const DI di;
    return hn::Div(hn::Add(hn::ConvertTo(df, hn::Iota(di, x)), hn::Set(df, 0.5f)), hn::Set(df, float(tex.width())));
}

// The output byte toUnorm8(k / 4080) of a read of level k (the float k / 4080, rounded to
// the nearest byte): round(k / 16), exactly k 255 / 4080, except at the ties k = 16 n + 8,
// where the float quotient's rounding decides. It lies above k / 4080 for those k <= 2048
// and below for those above, so ties round up, then down. Checked for every k on every
// target against the scalar code (SimdTargets.BytesFromLevelsEqualTheFloatQuantisation).
HWY_INLINE VI ByteOfLevel(VI k) {
    const DI di;
    const VI half = hn::IfThenElse(hn::Gt(k, hn::Set(di, 2048)), hn::Set(di, 7), hn::Set(di, 8));
    return hn::ShiftRight<4>(hn::Add(k, half));
}

// The output byte toUnorm8((ka / 4080 + kb / 4080) * 0.5) of the mean of two reads, with
// the scalar code's float reads and sum s. The exact mean is S / 8160 = (S / 32) / 255,
// S = ka + kb, so the byte is round(S / 32) except at the ties S = 32 n + 16, where it is
// n + 1 when s >= S / 4080 and n otherwise. The sign of s 4096 - S - s 16 = s 4080 - S is
// exact without an FMA: s 4096 and s 16 are exact, and near a tie each subtraction takes
// numbers within a factor of 2 of each other (Sterbenz), so neither rounds. Checked for
// every pair (ka, kb) on every target (SimdTargets.BytesFromLevelsEqualTheFloatQuantisation).
HWY_INLINE VI ByteOfMeanLevel(VI ka, VI kb) {
    const DF df;
    const DI di;
    const VI sum = hn::Add(ka, kb);
    const VI roundUp = hn::ShiftRight<5>(hn::Add(sum, hn::Set(di, 16)));
    const auto tie = hn::Eq(hn::And(sum, hn::Set(di, 31)), hn::Set(di, 16));
    const VF s = hn::Add(Levels4080(ka), Levels4080(kb));
    const VF d =
        hn::Sub(hn::Sub(hn::Mul(s, hn::Set(df, 4096.0f)), hn::ConvertTo(df, sum)), hn::Mul(s, hn::Set(df, 16.0f)));
    const auto below = hn::And(hn::RebindMask(di, hn::Lt(d, hn::Zero(df))), tie);
    return hn::Sub(roundUp, hn::IfThenElseZero(below, hn::Set(di, 1)));
}

// Stores output bytes (r, g, b per lane) with the source alpha; lanes that exited keep
// the source pixel.
HWY_INLINE void StoreBytes(VI r, VI g, VI b, int x, const std::uint8_t* exitMask, const Rgba8* src, Rgba8* dst) {
    const DU du;
    const VU srcV = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(src + x));
    const VU rgb =
        hn::Or(hn::Or(hn::BitCast(du, r), hn::ShiftLeft<8>(hn::BitCast(du, g))), hn::ShiftLeft<16>(hn::BitCast(du, b)));
    const VU result = hn::Or(rgb, hn::And(srcV, hn::Set(du, 0xFF000000u)));
    hn::StoreU(hn::IfThenElse(hn::RebindMask(du, ExitLanes(exitMask, x)), srcV, result), du,
               reinterpret_cast<std::uint32_t*>(dst + x));
}

// Test hooks (src/aa/ppaa_hooks.hpp): how many levels k in [0, 4080], and how many pairs of
// levels, get a byte from ByteOfLevel / ByteOfMeanLevel other than the scalar code's
// toUnorm8 of the float reads (kSixteenthLevels[k] = k / 4080).
// Mismatches of bytes(k) against want(k) over every level k, a vector of levels at a time.
template <class Bytes, class Want>
std::int64_t LevelMismatches(const Bytes& bytes, const Want& want) {
    const DI di;
    const int n = int(hn::Lanes(di));
    std::vector<std::int32_t> got(std::size_t(n), 0);
    std::int64_t mismatches = 0;
    for (int k0 = 0; k0 <= 4080; k0 += n) {
        hn::StoreU(bytes(hn::Min(hn::Iota(di, k0), hn::Set(di, 4080))), di, got.data());
        for (int i = 0; i < n && k0 + i <= 4080; ++i) mismatches += got[std::size_t(i)] != want(k0 + i);
    }
    return mismatches;
}
inline std::int64_t LevelByteMismatches() {
    return LevelMismatches([](VI k) { return ByteOfLevel(k); },
                           [](int k) { return toUnorm8(kSixteenthLevels[std::size_t(k)]); });
}
inline std::int64_t MeanLevelByteMismatches() {
    std::int64_t mismatches = 0;
    for (int ka = 0; ka <= 4080; ++ka) {
        const float a = kSixteenthLevels[std::size_t(ka)];
        mismatches += LevelMismatches([ka](VI kb) { return ByteOfMeanLevel(hn::Set(DI(), ka), kb); },
                                      [a](int kb) { return toUnorm8((a + kSixteenthLevels[std::size_t(kb)]) * 0.5f); });
    }
    return mismatches;
}

// Runs `chunk` on the interior chunks of row y that hold at least one edge pixel and marks
// their pixels kWritten; the caller does x = 0, the tail, the exit runs and the rest.
template <class Chunk>
HWY_INLINE void RowChunks(int w, std::uint8_t* mask, const Chunk& chunk) {
    const int n = int(hn::Lanes(DF()));
    for (int x = 1; x + n <= w - 1; x += n) {
        if (skipBytes(mask, x, x + n, kExit) == x + n) continue;  // all exit: the caller copies
        chunk(x);
        std::memset(mask + x, kWritten, std::size_t(n));
    }
}

// Plane rows [r0, r1) of each luma plane, into their ring slots (layout in luma_planes.hpp). Half-way
// reads between two texels are 8 (a + b) / 4080 = (a + b) / 510 per channel, between four
// texels 4 (a + b + c + d) / 4080 = (a + b + c + d) / 1020, both exactly (same real number).
inline void LumaPlaneRows(ImageView<const Rgba8> in, const LumaPlanes& planes, int r0, int r1) {
    const DF df;
    const DU du;
    const int w = in.width(), h = in.height(), n = int(hn::Lanes(df));
    float* data = const_cast<float*>(planes.data);
    const VF wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    const ExactDivisor<DF> k510(df, 510.0f), k1020(df, 1020.0f);
    auto lumaOf = [&](VI sr, VI sg, VI sb, const ExactDivisor<DF>& k) {
        const VF r = DivExact(hn::ConvertTo(df, sr), k);
        const VF g = DivExact(hn::ConvertTo(df, sg), k);
        const VF b = DivExact(hn::ConvertTo(df, sb), k);
        return hn::Sqrt(hn::Add(hn::Add(hn::Mul(wr, r), hn::Mul(wg, g)), hn::Mul(wb, b)));
    };
    auto load = [&](const Rgba8* p) { return hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(p)); };
    auto pairV = [&](const Rgba8* a, const Rgba8* b) {
        const VU pa = load(a), pb = load(b);
        auto sum = [&](int s) { return hn::Add(TexelByte(pa, s), TexelByte(pb, s)); };
        return lumaOf(sum(0), sum(8), sum(16), k510);
    };
    auto quadV = [&](const Rgba8* a, const Rgba8* b) {  // columns c - 1, c of rows a and b
        const VU p0 = load(a), p1 = load(a + 1), p2 = load(b), p3 = load(b + 1);
        auto sum = [&](int s) {
            return hn::Add(hn::Add(TexelByte(p0, s), TexelByte(p1, s)), hn::Add(TexelByte(p2, s), TexelByte(p3, s)));
        };
        return lumaOf(sum(0), sum(8), sum(16), k1020);
    };
    auto clampRow = [h](int y) { return y < 0 ? 0 : (y >= h ? h - 1 : y); };
    for (int r = r0; r < r1; ++r) {
        // Plane H, row r: between image rows r - 1 and r (clamped).
        const Rgba8* a = in.row(clampRow(r - 1));
        const Rgba8* b = in.row(clampRow(r));
        float* out = data + planes.rowH(r);
        int x = 0;
        for (; x + n <= w; x += n) hn::StoreU(pairV(a + x, b + x), df, out + x);
        for (; x < w; ++x) out[x] = pairLuma(a[x], b[x]);
        // Plane V, row r < H: column c between image columns c - 1 and c (clamped).
        if (r < h) {
            float* v = data + planes.rowV(r);
            v[0] = pairLuma(b[0], b[0]);
            v[w] = pairLuma(b[w - 1], b[w - 1]);
            x = 0;
            for (; x + n <= w - 1; x += n) hn::StoreU(pairV(b + x, b + x + 1), df, v + 1 + x);
            for (; x < w - 1; ++x) v[1 + x] = pairLuma(b[x], b[x + 1]);
        }
        if (!planes.hasQuad()) continue;
        // Plane Q, row r: column c between columns c - 1 and c of rows r - 1 and r.
        float* q = data + planes.rowQ(r);
        q[0] = quadLuma(a[0], a[0], b[0], b[0]);
        q[w] = quadLuma(a[w - 1], a[w - 1], b[w - 1], b[w - 1]);
        int c = 1;
        for (; c - 1 + n + 1 <= w; c += n) hn::StoreU(quadV(a + c - 1, b + c - 1), df, q + c);
        for (; c < w; ++c) q[c] = quadLuma(a[c - 1], a[c], b[c - 1], b[c]);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
