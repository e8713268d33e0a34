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
#include "src/aa/ppaa_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
    const EdgeSidesV sides = EdgeSides(n);
    d.horizontal = sides.horizontal;
    d.luma1 = sides.luma1, d.luma2 = sides.luma2, d.g1 = sides.g1, d.g2 = sides.g2;

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
    const VF maxDiff = hn::Set(df, maxDiffusion);
    const VF sx = hn::Mul(hn::Mul(d.dirX, maxDiff), d.strength), sy = hn::Mul(hn::Mul(d.dirY, maxDiff), d.strength);
    const VF u = CentreU(tex, x);
    const VF v = hn::Set(df, tex.centreV(y));
    const VF dU = hn::Mul(sx, hn::Set(df, tex.invW())), dV = hn::Mul(sy, hn::Set(df, tex.invH()));
    const RgbV a = SampleGpu(tex, hn::Add(hn::Sub(u, dU), offU), hn::Add(hn::Sub(v, dV), offV));
    const RgbV b = SampleGpu(tex, hn::Add(hn::Add(u, dU), offU), hn::Add(hn::Add(v, dV), offV));
    const VF half = hn::Set(df, 0.5f);
    StoreRgb({hn::Mul(hn::Add(a.r, b.r), half), hn::Mul(hn::Add(a.g, b.g), half), hn::Mul(hn::Add(a.b, b.b), half)},
             x, exitMask, src, dst);
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
HWY_INLINE void SearchSide(const LumaPlanes& planes, const hn::Mask<DF>& horizontal, const hn::Mask<DF>& steep2,
                           int x, int y, int sign, VF first, VF gradientScaled, VF localAverage,
                           hn::Mask<DF> skip, int maxDistance, VF* distance, VF* deltaEnd) {
    const DF df;
    const DI di;
    const int w = planes.width, h = planes.height;
    (void)w;
    VF delta = first;
    auto found = hn::Ge(hn::Abs(delta), gradientScaled);
    VF dist = hn::IfThenElseZero(found, hn::Set(df, 1.0f));
    VF end = delta;
    auto done = hn::Or(found, skip);
    const VI xv = hn::Iota(di, x);
    const VI steepI = hn::IfThenElseZero(hn::RebindMask(di, steep2), hn::Set(di, 1));
    // Horizontal edges: plane H row y + steep2, column clamp(x + sign k).
    const VI rowH = hn::Add(hn::Set(di, int(planes.rowH(y))), hn::Mul(steepI, hn::Set(di, planes.width)));
    // Vertical edges: plane V column x + steep2 of row clamp(y + sign k).
    const VI colV = hn::Add(xv, steepI);
    const auto hor = hn::RebindMask(di, horizontal);
    const VI zero = hn::Zero(di), lastX = hn::Set(di, w - 1);
    for (int k = 2; k <= maxDistance && !hn::AllTrue(df, done); ++k) {
        const VI idxH = hn::Add(rowH, hn::Min(hn::Max(hn::Add(xv, hn::Set(di, sign * k)), zero), lastX));
        const int yk = std::clamp(y + sign * k, 0, h - 1);
        const VI idxV = hn::Add(colV, hn::Set(di, int(planes.rowV(yk))));
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
HWY_INLINE void Ddaa2Chunk(const Texture& tex, const ImageF& L, const LumaPlanes& planes, int x, int y,
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
    const auto skip = ExitLanes(exitMask, x);
    const int maxDistance = 3 * p.searchRounds;
    VF d1, d2, end1, end2;
    SearchSide(planes, d.horizontal, steep2, x, y, -1, hn::Sub(first1, localAverage), gradientScaled, localAverage,
               skip, maxDistance, &d1, &end1);
    SearchSide(planes, d.horizontal, steep2, x, y, +1, hn::Sub(first2, localAverage), gradientScaled, localAverage,
               skip, maxDistance, &d2, &end2);
    const VF pixelOffset = hn::Sub(half, hn::Div(hn::Min(d1, d2), hn::Add(d1, d2)));
    const VF deltaNear = hn::IfThenElse(hn::Lt(d1, d2), end1, end2);
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f);
    const auto correct = MaskNe(hn::Lt(deltaNear, zero), hn::Lt(n.C, localAverage));
    const VF across = hn::IfThenElse(steep2, one, hn::Set(df, -1.0f));
    const VF offset = hn::IfThenElseZero(correct, hn::Mul(pixelOffset, across));

    // Combination (section 2.3).
    const VF edgeStrength = hn::Min(one, hn::Mul(hn::Set(df, 2.0f), hn::Abs(offset)));
    d.strength = hn::Mul(d.strength, hn::Sub(one, edgeStrength));
    const VF offU = hn::IfThenElse(d.horizontal, zero, hn::Mul(offset, hn::Set(df, tex.invW())));
    const VF offV = hn::IfThenElse(d.horizontal, hn::Mul(offset, hn::Set(df, tex.invH())), zero);
    DiffuseAndStore(tex, d, p.maxDiffusion, offU, offV, x, y, exitMask, src, dst);
}

inline void Ddaa1RowSimd(const Texture& tex, const ImageF& L, int y, const std::uint8_t* exitMask,
                         const Ddaa1Params& p, const Rgba8* src, Rgba8* dst, std::uint8_t* handled) {
    RowChunks(L.width(), exitMask, handled, [&](int x) { Ddaa1Chunk(tex, L, x, y, exitMask, p, src, dst); });
}

inline void Ddaa2RowSimd(const Texture& tex, const ImageF& L, const LumaPlanes& planes, int y,
                         const std::uint8_t* exitMask, const Ddaa2Params& p, const Rgba8* src, Rgba8* dst,
                         std::uint8_t* handled) {
    RowChunks(L.width(), exitMask, handled,
              [&](int x) { Ddaa2Chunk(tex, L, planes, x, y, exitMask, p, src, dst); });
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
