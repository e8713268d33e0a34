// Highway body of ddaa1's per-pixel kernel, across pixels: each lane is one pixel of a
// row, so a vector handles N neighbouring pixels at once (as a GPU's warp does).
//
// Exactness: every float operation is the scalar kernel's (ddaa_kernel.hpp) in the same
// order and without FMA; the GPU-model bilinear reads are integer work on gathered
// texels, divided by 4080 exactly (IEEE division = the kSixteenthLevels table). Only the
// GPU filtering model has this path; tests/properties check it equals the reference.
#if defined(SSFX_AA_DDAA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_DDAA_INL_H_
#undef SSFX_AA_DDAA_INL_H_
#else
#define SSFX_AA_DDAA_INL_H_
#endif

#include <hwy/highway.h>

#include "src/aa/ddaa_kernel.hpp"

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

// k = (sum + 2048) >> 12 of one channel (byte `shift` of each texel), as a float k / 4080.
HWY_INLINE VF Channel(VU t00, VU t10, VU t01, VU t11, VI w00, VI w10, VI w01, VI w11, int shift) {
    const DF df;
    const DI di;
    const VU mask = hn::Set(DU(), 0xFFu);
    auto byte = [&](VU t) { return hn::BitCast(di, hn::And(hn::ShiftRightSame(t, shift), mask)); };
    const VI sum = hn::Add(hn::Add(hn::Add(hn::Mul(w00, byte(t00)), hn::Mul(w10, byte(t10))), hn::Mul(w01, byte(t01))),
                           hn::Mul(w11, byte(t11)));
    const VI k = hn::ShiftRight<12>(hn::Add(sum, hn::Set(di, 2048)));
    return hn::Div(hn::ConvertTo(df, k), hn::Set(df, 4080.0f));
}

// Bilinear GPU-model read at (u, v) per lane (Texture::sampleGpu).
HWY_INLINE RgbV SampleGpu(const Texture& tex, VF u, VF v) {
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
    const VI k256 = hn::Set(di, 256);
    const VI nx = hn::Sub(k256, ax.w), ny = hn::Sub(k256, ay.w);
    const VI w00 = hn::Mul(nx, ny), w10 = hn::Mul(ax.w, ny), w01 = hn::Mul(nx, ay.w), w11 = hn::Mul(ax.w, ay.w);
    return {Channel(t00, t10, t01, t11, w00, w10, w01, w11, 0), Channel(t00, t10, t01, t11, w00, w10, w01, w11, 8),
            Channel(t00, t10, t01, t11, w00, w10, w01, w11, 16)};
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
    const VF s = hn::Sub(a, c);                      // Fast2Sum(a, -c), |a| >= |c|
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

// ddaa1 for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1. Lanes whose exit mask is
// set keep the source pixel.
HWY_INLINE void Ddaa1Chunk(const Texture& tex, const ImageF& L, int x, int y, const std::uint8_t* exitMask,
                           const Ddaa1Params& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DI di;
    const DU du;
    const hn::Rebind<std::uint8_t, DF> d8;
    const int w = L.width(), h = L.height();
    const float* ra = L.data() + std::size_t(y > 0 ? y - 1 : 0) * std::size_t(w);
    const float* rc = L.data() + std::size_t(y) * std::size_t(w);
    const float* rb = L.data() + std::size_t(y + 1 < h ? y + 1 : h - 1) * std::size_t(w);
    // Neighbourhood (names as in the spec: S = row above, N = row below).
    const VF C = hn::LoadU(df, rc + x), W = hn::LoadU(df, rc + x - 1), E = hn::LoadU(df, rc + x + 1);
    const VF S = hn::LoadU(df, ra + x), SW = hn::LoadU(df, ra + x - 1), SE = hn::LoadU(df, ra + x + 1);
    const VF N = hn::LoadU(df, rb + x), NW = hn::LoadU(df, rb + x - 1), NE = hn::LoadU(df, rb + x + 1);

    // edgeSides()
    const VF m2 = hn::Set(df, -2.0f), two = hn::Set(df, 2.0f);
    const VF edgeH = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, W), hn::Add(SW, NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, C), hn::Add(S, N))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, E), hn::Add(SE, NE))));
    const VF edgeV = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, N), hn::Add(NE, NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, C), hn::Add(W, E))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, S), hn::Add(SW, SE))));
    const auto horizontal = hn::Ge(edgeH, edgeV);
    const VF g1 = hn::Sub(hn::IfThenElse(horizontal, S, W), C);
    const VF g2 = hn::Sub(hn::IfThenElse(horizontal, N, E), C);

    // diffusion()
    const VF k1 = hn::Set(df, 162.0f / 256.0f), k2 = hn::Set(df, 47.0f / 256.0f);
    const VF Dx = hn::Sub(hn::Add(hn::Add(hn::Mul(W, k1), hn::Mul(SW, k2)), hn::Mul(NW, k2)),
                          hn::Add(hn::Add(hn::Mul(E, k1), hn::Mul(SE, k2)), hn::Mul(NE, k2)));
    const VF Dy = hn::Sub(hn::Add(hn::Add(hn::Mul(S, k1), hn::Mul(SW, k2)), hn::Mul(SE, k2)),
                          hn::Add(hn::Add(hn::Mul(N, k1), hn::Mul(NW, k2)), hn::Mul(NE, k2)));
    const VF ex = hn::Neg(Dy), ey = Dx;
    const VF len = hn::Sqrt(hn::Add(hn::Mul(ex, ex), hn::Mul(ey, ey)));
    const VF raw = hn::Mul(hn::Set(df, p.strength), hn::Sqrt(len));
    const auto valid = hn::Not(hn::Lt(raw, hn::Set(df, 1e-6f)));
    const VF one = hn::Set(df, 1.0f);
    VF strength = hn::IfThenElseZero(valid, hn::Min(one, raw));
    const VF dirX = hn::IfThenElseZero(valid, hn::Div(ex, len));
    const VF dirY = hn::IfThenElseZero(valid, hn::Div(ey, len));
    const VF zero = hn::Zero(df);
    const auto sameSign = hn::RebindMask(
        df, hn::Eq(hn::BitCast(di, hn::VecFromMask(df, hn::Gt(g1, zero))),
                   hn::BitCast(di, hn::VecFromMask(df, hn::Gt(g2, zero)))));
    const VF ridge = hn::Sub(one, hn::Min(one, hn::Mul(hn::Set(df, p.ridgeFactor), hn::Min(hn::Abs(g1), hn::Abs(g2)))));
    strength = hn::IfThenElse(sameSign, hn::Mul(strength, ridge), strength);

    // diffuse(): two reads at centre -/+ step.
    const VF maxDiff = hn::Set(df, p.maxDiffusion);
    const VF sx = hn::Mul(hn::Mul(dirX, maxDiff), strength), sy = hn::Mul(hn::Mul(dirY, maxDiff), strength);
    const VF u = hn::Div(hn::Add(hn::ConvertTo(df, hn::Iota(di, x)), hn::Set(df, 0.5f)),
                         hn::Set(df, float(tex.width())));
    const VF v = hn::Set(df, tex.centreV(y));
    const VF dU = hn::Mul(sx, hn::Set(df, tex.invW())), dV = hn::Mul(sy, hn::Set(df, tex.invH()));
    const RgbV a = SampleGpu(tex, hn::Add(hn::Sub(u, dU), zero), hn::Add(hn::Sub(v, dV), zero));
    const RgbV b = SampleGpu(tex, hn::Add(hn::Add(u, dU), zero), hn::Add(hn::Add(v, dV), zero));
    const VF half = hn::Set(df, 0.5f);
    const VI qr = Quantize(hn::Mul(hn::Add(a.r, b.r), half));
    const VI qg = Quantize(hn::Mul(hn::Add(a.g, b.g), half));
    const VI qb = Quantize(hn::Mul(hn::Add(a.b, b.b), half));

    const VU srcV = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(src + x));
    const VU rgb = hn::Or(hn::Or(hn::BitCast(du, qr), hn::ShiftLeft<8>(hn::BitCast(du, qg))),
                          hn::ShiftLeft<16>(hn::BitCast(du, qb)));
    const VU result = hn::Or(rgb, hn::And(srcV, hn::Set(du, 0xFF000000u)));
    const auto keep = hn::RebindMask(du, hn::Ne(hn::PromoteTo(di, hn::LoadU(d8, exitMask + x)), hn::Zero(di)));
    hn::StoreU(hn::IfThenElse(keep, srcV, result), du, reinterpret_cast<std::uint32_t*>(dst + x));
}

// Processes the interior chunks of row y that contain at least one edge pixel; returns the
// first x not handled (the caller finishes [that, W) and x = 0 with the scalar kernel).
// handled[x] is set to 1 for pixels written here.
inline int Ddaa1RowSimd(const Texture& tex, const ImageF& L, int y, const std::uint8_t* exitMask,
                        const Ddaa1Params& p, const Rgba8* src, Rgba8* dst, std::uint8_t* handled) {
    const int n = int(hn::Lanes(DF()));
    const int w = L.width();
    int x = 1;
    for (; x + n <= w - 1; x += n) {
        bool any = false;
        for (int i = 0; i < n; ++i) any |= exitMask[x + i] == 0;
        if (!any) continue;  // the caller copies exit pixels
        Ddaa1Chunk(tex, L, x, y, exitMask, p, src, dst);
        for (int i = 0; i < n; ++i) handled[x + i] = 1;
    }
    return x;
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
