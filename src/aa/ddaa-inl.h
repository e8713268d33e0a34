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

// The 3x3 luma neighbourhood of pixels [x, x + N) of row y (S = row above, N = row below).
struct NeighbourhoodV {
    VF C, W, E, S, N, SW, NW, SE, NE;
};
HWY_INLINE NeighbourhoodV LoadNeighbourhood(const ImageF& L, int x, int y) {
    const DF df;
    const int w = L.width(), h = L.height();
    const float* ra = L.data() + std::size_t(y > 0 ? y - 1 : 0) * std::size_t(w);
    const float* rc = L.data() + std::size_t(y) * std::size_t(w);
    const float* rb = L.data() + std::size_t(y + 1 < h ? y + 1 : h - 1) * std::size_t(w);
    return {hn::LoadU(df, rc + x),     hn::LoadU(df, rc + x - 1), hn::LoadU(df, rc + x + 1),
            hn::LoadU(df, ra + x),     hn::LoadU(df, rb + x),     hn::LoadU(df, ra + x - 1),
            hn::LoadU(df, rb + x - 1), hn::LoadU(df, ra + x + 1), hn::LoadU(df, rb + x + 1)};
}

// edgeSides() and diffusion() of ddaa_kernel.hpp, per lane.
struct DiffusionV {
    hn::Mask<DF> horizontal;
    VF luma1, luma2, g1, g2;
    VF dirX, dirY, strength;
};
HWY_INLINE DiffusionV Diffusion(const NeighbourhoodV& n, const Ddaa1Params& p) {
    const DF df;
    const DI di;
    DiffusionV d;
    const VF m2 = hn::Set(df, -2.0f), two = hn::Set(df, 2.0f);
    const VF edgeH = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, n.W), hn::Add(n.SW, n.NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, n.C), hn::Add(n.S, n.N))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, n.E), hn::Add(n.SE, n.NE))));
    const VF edgeV = hn::Add(hn::Add(hn::Abs(hn::Add(hn::Mul(m2, n.N), hn::Add(n.NE, n.NW))),
                                     hn::Mul(hn::Abs(hn::Add(hn::Mul(m2, n.C), hn::Add(n.W, n.E))), two)),
                             hn::Abs(hn::Add(hn::Mul(m2, n.S), hn::Add(n.SW, n.SE))));
    d.horizontal = hn::Ge(edgeH, edgeV);
    d.luma1 = hn::IfThenElse(d.horizontal, n.S, n.W);
    d.luma2 = hn::IfThenElse(d.horizontal, n.N, n.E);
    d.g1 = hn::Sub(d.luma1, n.C);
    d.g2 = hn::Sub(d.luma2, n.C);

    const VF k1 = hn::Set(df, 162.0f / 256.0f), k2 = hn::Set(df, 47.0f / 256.0f);
    const VF Dx = hn::Sub(hn::Add(hn::Add(hn::Mul(n.W, k1), hn::Mul(n.SW, k2)), hn::Mul(n.NW, k2)),
                          hn::Add(hn::Add(hn::Mul(n.E, k1), hn::Mul(n.SE, k2)), hn::Mul(n.NE, k2)));
    const VF Dy = hn::Sub(hn::Add(hn::Add(hn::Mul(n.S, k1), hn::Mul(n.SW, k2)), hn::Mul(n.SE, k2)),
                          hn::Add(hn::Add(hn::Mul(n.N, k1), hn::Mul(n.NW, k2)), hn::Mul(n.NE, k2)));
    const VF ex = hn::Neg(Dy), ey = Dx;
    const VF len = hn::Sqrt(hn::Add(hn::Mul(ex, ex), hn::Mul(ey, ey)));
    const VF raw = hn::Mul(hn::Set(df, p.strength), hn::Sqrt(len));
    const auto valid = hn::Not(hn::Lt(raw, hn::Set(df, 1e-6f)));
    const VF one = hn::Set(df, 1.0f), zero = hn::Zero(df);
    d.strength = hn::IfThenElseZero(valid, hn::Min(one, raw));
    d.dirX = hn::IfThenElseZero(valid, hn::Div(ex, len));
    d.dirY = hn::IfThenElseZero(valid, hn::Div(ey, len));
    const auto sameSign = hn::RebindMask(df, hn::Eq(hn::BitCast(di, hn::VecFromMask(df, hn::Gt(d.g1, zero))),
                                                    hn::BitCast(di, hn::VecFromMask(df, hn::Gt(d.g2, zero)))));
    const VF ridge =
        hn::Sub(one, hn::Min(one, hn::Mul(hn::Set(df, p.ridgeFactor), hn::Min(hn::Abs(d.g1), hn::Abs(d.g2)))));
    d.strength = hn::IfThenElse(sameSign, hn::Mul(d.strength, ridge), d.strength);
    return d;
}

// diffuse(): the average of two reads at centre -/+ step + (offU, offV), quantised and
// stored with the source alpha; lanes whose exit mask is set keep the source pixel.
HWY_INLINE void DiffuseAndStore(const Texture& tex, const DiffusionV& d, float maxDiffusion, VF offU, VF offV, int x,
                                int y, const std::uint8_t* exitMask, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DI di;
    const DU du;
    const hn::Rebind<std::uint8_t, DF> d8;
    const VF maxDiff = hn::Set(df, maxDiffusion);
    const VF sx = hn::Mul(hn::Mul(d.dirX, maxDiff), d.strength), sy = hn::Mul(hn::Mul(d.dirY, maxDiff), d.strength);
    const VF u = hn::Div(hn::Add(hn::ConvertTo(df, hn::Iota(di, x)), hn::Set(df, 0.5f)),
                         hn::Set(df, float(tex.width())));
    const VF v = hn::Set(df, tex.centreV(y));
    const VF dU = hn::Mul(sx, hn::Set(df, tex.invW())), dV = hn::Mul(sy, hn::Set(df, tex.invH()));
    const RgbV a = SampleGpu(tex, hn::Add(hn::Sub(u, dU), offU), hn::Add(hn::Sub(v, dV), offV));
    const RgbV b = SampleGpu(tex, hn::Add(hn::Add(u, dU), offU), hn::Add(hn::Add(v, dV), offV));
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

// ddaa1 for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1.
HWY_INLINE void Ddaa1Chunk(const Texture& tex, const ImageF& L, int x, int y, const std::uint8_t* exitMask,
                           const Ddaa1Params& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DiffusionV d = Diffusion(LoadNeighbourhood(L, x, y), p);
    DiffuseAndStore(tex, d, p.maxDiffusion, hn::Zero(df), hn::Zero(df), x, y, exitMask, src, dst);
}

// ddaa2's edge search for one side, per lane (edgeSearchOffset's searchSide): positions 2..
// maxDistance read from the pair-luma planes (see PairLumaPlanes). Returns the distance
// (maxDistance + 1 if not found) and the delta at the end (or at the last read).
HWY_INLINE void SearchSide(const PairPlanes& planes, const hn::Mask<DF>& horizontal, const hn::Mask<DF>& steep2,
                           int x, int y, int sign, VF first, VF gradientScaled, VF localAverage,
                           hn::Mask<DF> skip, int maxDistance, VF* distance, VF* deltaEnd) {
    const DF df;
    const DI di;
    const int w = planes.width, h = planes.height;
    VF delta = first;
    auto found = hn::Ge(hn::Abs(delta), gradientScaled);
    VF dist = hn::IfThenElseZero(found, hn::Set(df, 1.0f));
    VF end = delta;
    auto done = hn::Or(found, skip);
    const VI xv = hn::Iota(di, x);
    const VI steepI = hn::IfThenElseZero(hn::RebindMask(di, steep2), hn::Set(di, 1));
    // Horizontal edges: plane H row y + steep2, column clamp(x + sign k).
    const VI rowH = hn::Mul(hn::Add(hn::Set(di, y), steepI), hn::Set(di, w));
    // Vertical edges: plane V column x + steep2 of row clamp(y + sign k).
    const VI colV = hn::Add(hn::Add(xv, steepI), hn::Set(di, planes.offsetV));
    const auto hor = hn::RebindMask(di, horizontal);
    const VI zero = hn::Zero(di), lastX = hn::Set(di, w - 1);
    for (int k = 2; k <= maxDistance && !hn::AllTrue(df, done); ++k) {
        const VI idxH = hn::Add(rowH, hn::Min(hn::Max(hn::Add(xv, hn::Set(di, sign * k)), zero), lastX));
        const int yk = std::clamp(y + sign * k, 0, h - 1);
        const VI idxV = hn::Add(colV, hn::Set(di, yk * (w + 1)));
        const VF val = hn::GatherIndex(df, planes.data, hn::IfThenElse(hor, idxH, idxV));
        delta = hn::Sub(val, localAverage);
        const auto hit = hn::AndNot(found, hn::Ge(hn::Abs(delta), gradientScaled));
        dist = hn::IfThenElse(hit, hn::Set(df, float(k)), dist);
        end = hn::IfThenElse(found, end, delta);
        found = hn::Or(found, hit);
        done = hn::Or(done, hit);
    }
    // Lanes that stopped early because every lane was done keep their values; lanes that
    // never found an end read up to maxDistance (the loop only ends early when all are done).
    *distance = hn::IfThenElse(found, dist, hn::Set(df, float(maxDistance + 1)));
    *deltaEnd = end;
}

// ddaa2 for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1.
HWY_INLINE void Ddaa2Chunk(const Texture& tex, const ImageF& L, const PairPlanes& planes, int x, int y,
                           const std::uint8_t* exitMask, const Ddaa2Params& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DI di;
    const hn::Rebind<std::uint8_t, DF> d8;
    const NeighbourhoodV n = LoadNeighbourhood(L, x, y);
    DiffusionV d = Diffusion(n, p);

    // edgeSearchOffset()
    const auto steep2 = hn::Gt(hn::Abs(d.g2), hn::Abs(d.g1));
    const VF lumaSteep = hn::IfThenElse(steep2, d.luma2, d.luma1);
    const VF gradientScaled = hn::Mul(hn::Set(df, 0.25f), hn::Max(hn::Abs(d.g1), hn::Abs(d.g2)));
    const VF half = hn::Set(df, 0.5f);
    const VF localAverage = hn::Mul(hn::Add(lumaSteep, n.C), half);
    const VF first1 = hn::IfThenElse(d.horizontal, hn::Mul(hn::Add(n.W, hn::IfThenElse(steep2, n.NW, n.SW)), half),
                                     hn::Mul(hn::Add(n.S, hn::IfThenElse(steep2, n.SE, n.SW)), half));
    const VF first2 = hn::IfThenElse(d.horizontal, hn::Mul(hn::Add(n.E, hn::IfThenElse(steep2, n.NE, n.SE)), half),
                                     hn::Mul(hn::Add(n.N, hn::IfThenElse(steep2, n.NE, n.NW)), half));
    const auto skip = hn::RebindMask(df, hn::Ne(hn::PromoteTo(di, hn::LoadU(d8, exitMask + x)), hn::Zero(di)));
    const int maxDistance = 3 * p.searchRounds;
    VF d1, d2, end1, end2;
    SearchSide(planes, d.horizontal, steep2, x, y, -1, hn::Sub(first1, localAverage), gradientScaled, localAverage,
               skip, maxDistance, &d1, &end1);
    SearchSide(planes, d.horizontal, steep2, x, y, +1, hn::Sub(first2, localAverage), gradientScaled, localAverage,
               skip, maxDistance, &d2, &end2);
    const VF pixelOffset = hn::Sub(half, hn::Div(hn::Min(d1, d2), hn::Add(d1, d2)));
    const VF deltaNear = hn::IfThenElse(hn::Lt(d1, d2), end1, end2);
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
    const auto correct = hn::RebindMask(
        df, hn::Ne(hn::BitCast(di, hn::VecFromMask(df, hn::Lt(deltaNear, zero))),
                   hn::BitCast(di, hn::VecFromMask(df, hn::Lt(n.C, localAverage)))));
    const VF across = hn::IfThenElse(steep2, one, hn::Set(df, -1.0f));
    const VF offset = hn::IfThenElseZero(correct, hn::Mul(pixelOffset, across));

    // Combination (section 2.3).
    const VF edgeStrength = hn::Min(one, hn::Mul(hn::Set(df, 2.0f), hn::Abs(offset)));
    d.strength = hn::Mul(d.strength, hn::Sub(one, edgeStrength));
    const VF offU = hn::IfThenElse(d.horizontal, zero, hn::Mul(offset, hn::Set(df, tex.invW())));
    const VF offV = hn::IfThenElse(d.horizontal, hn::Mul(offset, hn::Set(df, tex.invH())), zero);
    DiffuseAndStore(tex, d, p.maxDiffusion, offU, offV, x, y, exitMask, src, dst);
}

// Runs `chunk` on the interior chunks of row y that hold at least one edge pixel and marks
// their pixels in `handled`; the caller does x = 0, the tail and the exit pixels.
template <class Chunk>
HWY_INLINE void RowChunks(int w, const std::uint8_t* exitMask, std::uint8_t* handled, const Chunk& chunk) {
    const int n = int(hn::Lanes(DF()));
    for (int x = 1; x + n <= w - 1; x += n) {
        bool any = false;
        for (int i = 0; i < n; ++i) any |= exitMask[x + i] == 0;
        if (!any) continue;  // the caller copies exit pixels
        chunk(x);
        for (int i = 0; i < n; ++i) handled[x + i] = 1;
    }
}

inline void Ddaa1RowSimd(const Texture& tex, const ImageF& L, int y, const std::uint8_t* exitMask,
                         const Ddaa1Params& p, const Rgba8* src, Rgba8* dst, std::uint8_t* handled) {
    RowChunks(L.width(), exitMask, handled, [&](int x) { Ddaa1Chunk(tex, L, x, y, exitMask, p, src, dst); });
}

inline void Ddaa2RowSimd(const Texture& tex, const ImageF& L, const PairPlanes& planes, int y,
                         const std::uint8_t* exitMask, const Ddaa2Params& p, const Rgba8* src, Rgba8* dst,
                         std::uint8_t* handled) {
    RowChunks(L.width(), exitMask, handled,
              [&](int x) { Ddaa2Chunk(tex, L, planes, x, y, exitMask, p, src, dst); });
}

// Pair-luma planes for rows [y0, y1): plane H row y + 1 holds, for each column, the luma
// of the GPU-model read half-way between image rows y and y + 1 (8 (a + b) / 4080 per
// channel = (a + b) / 510, exactly); row 0 and row H are the clamped rows 0 and H - 1.
// Plane V (width W + 1) likewise between columns x - 1 and x.
inline void PairLumaRows(ImageView<const Rgba8> in, const ImageF& L, int y0, int y1, float* data, int offsetV) {
    const DF df;
    const DI di;
    const DU du;
    const int w = in.width(), h = in.height(), n = int(hn::Lanes(df));
    const VU mask = hn::Set(du, 0xFFu);
    const VF k510 = hn::Set(df, 510.0f);
    const VF wr = hn::Set(df, 0.299f), wg = hn::Set(df, 0.587f), wb = hn::Set(df, 0.114f);
    auto pairLumaV = [&](const Rgba8* a, const Rgba8* b) {
        const VU pa = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(a));
        const VU pb = hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(b));
        auto ch = [&](int shift) {
            const VU sum = hn::Add(hn::And(hn::ShiftRightSame(pa, shift), mask), hn::And(hn::ShiftRightSame(pb, shift), mask));
            return hn::Div(hn::ConvertTo(df, hn::BitCast(di, sum)), k510);
        };
        return hn::Sqrt(hn::Add(hn::Add(hn::Mul(wr, ch(0)), hn::Mul(wg, ch(8))), hn::Mul(wb, ch(16))));
    };
    for (int y = y0; y < y1; ++y) {
        const float* lrow = L.data() + std::size_t(y) * std::size_t(w);
        // Plane H, row y + 1 (and row 0 from the first image row).
        float* hrow = data + std::size_t(y + 1) * std::size_t(w);
        if (y == 0) std::copy(lrow, lrow + w, data);
        if (y + 1 < h) {
            const Rgba8* a = in.row(y);
            const Rgba8* b = in.row(y + 1);
            int x = 0;
            for (; x + n <= w; x += n) hn::StoreU(pairLumaV(a + x, b + x), df, hrow + x);
            for (; x < w; ++x) hrow[x] = pairLuma(a[x], b[x]);
        } else {
            std::copy(lrow, lrow + w, hrow);
        }
        // Plane V, row y: column c is between image columns c - 1 and c.
        float* vrow = data + std::size_t(offsetV) + std::size_t(y) * std::size_t(w + 1);
        const Rgba8* r = in.row(y);
        vrow[0] = lrow[0];
        vrow[w] = lrow[w - 1];
        int x = 0;
        for (; x + n <= w - 1; x += n) hn::StoreU(pairLumaV(r + x, r + x + 1), df, vrow + 1 + x);
        for (; x < w - 1; ++x) vrow[1 + x] = pairLuma(r[x], r[x + 1]);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
