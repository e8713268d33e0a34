// Highway body of ddaa1's per-pixel kernel, across pixels: each lane is one pixel of a
// row, so a vector handles N neighbouring pixels at once (as a GPU's warp does).
//
// Exactness: every float operation is the scalar kernel's (ddaa_kernel.hpp) in the same
// order and without FMA; on a unorm texture the GPU-model bilinear reads are integer work on
// texels, and the output byte of their mean comes from their levels (ByteOfMeanLevel in
// ppaa-inl.h); on an sRGB texture they are Texture::sampleGpuDecoded's float sums.
// Only the GPU filtering model has this path; tests/properties check it equals the
// reference.
#if defined(SSFX_AA_DDAA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_DDAA_INL_H_
#undef SSFX_AA_DDAA_INL_H_
#else
#define SSFX_AA_DDAA_INL_H_
#endif

#include <hwy/highway.h>

#include "src/aa/ddaa_kernel.hpp"
#include "src/aa/ppaa-inl.h"

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
// stored with the source alpha; lanes whose exit mask is set keep the source pixel. A unorm
// texture's byte comes from the reads' levels (ByteOfMeanLevel); an sRGB texture's reads are
// its decoded floats, averaged as the scalar code does and encoded (EncodeSrgb8).
HWY_INLINE void DiffuseAndStore(const Texture& tex, const LumaRows& L, const DiffusionV& d, float maxDiffusion, VF offU,
                                VF offV, int x, int y, const std::uint8_t* exitMask, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const VF maxDiff = hn::Set(df, maxDiffusion);
    const VF sx = hn::Mul(hn::Mul(d.dirX, maxDiff), d.strength), sy = hn::Mul(hn::Mul(d.dirY, maxDiff), d.strength);
    const VF u = CentreU(tex, x);
    const VF v = hn::Set(df, tex.centreV(y));
    const VF dU = hn::Mul(sx, hn::Set(df, tex.invW())), dV = hn::Mul(sy, hn::Set(df, tex.invH()));
    const VF au = hn::Add(hn::Sub(u, dU), offU), av = hn::Add(hn::Sub(v, dV), offV);
    const VF bu = hn::Add(hn::Add(u, dU), offU), bv = hn::Add(hn::Add(v, dV), offV);
    // The reads stay within a texel of the pixel (maxDiffusion <= 1 and, in ddaa2, the
    // diffusion shrinking as the edge offset grows), so they nearly always come from the
    // pixel's 3 x 3 texels; the rest are gathered.
    const auto skip = ExitLanes(exitMask, x);
    if (tex.format() == TextureFormat::Srgb) {  // from the band's decoded rows
        RgbV a, b;
        if (!NearDecoded(tex, L, au, av, x, y, skip, &a)) a = QuadDecoded(GatherQuad(tex, au, av), tex.decodeTable());
        if (!NearDecoded(tex, L, bu, bv, x, y, skip, &b)) b = QuadDecoded(GatherQuad(tex, bu, bv), tex.decodeTable());
        const VF half = hn::Set(df, 0.5f);
        auto mean = [&](VF ca, VF cb) { return EncodeByte(hn::Mul(hn::Add(ca, cb), half), true); };
        StoreBytes(mean(a.r, b.r), mean(a.g, b.g), mean(a.b, b.b), x, exitMask, src, dst);
        return;
    }
    TexelQuad qa, qb;
    if (!NearQuad(tex, au, av, x, y, skip, &qa)) qa = GatherQuad(tex, au, av);
    if (!NearQuad(tex, bu, bv, x, y, skip, &qb)) qb = GatherQuad(tex, bu, bv);
    const RgbK a = QuadLevels(qa), b = QuadLevels(qb);
    StoreBytes(ByteOfMeanLevel(a.r, b.r), ByteOfMeanLevel(a.g, b.g), ByteOfMeanLevel(a.b, b.b), x, exitMask, src, dst);
}

// ddaa1 for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1.
HWY_INLINE void Ddaa1Chunk(const Texture& tex, const LumaRows& L, int x, int y, const std::uint8_t* exitMask,
                           const Ddaa1Params& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DiffusionV d = Diffusion(LoadNeighbourhood(L, x, y), p);
    DiffuseAndStore(tex, L, d, p.maxDiffusion, hn::Zero(df), hn::Zero(df), x, y, exitMask, src, dst);
}

// ddaa2's edge search, both sides at once, per lane (edgeSearchOffset's searchSide).
// Positions 2 .. maxDistance are read from the pair-luma planes in rounds of three
// positions per side, all six gathers of a round issued before any is used: the paper's
// "batched sampling" (section 2.5), which on a CPU hides the gathers' latency. Results
// are taken nearest first, so the outcome is the sequential one.
struct SideV {
    VF dist, end;
    hn::Mask<DF> found;
};
HWY_INLINE void SearchBothSides(const LumaPlanes& planes, const hn::Mask<DF>& horizontal, const hn::Mask<DF>& steep2,
                                int x, int y, VF first1, VF first2, VF gradientScaled, VF localAverage,
                                hn::Mask<DF> skip, int maxDistance, SideV* side1, SideV* side2) {
    const DF df;
    const DI di;
    const int h = planes.height;
    const VI xv = IotaFrom(di, x);
    const VI steepI = hn::IfThenElseZero(hn::RebindMask(di, steep2), hn::Set(di, 1));
    // Horizontal edges: plane H row y + steep2, column clamp(x + sign k).
    const VI rowH = hn::IfThenElse(hn::RebindMask(di, steep2), hn::Set(di, int(planes.rowH(y + 1))),
                                   hn::Set(di, int(planes.rowH(y))));
    // Vertical edges: plane V column x + steep2 of row clamp(y + sign k).
    const VI colV = hn::Add(xv, steepI);
    const auto hor = hn::RebindMask(di, horizontal);
    const VI zero = hn::Zero(di), lastX = hn::Set(di, planes.width - 1);
    // Every lane reads position `offset` along its edge; only the plane row (horizontal
    // edges) or column (vertical ones) differs, by steep side. Away from the left and right
    // borders that is two contiguous loads per plane; near them, a gather with clamping.
    const bool contiguous = x - maxDistance >= 0 && x + int(hn::Lanes(df)) - 1 + maxDistance <= planes.width - 1;
    auto gather = [&](int offset) {  // signed position along the edge
        const int yk = std::clamp(y + offset, 0, h - 1);
        if (contiguous) {
            const float* h0 = planes.data + planes.rowH(y) + x + offset;      // between rows y - 1 and y
            const float* h1 = planes.data + planes.rowH(y + 1) + x + offset;  // between rows y and y + 1
            const float* v0 = planes.data + planes.rowV(yk) + x;              // between columns x - 1 and x
            const VF alongH = hn::IfThenElse(steep2, hn::LoadU(df, h1), hn::LoadU(df, h0));
            const VF alongV = hn::IfThenElse(steep2, hn::LoadU(df, v0 + 1), hn::LoadU(df, v0));
            return hn::IfThenElse(horizontal, alongH, alongV);
        }
        const VI idxH = hn::Add(rowH, hn::Min(hn::Max(hn::Add(xv, hn::Set(di, offset)), zero), lastX));
        const VI idxV = hn::Add(colV, hn::Set(di, int(planes.rowV(yk))));
        return hn::GatherIndex(df, planes.data, hn::IfThenElse(hor, idxH, idxV));
    };
    auto start = [&](VF first, SideV* s) {
        const VF delta = hn::Sub(first, localAverage);
        s->found = hn::Ge(hn::Abs(delta), gradientScaled);
        s->dist = hn::IfThenElseZero(s->found, hn::Set(df, 1.0f));
        s->end = delta;
    };
    auto take = [&](VF value, int k, SideV* s) {
        const VF delta = hn::Sub(value, localAverage);
        const auto hit = hn::AndNot(s->found, hn::Ge(hn::Abs(delta), gradientScaled));
        s->dist = hn::IfThenElse(hit, hn::Set(df, float(k)), s->dist);
        s->end = hn::IfThenElse(s->found, s->end, delta);
        s->found = hn::Or(s->found, hit);
    };
    start(first1, side1);
    start(first2, side2);
    for (int k0 = 2; k0 <= maxDistance;) {
        const int k1 = std::min(k0 == 2 ? 3 : k0 + 2, maxDistance);  // round 0 has positions 2, 3
        if (hn::AllTrue(df, hn::Or(hn::And(side1->found, side2->found), skip))) break;
        VF a[3], b[3];
        for (int k = k0; k <= k1; ++k) a[k - k0] = gather(-k), b[k - k0] = gather(k);
        for (int k = k0; k <= k1; ++k) take(a[k - k0], k, side1), take(b[k - k0], k, side2);
        k0 = k1 + 1;
    }
    // Not found: distance maxDistance + 1, delta of the last read (the loop only stops
    // early when every lane is found or skipped).
    const VF notFound = hn::Set(df, float(maxDistance + 1));
    side1->dist = hn::IfThenElse(side1->found, side1->dist, notFound);
    side2->dist = hn::IfThenElse(side2->found, side2->dist, notFound);
}

// ddaa2 for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1.
HWY_INLINE void Ddaa2Chunk(const Texture& tex, const LumaRows& L, const LumaPlanes& planes, int x, int y,
                           const std::uint8_t* exitMask, const Ddaa2Params& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
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
    SideV s1, s2;
    SearchBothSides(planes, d.horizontal, steep2, x, y, first1, first2, gradientScaled, localAverage, skip,
                    3 * p.searchRounds, &s1, &s2);
    const VF d1 = s1.dist, d2 = s2.dist, end1 = s1.end, end2 = s2.end;
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
    DiffuseAndStore(tex, L, d, p.maxDiffusion, offU, offV, x, y, exitMask, src, dst);
}

inline void Ddaa1RowSimd(const Texture& tex, const LumaRows& L, int y, std::uint8_t* exitMask, const Ddaa1Params& p,
                         const Rgba8* src, Rgba8* dst) {
    RowChunks(L.width, exitMask, [&](int x) { Ddaa1Chunk(tex, L, x, y, exitMask, p, src, dst); });
}

inline void Ddaa2RowSimd(const Texture& tex, const LumaRows& L, const LumaPlanes& planes, int y, std::uint8_t* exitMask,
                         const Ddaa2Params& p, const Rgba8* src, Rgba8* dst) {
    RowChunks(L.width, exitMask, [&](int x) { Ddaa2Chunk(tex, L, planes, x, y, exitMask, p, src, dst); });
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
