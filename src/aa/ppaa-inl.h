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
#include "src/core/iota-inl.h"
#include "src/core/srgb_encode-inl.h"

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
using ssfx::HWY_NAMESPACE::IotaFrom;

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

// The four texels (t00 = (x0, y0), t10 = (x1, y0), t01 = (x0, y1), t11 = (x1, y1)) and the
// GPU weights of a bilinear read, per lane: what both encodings filter.
struct TexelQuad {
    VU t00, t10, t01, t11;
    VI wx, wy;
};

// The texels of a GPU-model read at (u, v) per lane (Texture::fetch), gathered.
HWY_INLINE TexelQuad GatherQuad(const Texture& tex, VF u, VF v) {
    const DI di;
    const DU du;
    const AxisV ax = SplitAxis(u, float(tex.width()), tex.width());
    const AxisV ay = SplitAxis(v, float(tex.height()), tex.height());
    const VI stride = hn::Set(di, int(tex.image().stride()));
    const VI r0 = hn::Mul(ay.i0, stride), r1 = hn::Mul(ay.i1, stride);
    const auto* base = reinterpret_cast<const std::uint32_t*>(tex.image().data());
    return {hn::GatherIndex(du, base, hn::Add(r0, ax.i0)),
            hn::GatherIndex(du, base, hn::Add(r0, ax.i1)),
            hn::GatherIndex(du, base, hn::Add(r1, ax.i0)),
            hn::GatherIndex(du, base, hn::Add(r1, ax.i1)),
            ax.w,
            ay.w};
}

// A unorm texture's read as levels (Texture::sampleGpu).
HWY_INLINE RgbK QuadLevels(const TexelQuad& q) { return ChannelLevels(q.t00, q.t10, q.t01, q.t11, q.wx, q.wy); }

// Texel byte `shift` decoded by `table` (sRGB: kSrgb8), per lane.
HWY_INLINE VF DecodeByte(VU t, int shift, const float* table) {
    return hn::GatherIndex(DF(), table, TexelByte(t, shift));
}

// An sRGB texture's read (Texture::sampleGpuDecoded) weighs the decoded texels in float by
// the same 8-bit weights, exact as floats (multiples of 1/65536), and sums in its order.
struct DecodedWeights {
    VF w00, w10, w01, w11;
};
HWY_INLINE DecodedWeights WeightsOf(VI wx, VI wy) {
    const DF df;
    const DI di;
    const VI full = hn::Set(di, 256);
    const VF unit = hn::Set(df, 1.0f / 65536.0f);
    const VI ix = hn::Sub(full, wx), iy = hn::Sub(full, wy);
    return {hn::Mul(hn::ConvertTo(df, hn::Mul(ix, iy)), unit), hn::Mul(hn::ConvertTo(df, hn::Mul(wx, iy)), unit),
            hn::Mul(hn::ConvertTo(df, hn::Mul(ix, wy)), unit), hn::Mul(hn::ConvertTo(df, hn::Mul(wx, wy)), unit)};
}
HWY_INLINE VF WeightedSum(const DecodedWeights& w, VF t00, VF t10, VF t01, VF t11) {
    return hn::Add(hn::Add(hn::Add(hn::Mul(w.w00, t00), hn::Mul(w.w10, t10)), hn::Mul(w.w01, t01)),
                   hn::Mul(w.w11, t11));
}
// The read from a quad of texels, each channel decoded by a gather from `table`.
HWY_INLINE RgbV QuadDecoded(const TexelQuad& q, const float* table) {
    const DecodedWeights w = WeightsOf(q.wx, q.wy);
    auto channel = [&](int shift) {
        return WeightedSum(w, DecodeByte(q.t00, shift, table), DecodeByte(q.t10, shift, table),
                           DecodeByte(q.t01, shift, table), DecodeByte(q.t11, shift, table));
    };
    return {channel(0), channel(8), channel(16)};
}

// Bilinear GPU-model read at (u, v) per lane (Texture::sampleGpu), as levels.
HWY_INLINE RgbK SampleGpuLevels(const Texture& tex, VF u, VF v) { return QuadLevels(GatherQuad(tex, u, v)); }

// The same as floats (Texture::sample's values, either encoding).
HWY_INLINE RgbV SampleGpu(const Texture& tex, VF u, VF v) {
    if (tex.format() == TextureFormat::Srgb) return QuadDecoded(GatherQuad(tex, u, v), tex.decodeTable());
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

// The texels of the GPU-model read at (u, v) per lane, from the 3 x 3 texels around each
// lane's pixel (row y, pixels x .. x + N - 1 with 1 <= x, x + N <= W - 1), loaded contiguously rather
// than gathered. Valid when every lane that counts (not in `skip`) reads within a texel of
// its pixel: floor(u W - 0.5) and floor(v H - 0.5) are its own column and row or the ones
// before. Otherwise returns false and writes nothing (the caller gathers). Same indices,
// clamping (rows only: columns stay inside) and weights as SampleGpu, so the same result.
// The split, and the selection of the four texels from `load(r, dx)` (row y - 1 + r clamped,
// columns x + dx ..), shared by the texels (NearQuad) and an sRGB texture's decoded
// channels (NearDecoded).
struct NearSplitXY {
    NearSplit x, y;
};
HWY_INLINE bool SplitNearXY(const Texture& tex, VF u, VF v, int x, int y, const hn::Mask<DF>& skip, NearSplitXY* s) {
    const DF df;
    const DI di;
    s->x = SplitNear(u, hn::Set(df, float(tex.width())), hn::ConvertTo(df, IotaFrom(di, x)));
    s->y = SplitNear(v, hn::Set(df, float(tex.height())), hn::Set(df, float(y)));
    return hn::AllTrue(df, hn::Or(hn::And(s->x.near, s->y.near), skip));
}
template <class D, class Load>
HWY_INLINE void SelectNear(D d, const NearSplitXY& s, const Load& load, hn::Vec<D> t[4]) {
    const auto lx = hn::RebindMask(d, s.x.before), ly = hn::RebindMask(d, s.y.before);
    hn::Vec<D> left[3], right[3];  // per row y - 1, y, y + 1: the texel pair (x0, x1) of each lane
    for (int r = 0; r < 3; ++r) {
        const hn::Vec<D> a = load(r, -1), b = load(r, 0), e = load(r, 1);
        left[r] = hn::IfThenElse(lx, a, b);
        right[r] = hn::IfThenElse(lx, b, e);
    }
    t[0] = hn::IfThenElse(ly, left[0], left[1]), t[1] = hn::IfThenElse(ly, right[0], right[1]);
    t[2] = hn::IfThenElse(ly, left[1], left[2]), t[3] = hn::IfThenElse(ly, right[1], right[2]);
}
HWY_INLINE bool NearQuad(const Texture& tex, VF u, VF v, int x, int y, const hn::Mask<DF>& skip, TexelQuad* q) {
    NearSplitXY s;
    if (!SplitNearXY(tex, u, v, x, y, skip, &s)) return false;
    const auto image = tex.image();
    const int h = tex.height();
    VU t[4];
    SelectNear(
        DU(), s,
        [&](int r, int dx) {
            const int row = std::clamp(y - 1 + r, 0, h - 1);
            return hn::LoadU(DU(), reinterpret_cast<const std::uint32_t*>(image.row(row)) + x + dx);
        },
        t);
    *q = {t[0], t[1], t[2], t[3], s.x.w, s.y.w};
    return true;
}
// The same read for an sRGB texture, from the band's decoded channel rows (LumaRows::decoded:
// float loads instead of a gather per texel and channel), summed as sampleGpuDecoded sums.
HWY_INLINE bool NearDecoded(const Texture& tex, const LumaRows& L, VF u, VF v, int x, int y, const hn::Mask<DF>& skip,
                            RgbV* c) {
    NearSplitXY s;
    if (!SplitNearXY(tex, u, v, x, y, skip, &s)) return false;
    const DecodedWeights w = WeightsOf(s.x.w, s.y.w);
    auto channel = [&](int ch) {
        VF t[4];
        SelectNear(
            DF(), s, [&](int r, int dx) { return hn::LoadU(DF(), L.decodedRow(y - 1 + r, ch) + x + dx); }, t);
        return WeightedSum(w, t[0], t[1], t[2], t[3]);
    };
    *c = {channel(0), channel(1), channel(2)};
    return true;
}

// An sRGB texture's read at (u, v) per lane (Texture::sampleGpuDecoded), from the band's
// decoded channel rows instead of texel gathers and a decode gather per texel and channel:
// each row's two texels are one 64-bit gather from a padded channel row, starting at column
// clamp(floor, -1, W - 1), which holds exactly the clamped pair (x0, x1) SplitAxis gives (the
// padding repeats the edge texels). Same weights and sums, so the same result. False, with
// nothing written, where a lane's rows are not among the band's (the caller gathers).
HWY_INLINE bool SampleDecodedRows(const Texture& tex, const LumaRows& L, VF u, VF v, RgbV* c) {
    const DF df;
    const DI di;
    const int w = tex.width();
    const AxisV ax = SplitAxis(u, float(w), w), ay = SplitAxis(v, float(tex.height()), tex.height());
    const VI first = hn::Set(di, L.first);
    if (!hn::AllTrue(di, hn::And(hn::Not(hn::Lt(ay.i0, first)), hn::Lt(ay.i1, hn::Add(first, hn::Set(di, L.count))))))
        return false;
    // ax.i0 == ax.i1 only where both are clamped to an edge: then the pair starts on the
    // padding before column 0, or on column W - 1 (whose next float is the padding after it).
    const VI one = hn::Set(di, 1);
    const VI pair = hn::IfThenElse(hn::And(hn::Eq(ax.i0, ax.i1), hn::Eq(ax.i0, hn::Zero(di))), hn::Set(di, -1), ax.i0);
    const VI stride = hn::Set(di, int(L.decodedStride()));
    // Float index of channel 0 of each row's pair: (row - first) * 3 * stride + 1 + pair.
    const VI col = hn::Add(pair, one);
    const VI at0 = hn::Add(hn::Mul(hn::Sub(ay.i0, first), hn::Mul(stride, hn::Set(di, 3))), col);
    const VI at1 = hn::Add(hn::Mul(hn::Sub(ay.i1, first), hn::Mul(stride, hn::Set(di, 3))), col);
    const DecodedWeights wt = WeightsOf(ax.w, ay.w);
    auto pairs = [&](VI at, VF* a, VF* b) {
#if HWY_TARGET == HWY_SCALAR
        *a = hn::GatherIndex(df, L.decoded, at);
        *b = hn::GatherIndex(df, L.decoded, hn::Add(at, one));
#else
        // Two gathers of 64-bit pairs (byte offsets: a pair may start at an odd float).
        const hn::Half<DI> dh;
        const hn::Rebind<std::int64_t, decltype(dh)> d64;
        const auto* base = reinterpret_cast<const std::int64_t*>(L.decoded);
        const VI bytes = hn::ShiftLeft<2>(at);
        const auto lo = hn::GatherOffset(d64, base, hn::PromoteTo(d64, hn::LowerHalf(dh, bytes)));
        const auto hi = hn::GatherOffset(d64, base, hn::PromoteTo(d64, hn::UpperHalf(dh, bytes)));
        const VF flo = hn::BitCast(df, lo), fhi = hn::BitCast(df, hi);
        *a = hn::ConcatEven(df, fhi, flo);
        *b = hn::ConcatOdd(df, fhi, flo);
#endif
    };
    VF ch[3];
    for (int k = 0; k < 3; ++k) {
        const VI offset = hn::Mul(stride, hn::Set(di, k));
        VF t00, t10, t01, t11;
        pairs(hn::Add(at0, offset), &t00, &t10);
        pairs(hn::Add(at1, offset), &t01, &t11);
        ch[k] = WeightedSum(wt, t00, t10, t01, t11);
    }
    *c = {ch[0], ch[1], ch[2]};
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

// A filtered value's output byte in its texture's encoding, per lane (toRgba8's encode8:
// toUnorm8, or encodeSrgb8 for an sRGB texture).
HWY_INLINE VI EncodeByte(VF v, bool srgb) { return srgb ? ssfx::HWY_NAMESPACE::EncodeSrgb8(DF(), v) : Quantize(v); }

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
    return hn::Div(hn::Add(hn::ConvertTo(df, IotaFrom(di, x)), hn::Set(df, 0.5f)), hn::Set(df, float(tex.width())));
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

// LumaPlaneRows for an sRGB texture: the image rows the plane rows span (r0 - 1 .. r1 - 1,
// clamped), decoded once each or read from the caller's `band` where it holds them, then
// per plane element the decoded texels weighted 1/2 (pairs) or 1/4 (quads) in
// Texture::sampleGpuDecoded's order (its zero terms add nothing): loads instead of 6 or 12
// gathers an element. A thread walking down the image asks for one plane row at a time; the
// last image row it decoded itself for the same call is its next first row, kept.
inline void LumaPlaneRowsSrgb(ImageView<const Rgba8> in, const LumaPlanes& planes, int r0, int r1,
                              const DecodedBand& band) {
    const DF df;
    const int w = in.width(), h = in.height(), n = int(hn::Lanes(df));
    float* data = const_cast<float*>(planes.data);
    const VF wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    const VF half = hn::Set(df, 0.5f), quarter = hn::Set(df, 0.25f);
    auto clampRow = [h](int y) { return y < 0 ? 0 : (y >= h ? h - 1 : y); };
    const int first = clampRow(r0 - 1), last = clampRow(r1 - 1);
    // Decoded rows first .. last not in the band, in DecodedBand's layout (channel c of a
    // row at c * cw).
    thread_local std::vector<float> decoded;
    thread_local struct {
        std::uint64_t call = 0;
        int row = -1;        // the last row decoded here for that call
        std::size_t at = 0;  // its offset in `decoded`
    } kept;
    const std::size_t cw = std::size_t(w) + 2, rowFloats = DecodedBand::rowFloats(w);
    const bool reuse =
        !band.holds(first) && kept.call == planes.call && kept.row == first && decoded.size() >= kept.at + rowFloats;
    if (reuse && kept.at != 0) std::memmove(decoded.data(), decoded.data() + kept.at, rowFloats * sizeof(float));
    decoded.resize(std::max(decoded.size(), std::size_t(last - first + 1) * rowFloats));
    for (int y = reuse ? first + 1 : first; y <= last; ++y) {
        if (band.holds(y)) continue;
        ssfx::HWY_NAMESPACE::DecodeSrgbRowPadded(in.row(y), w, decoded.data() + std::size_t(y - first) * rowFloats);
    }
    kept = {planes.call, band.holds(last) ? -1 : last, std::size_t(last - first) * rowFloats};
    auto channels = [&](int y) {
        const int row = clampRow(y);
        return band.holds(row) ? band.row(row, w) : decoded.data() + std::size_t(row - first) * rowFloats + 1;
    };
    auto luma3 = [&](VF r, VF g, VF b) {
        return hn::Sqrt(hn::Add(hn::Add(hn::Mul(wr, r), hn::Mul(wg, g)), hn::Mul(wb, b)));
    };
    // Pairs: texels at offsets a and b of two channel rows (channel c at c * cw).
    auto pairV = [&](const float* a, const float* b) {
        auto mean = [&](int c) {
            return hn::Add(hn::Mul(half, hn::LoadU(df, a + c * cw)), hn::Mul(half, hn::LoadU(df, b + c * cw)));
        };
        return luma3(mean(0), mean(1), mean(2));
    };
    auto pairS = [&](const float* a, const float* b) {
        auto mean = [&](int c) { return 0.5f * a[c * cw] + 0.5f * b[c * cw]; };
        return luma(mean(0), mean(1), mean(2));
    };
    // Quads: (x0, y0) = a[0], (x1, y0) = a[1], (x0, y1) = b[0], (x1, y1) = b[1] (quadS: the
    // four named, the edge texel twice at the borders).
    auto quadV = [&](const float* a, const float* b) {
        auto mean = [&](int c) {
            const VF t =
                hn::Add(hn::Mul(quarter, hn::LoadU(df, a + c * cw)), hn::Mul(quarter, hn::LoadU(df, a + c * cw + 1)));
            return hn::Add(hn::Add(t, hn::Mul(quarter, hn::LoadU(df, b + c * cw))),
                           hn::Mul(quarter, hn::LoadU(df, b + c * cw + 1)));
        };
        return luma3(mean(0), mean(1), mean(2));
    };
    auto quadS = [&](const float* a0, const float* a1, const float* b0, const float* b1) {
        auto mean = [&](int c) {
            return ((0.25f * a0[c * cw] + 0.25f * a1[c * cw]) + 0.25f * b0[c * cw]) + 0.25f * b1[c * cw];
        };
        return luma(mean(0), mean(1), mean(2));
    };
    for (int r = r0; r < r1; ++r) {
        const float* a = channels(r - 1);
        const float* b = channels(r);
        float* out = data + planes.rowH(r);
        int x = 0;
        for (; x + n <= w; x += n) hn::StoreU(pairV(a + x, b + x), df, out + x);
        for (; x < w; ++x) out[x] = pairS(a + x, b + x);
        if (r < h) {
            float* v = data + planes.rowV(r);
            v[0] = pairS(b, b);
            v[w] = pairS(b + w - 1, b + w - 1);
            x = 0;
            for (; x + n <= w - 1; x += n) hn::StoreU(pairV(b + x, b + x + 1), df, v + 1 + x);
            for (; x < w - 1; ++x) v[1 + x] = pairS(b + x, b + x + 1);
        }
        if (!planes.hasQuad()) continue;
        float* q = data + planes.rowQ(r);
        q[0] = quadS(a, a, b, b);
        q[w] = quadS(a + w - 1, a + w - 1, b + w - 1, b + w - 1);
        int c = 1;
        for (; c - 1 + n + 1 <= w; c += n) hn::StoreU(quadV(a + c - 1, b + c - 1), df, q + c);
        for (; c < w; ++c) q[c] = quadS(a + c - 1, a + c, b + c - 1, b + c);
    }
}

// Plane rows [r0, r1) of each luma plane, into their ring slots (layout in luma_planes.hpp). Half-way
// reads between two texels are 8 (a + b) / 4080 = (a + b) / 510 per channel, between four
// texels 4 (a + b + c + d) / 4080 = (a + b + c + d) / 1020, both exactly (same real number).
// An sRGB texture's are the decoded texels' float sums (LumaPlaneRowsSrgb).
inline void LumaPlaneRows(ImageView<const Rgba8> in, const LumaPlanes& planes, int r0, int r1,
                          const DecodedBand& band) {
    if (planes.format == TextureFormat::Srgb) return LumaPlaneRowsSrgb(in, planes, r0, r1, band);
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
