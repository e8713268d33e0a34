// Highway body of fxaa3d's per-pixel kernel across pixels (see fxaa3d.cpp for the scalar
// oracle, fxaa3dPixel). The walk keeps the scalar's float coordinates lane by lane, so the
// distances are bit-identical; its reads come from the luma planes (pair planes at whole-
// texel positions, the quad plane at the half-texel ones), which fxaa3d.cpp proves equal
// to the GPU-model reads for the image size before taking this path.
#if defined(SSFX_AA_FXAA3D_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AA_FXAA3D_INL_H_
#undef SSFX_AA_FXAA3D_INL_H_
#else
#define SSFX_AA_FXAA3D_INL_H_
#endif

#include <hwy/highway.h>

#include "src/aa/ppaa-inl.h"
#include "ssfx/aa/fxaa.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::aa::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Steps of the walk in half pixels (2 x FXAA_QUALITY__P0..P11 = 1, 1, 1, 1, 1, 1.5, 2, 2, 2, 2, 4, 8).
constexpr int kHalfSteps[12] = {2, 2, 2, 2, 2, 3, 4, 4, 4, 4, 8, 16};
constexpr float kFxaaSteps[12] = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f};

// Plane index of the read `hs` half pixels along the edge from pixels x.. of row y, half a
// pixel across towards the steep side (acrossH: plane row for horizontal edges, acrossV:
// plane column for vertical ones).
HWY_INLINE VI WalkIndex(const LumaPlanes& planes, const hn::Mask<DI>& horizontal, VI xv, int y, VI hs, VI acrossH,
                        VI acrossV) {
    const DI di;
    const VI one = hn::Set(di, 1), zero = hn::Zero(di);
    const VI wq = hn::Set(di, planes.width + 1);
    const auto even = hn::Eq(hn::And(hs, one), zero);
    const VI whole = hn::ShiftRight<1>(hs);                // hs / 2 for even hs
    const VI upper = hn::ShiftRight<1>(hn::Add(hs, one));  // (hs + 1) / 2 for odd hs
    // Plane rows to ring slots (rows are never negative: clamped, or y and y + 1).
    const VI ringMask = hn::Set(di, planes.ringMask);
    auto slot = [&](VI r) { return hn::And(r, ringMask); };
    const VI baseV = hn::Set(di, int(planes.sizeH())), baseQ = hn::Set(di, int(planes.sizeH() + planes.sizeV()));
    const VI rowH = slot(acrossH);
    // Horizontal edges: along x.
    const VI hEven = hn::Add(hn::Mul(rowH, hn::Set(di, planes.width)),
                             hn::Min(hn::Max(hn::Add(xv, whole), zero), hn::Set(di, planes.width - 1)));
    const VI hOdd = hn::Add(hn::Add(baseQ, hn::Mul(rowH, wq)),
                            hn::Min(hn::Max(hn::Add(xv, upper), zero), hn::Set(di, planes.width)));
    // Vertical edges: along y.
    const VI yv = hn::Set(di, y);
    const VI vEven = hn::Add(
        hn::Add(baseV, hn::Mul(slot(hn::Min(hn::Max(hn::Add(yv, whole), zero), hn::Set(di, planes.height - 1))), wq)),
        acrossV);
    const VI vOdd = hn::Add(
        hn::Add(baseQ, hn::Mul(slot(hn::Min(hn::Max(hn::Add(yv, upper), zero), hn::Set(di, planes.height))), wq)),
        acrossV);
    return hn::IfThenElse(horizontal, hn::IfThenElse(even, hEven, hOdd), hn::IfThenElse(even, vEven, vOdd));
}

// fxaa3d's final read, at the pixel's centre along the edge and `across` (a texture
// coordinate) across it, when pixel centres are texels (centresAreTexels): the GPU model's
// lerp between the two texels across the edge around the read, from contiguous loads of rows
// y - 1, y, y + 1 (clamped) and columns x - 1, x, x + 1 instead of four gathers. Returns
// false, writing nothing, when a lane that counts reads further than one texel before its
// own (then the caller gathers). Otherwise gives the output bytes:
//  - unorm: the bilinear sum with along-weight 0 is 256 ((256 - w) a + w b) for the texel
//    pair (a, b) and b's weight w, so the read's level is ((256 - w) a + w b + 8) >> 4;
//  - sRGB: from the band's decoded rows, the two non-zero terms of sampleGpuDecoded's sum
//    (the zero terms add nothing), weights (256 - w) 256 / 65536 and w 256 / 65536, exact
//    as floats (a sum of two terms is the same in either order), encoded.
HWY_INLINE bool AcrossBytes(const Texture& tex, const LumaRows& L, const hn::Mask<DF>& horizontal, VF across, int x,
                            int y, const hn::Mask<DF>& skip, RgbK* bytes) {
    const DF df;
    const DI di;
    const DU du;
    const VF size = hn::IfThenElse(horizontal, hn::Set(df, float(tex.height())), hn::Set(df, float(tex.width())));
    const VF own = hn::IfThenElse(horizontal, hn::Set(df, float(y)), hn::ConvertTo(df, IotaFrom(di, x)));
    const NearSplit s = SplitNear(across, size, own);
    if (!hn::AllTrue(df, hn::Or(s.near, skip))) return false;
    // The pair (a, b) from `load(dy, dx)` (the texel or value at (x + dx, y + dy), rows clamped).
    auto select = [&](auto d, const auto& load, auto* a, auto* b) {
        const auto hor = hn::RebindMask(d, horizontal), lo = hn::RebindMask(d, s.before);
        const auto centre = load(0, 0);
        *a = hn::IfThenElse(lo, hn::IfThenElse(hor, load(-1, 0), load(0, -1)), centre);
        *b = hn::IfThenElse(lo, centre, hn::IfThenElse(hor, load(1, 0), load(0, 1)));
    };
    if (tex.format() == TextureFormat::Srgb) {
        const VF unit = hn::Set(df, 1.0f / 256.0f);
        const VF wb = hn::Mul(hn::ConvertTo(df, s.w), unit);
        const VF wa = hn::Mul(hn::ConvertTo(df, hn::Sub(hn::Set(di, 256), s.w)), unit);
        auto channel = [&](int ch) {
            VF a, b;
            select(
                df, [&](int dy, int dx) { return hn::LoadU(df, L.decodedRow(y + dy, ch) + x + dx); }, &a, &b);
            return EncodeByte(hn::Add(hn::Mul(wa, a), hn::Mul(wb, b)), true);
        };
        *bytes = {channel(0), channel(1), channel(2)};
        return true;
    }
    const auto image = tex.image();
    const int h = tex.height();
    VU a, b;
    select(
        du,
        [&](int dy, int dx) {
            const int r = std::clamp(y + dy, 0, h - 1);
            return hn::LoadU(du, reinterpret_cast<const std::uint32_t*>(image.row(r)) + x + dx);
        },
        &a, &b);
    auto channel = [&](int shift) {
        const VI sum = Lerp256(TexelByte(a, shift), TexelByte(b, shift), s.w);
        return ByteOfLevel(hn::ShiftRight<4>(hn::Add(sum, hn::Set(di, 8))));
    };
    *bytes = {channel(0), channel(8), channel(16)};
    return true;
}

// The output bytes of a gathered read.
HWY_INLINE RgbK ReadBytes(const Texture& tex, VF u, VF v) {
    const TexelQuad q = GatherQuad(tex, u, v);
    if (tex.format() == TextureFormat::Srgb) {
        const RgbV c = QuadDecoded(q, tex.decodeTable());
        return {EncodeByte(c.r, true), EncodeByte(c.g, true), EncodeByte(c.b, true)};
    }
    const RgbK k = QuadLevels(q);
    return {ByteOfLevel(k.r), ByteOfLevel(k.g), ByteOfLevel(k.b)};
}

// fxaa3d for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1.
HWY_INLINE void Fxaa3dChunk(const Texture& tex, const LumaRows& L, const LumaPlanes& planes, bool lerp, int x, int y,
                            const std::uint8_t* exitMask, const Fxaa3dParams& p, const Rgba8* src, Rgba8* dst) {
    const DF df;
    const DI di;
    const NeighbourhoodV n = LoadNeighbourhood(L, x, y);
    const EdgeSidesV s = EdgeSides(n);
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), half = hn::Set(df, 0.5f);
    const VF lumaMax = hn::Max(hn::Max(hn::Max(n.S, n.N), hn::Max(n.W, n.E)), n.C);
    const VF lumaMin = hn::Min(hn::Min(hn::Min(n.S, n.N), hn::Min(n.W, n.E)), n.C);
    const VF range = hn::Sub(lumaMax, lumaMin);

    const auto pair1 = hn::Ge(hn::Abs(s.g1), hn::Abs(s.g2));
    const VF lumaSteep = hn::IfThenElse(pair1, s.luma1, s.luma2);
    const VF gradientScaled = hn::Mul(hn::Set(df, 0.25f), hn::Max(hn::Abs(s.g1), hn::Abs(s.g2)));
    const VF localAverage = hn::Mul(hn::Add(lumaSteep, n.C), half);
    const VF base = hn::IfThenElse(s.horizontal, hn::Set(df, tex.invH()), hn::Set(df, tex.invW()));
    const VF lengthSign = hn::IfThenElse(pair1, hn::Neg(base), base);

    // Along-edge coordinates: u for horizontal edges, v for vertical ones (the other
    // coordinate of the walk never changes, its step being 0).
    const VF u = CentreU(tex, x), v = hn::Set(df, tex.centreV(y));
    const VF centre = hn::IfThenElse(s.horizontal, u, v);
    const VF off = hn::IfThenElse(s.horizontal, hn::Set(df, tex.invW()), hn::Set(df, tex.invH()));
    VF posN = hn::Sub(centre, hn::Mul(off, hn::Set(df, kFxaaSteps[0])));
    VF posP = hn::Add(centre, hn::Mul(off, hn::Set(df, kFxaaSteps[0])));
    int hsN = -kHalfSteps[0], hsP = kHalfSteps[0];  // position of the lanes still walking

    const auto hor = hn::RebindMask(di, s.horizontal);
    const VI xv = IotaFrom(di, x);
    const VI steep2 = hn::IfThenElseZero(hn::RebindMask(di, hn::Not(pair1)), hn::Set(di, 1));
    const VI acrossH = hn::Add(hn::Set(di, y), steep2);  // plane row between y - 1 | y and y | y + 1
    const VI acrossV = hn::Add(xv, steep2);              // plane column likewise
    // Lanes still walking a side all stand at the same position (they took the same steps);
    // lanes already done read something that is discarded. So away from the left and right
    // borders a read is two contiguous loads per plane; near them, a gather with clamping.
    const int reach = 27;  // the walk ends at most 26.5 px away
    const bool contiguous = x - reach >= 0 && x + int(hn::Lanes(df)) - 1 + reach <= planes.width - 1;
    const int h = planes.height;
    auto read = [&](int hs) {
        VF value;
        if (!contiguous) {
            value = hn::GatherIndex(df, planes.data, WalkIndex(planes, hor, xv, y, hn::Set(di, hs), acrossH, acrossV));
        } else if (hs % 2 == 0) {  // pair planes
            const int a = hs / 2;
            const float* h0 = planes.data + planes.rowH(y) + x + a;
            const float* h1 = planes.data + planes.rowH(y + 1) + x + a;
            const float* v0 = planes.data + planes.rowV(std::clamp(y + a, 0, h - 1)) + x;
            value = hn::IfThenElse(s.horizontal, hn::IfThenElse(pair1, hn::LoadU(df, h0), hn::LoadU(df, h1)),
                                   hn::IfThenElse(pair1, hn::LoadU(df, v0), hn::LoadU(df, v0 + 1)));
        } else {  // quad plane
            const int c = (hs + 1) / 2;
            const float* q0 = planes.data + planes.rowQ(y) + x + c;
            const float* q1 = planes.data + planes.rowQ(y + 1) + x + c;
            const float* v0 = planes.data + planes.rowQ(std::clamp(y + c, 0, h)) + x;
            value = hn::IfThenElse(s.horizontal, hn::IfThenElse(pair1, hn::LoadU(df, q0), hn::LoadU(df, q1)),
                                   hn::IfThenElse(pair1, hn::LoadU(df, v0), hn::LoadU(df, v0 + 1)));
        }
        return hn::Sub(value, localAverage);
    };
    const auto skip = ExitLanes(exitMask, x);
    VF endN = read(hsN), endP = read(hsP);
    auto doneN = hn::Or(hn::Ge(hn::Abs(endN), gradientScaled), skip);
    auto doneP = hn::Or(hn::Ge(hn::Abs(endP), gradientScaled), skip);
    for (int i = 1; i < 12; ++i) {
        const VF step = hn::Mul(off, hn::Set(df, kFxaaSteps[i]));
        posN = hn::IfThenElse(doneN, posN, hn::Sub(posN, step));
        hsN -= kHalfSteps[i];
        const bool back = i == 1 && p.paperSearchQuirk;  // the paper's shader steps side 2 back once
        posP = hn::IfThenElse(doneP, posP, back ? hn::Sub(posP, step) : hn::Add(posP, step));
        hsP += back ? -kHalfSteps[i] : kHalfSteps[i];
        if (i == 11 || hn::AllTrue(df, hn::And(doneN, doneP))) break;  // no read after the last step
        endN = hn::IfThenElse(doneN, endN, read(hsN));
        endP = hn::IfThenElse(doneP, endP, read(hsP));
        doneN = hn::Or(doneN, hn::Ge(hn::Abs(endN), gradientScaled));
        doneP = hn::Or(doneP, hn::Ge(hn::Abs(endP), gradientScaled));
    }

    const VF dstN = hn::Sub(centre, posN), dstP = hn::Sub(posP, centre);
    const auto centreBelow = hn::Lt(hn::Sub(n.C, localAverage), zero);
    const auto goodSpanN = MaskNe(hn::Lt(endN, zero), centreBelow);
    const auto goodSpanP = MaskNe(hn::Lt(endP, zero), centreBelow);
    const auto directionN = hn::Lt(dstN, dstP);
    const VF pixelOffset = hn::Sub(half, hn::Div(hn::Min(dstN, dstP), hn::Add(dstN, dstP)));
    const auto goodSpan = hn::Or(hn::And(directionN, goodSpanN), hn::AndNot(directionN, goodSpanP));

    // Sub-pixel term (FXAA 3.11 subpix).
    const VF avg = hn::Mul(
        hn::Set(df, 1.0f / 12.0f),
        hn::Add(hn::Add(hn::Mul(hn::Set(df, 2.0f), hn::Add(hn::Add(n.S, n.N), hn::Add(n.W, n.E))), hn::Add(n.SW, n.NW)),
                hn::Add(n.SE, n.NE)));
    VF sp = hn::Min(hn::Max(hn::Div(hn::Abs(hn::Sub(avg, n.C)), range), zero), one);
    sp = hn::IfThenElseZero(hn::Gt(range, zero), sp);
    sp = hn::Mul(hn::Mul(hn::Add(hn::Mul(hn::Set(df, -2.0f), sp), hn::Set(df, 3.0f)), sp), sp);
    const VF sub = hn::Mul(hn::Mul(sp, sp), hn::Set(df, p.subpix));
    const VF offset = hn::Max(hn::IfThenElseZero(goodSpan, pixelOffset), sub);

    const VF shift = hn::Mul(offset, lengthSign);
    const VF su = hn::IfThenElse(s.horizontal, u, hn::Add(u, shift));
    const VF sv = hn::IfThenElse(s.horizontal, hn::Add(v, shift), v);
    RgbK c;
    if (!lerp || !AcrossBytes(tex, L, s.horizontal, hn::IfThenElse(s.horizontal, sv, su), x, y, skip, &c))
        c = ReadBytes(tex, su, sv);
    StoreBytes(c.r, c.g, c.b, x, exitMask, src, dst);
}

// lerp: centresAreTexels(tex), so the final reads may take AcrossBytes.
inline void Fxaa3dRowSimd(const Texture& tex, const LumaRows& L, const LumaPlanes& planes, bool lerp, int y,
                          std::uint8_t* exitMask, const Fxaa3dParams& p, const Rgba8* src, Rgba8* dst) {
    RowChunks(L.width, exitMask, [&](int x) { Fxaa3dChunk(tex, L, planes, lerp, x, y, exitMask, p, src, dst); });
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::aa::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
