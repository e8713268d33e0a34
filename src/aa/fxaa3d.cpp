// fxaa3d: FXAA 3.11 "desktop"/quality with a 12-iteration edge search (T. Lottes, NVIDIA
// 2011; FXAA_QUALITY__PRESET 39 step list), as used in the DDAA paper's comparison
// (spec ppaa.md "fxaa3d").
//
// Deviation switch: Fxaa3dParams::paperSearchQuirk (default on) reproduces the paper's
// shader, which steps side 2 back one pixel after its first read.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/fxaa3d-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/fxaa3d-inl.h"

#if HWY_ONCE
#include "src/aa/luma_driver.hpp"
#include "src/aa/luma_planes.hpp"
#include "ssfx/aa/fxaa.hpp"

namespace ssfx::aa {

namespace detail {
HWY_EXPORT(Fxaa3dRowSimd);

// True when, for this image size, every read of the walk lands on the texels a luma plane
// pairs up, with the GPU-model weights that make it a plane value: 0/256 along and 128
// across at whole-pixel distances (pair planes), 128 and 128 at the x.5 distances (quad
// plane). Replays fxaa3dPixel()'s float coordinate arithmetic, clamp-to-edge included.
// O(12 (W + H)); true for every realistic size.
bool walkReadsArePlaneReads(const Texture& tex, bool quirk) {
    constexpr float kQ[12] = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f};
    constexpr int kHalf[12] = {2, 2, 2, 2, 2, 3, 4, 4, 4, 4, 8, 16};
    auto axisOk = [&](int n, float inv, auto centre, auto split) {
        auto clampN = [n](int i) { return std::clamp(i, 0, n - 1); };
        for (int i = 0; i < n; ++i) {
            const float c = centre(i);
            for (int side : {-1, 1}) {
                float pos = side < 0 ? c - inv * kQ[0] : c + inv * kQ[0];
                int hs = 2 * side;
                for (int k = 0; k <= 10; ++k) {  // reads follow the steps 0 .. 10
                    if (k > 0) {
                        const bool backwards = side < 0 || (k == 1 && quirk);
                        pos = backwards ? pos - inv * kQ[k] : pos + inv * kQ[k];
                        hs += backwards ? -kHalf[k] : kHalf[k];
                    }
                    const Texture::AxisPos a = split(pos);
                    if (hs % 2 == 0) {
                        if (a.w != 0 && a.w != 256) return false;
                        if (clampN(a.index + (a.w == 256 ? 1 : 0)) != clampN(i + hs / 2)) return false;
                    } else if (a.w != 128 || clampN(a.index) != clampN(i + (hs - 1) / 2) ||
                               clampN(a.index + 1) != clampN(i + (hs + 1) / 2)) {
                        return false;
                    }
                }
            }
            if (!acrossIsHalfWay(n, inv, c, i, split)) return false;
        }
        return true;
    };
    return forBothAxes(tex, axisOk);
}

namespace {

// The walk reads at most 37 half pixels along its edge (the steps before its last read:
// 2 x (1 + 1 + 1 + 1 + 1 + 1.5 + 2 + 2 + 2 + 2 + 4)), so vertical edges read plane rows
// y - 18 .. y + 19: a band's planes hold 19 rows either side.
constexpr int kWalkReachRows = 19;

// Step after each unsuccessful read, in pixels: 1 for the first five, then skipping.
// Skipping is what gives FXAA its stipple artifacts (DDAA paper Fig. 7); kept: baseline.
constexpr float kSteps[12] = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f};

Rgb fxaa3dPixel(const Texture& tex, int x, int y, const Luma3x3& n, float range, const Fxaa3dParams& p) {
    const EdgeSides s = edgeSides(n);
    const bool pair1 = std::fabs(s.g1) >= std::fabs(s.g2);  // steeper side; ties go to side 1
    const float lumaSteep = pair1 ? s.luma1 : s.luma2;
    const float gradientScaled = 0.25f * maxf(std::fabs(s.g1), std::fabs(s.g2));
    const float localAverage = (lumaSteep + n.C) * 0.5f;
    float lengthSign = s.horizontal ? tex.invH() : tex.invW();
    if (pair1) lengthSign = -lengthSign;

    const float u = tex.centreU(x), v = tex.centreV(y);
    // posB: half a pixel across, towards the steep side; offNP: one pixel along the edge.
    float bu = u, bv = v;
    if (s.horizontal)
        bv += lengthSign * 0.5f;
    else
        bu += lengthSign * 0.5f;
    const float offU = s.horizontal ? tex.invW() : 0.0f;
    const float offV = s.horizontal ? 0.0f : tex.invH();

    float nU = bu - offU * kSteps[0], nV = bv - offV * kSteps[0];
    float pU = bu + offU * kSteps[0], pV = bv + offV * kSteps[0];
    // The across coordinate stays fixed along the walk (its step is 0): split it once.
    const Texture::AxisPos across = s.horizontal ? tex.axisV(bv) : tex.axisU(bu);
    auto walkLuma = [&](float wu, float wv) {
        const Rgb c = s.horizontal ? tex.sample(tex.axisU(wu), across, 0, 0) : tex.sample(across, tex.axisV(wv), 0, 0);
        return edgeLuma(c, p.chromaWeight) - localAverage;
    };
    float endN = walkLuma(nU, nV);
    float endP = walkLuma(pU, pV);
    bool doneN = std::fabs(endN) >= gradientScaled;
    bool doneP = std::fabs(endP) >= gradientScaled;
    for (int i = 1; i < 12; ++i) {
        if (!doneN) nU -= offU * kSteps[i], nV -= offV * kSteps[i];
        if (!doneP) {
            if (i == 1 && p.paperSearchQuirk)
                pU -= offU * kSteps[i], pV -= offV * kSteps[i];
            else
                pU += offU * kSteps[i], pV += offV * kSteps[i];
        }
        if ((doneN && doneP) || i == 11) break;  // after the last step there is no read
        if (!doneN) endN = walkLuma(nU, nV);
        if (!doneP) endP = walkLuma(pU, pV);
        doneN = doneN || std::fabs(endN) >= gradientScaled;
        doneP = doneP || std::fabs(endP) >= gradientScaled;
    }

    const float dstN = s.horizontal ? u - nU : v - nV;
    const float dstP = s.horizontal ? pU - u : pV - v;
    const bool centreBelow = n.C - localAverage < 0.0f;
    const bool goodSpanN = (endN < 0.0f) != centreBelow;
    const bool goodSpanP = (endP < 0.0f) != centreBelow;
    const bool directionN = dstN < dstP;
    const float pixelOffset = 0.5f - minf(dstN, dstP) / (dstN + dstP);
    const bool goodSpan = directionN ? goodSpanN : goodSpanP;

    // Sub-pixel aliasing term (FXAA 3.11 subpix, spec step 6).
    const float avg = (1.0f / 12.0f) * (2.0f * ((n.S + n.N) + (n.W + n.E)) + (n.SW + n.NW) + (n.SE + n.NE));
    // range is 0 only when both thresholds are 0 and the pixel is flat: no sub-pixel term
    // (a GPU's saturate(0/0) gives 0 too).
    float sp = range > 0.0f ? minf(maxf(std::fabs(avg - n.C) / range, 0.0f), 1.0f) : 0.0f;
    sp = (-2.0f * sp + 3.0f) * sp * sp;
    const float sub = sp * sp * p.subpix;

    const float offset = maxf(goodSpan ? pixelOffset : 0.0f, sub);
    return s.horizontal ? tex.sample(u, v + offset * lengthSign) : tex.sample(u + offset * lengthSign, v);
}

void validate(const Fxaa3dParams& p) { validateParams(kFxaa3dParams, &p, "fxaa3d"); }

void run(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3dParams& p, const Exec& exec, bool reference) {
    checkInput("fxaa3d", in);
    checkOutput("fxaa3d", in, out);
    validate(p);
    const Texture tex(in, p.filtering, p.texture);
    // The colour-aware measure (chromaWeight > 0) runs the scalar kernel, on all threads.
    const bool scalar = reference || p.chromaWeight != 0.0f;
    // The vector kernel across pixels: GPU filtering model, and walk reads provably equal to
    // plane lookups for this size (else everything takes the scalar kernel).
    const bool vector = !scalar && p.filtering == Filtering::Gpu &&
                        oncePerSize(in.width(), in.height(), p.paperSearchQuirk,
                                    [&] { return walkReadsArePlaneReads(tex, p.paperSearchQuirk); }) &&
                        planesFitGatherIndices(in.width());
    const bool lerp = vector && oncePerSize(in.width(), in.height(), -1, [&] { return centresAreTexels(tex); });
    PlaneNeeds needs;
    needs.planes = needs.quad = vector;
    needs.reach = kWalkReachRows;
    auto rows = [&](int y, const LumaRows& band, const LumaPlanes& planes, std::uint8_t* mask, const Rgba8* src,
                    Rgba8* dst) {
        if (vector) HWY_DYNAMIC_DISPATCH(Fxaa3dRowSimd)(tex, band, planes, lerp, y, mask, p, src, dst);
    };
    runLumaMethod(
        in, out, scalar, p.chromaWeight, p.texture, p.edgeThresholdMin, p.edgeThreshold, exec, needs,
        [&](int x, int y, const Luma3x3& n, float range) { return fxaa3dPixel(tex, x, y, n, range, p); }, rows);
}

}  // namespace
}  // namespace detail

Fxaa3dParams fxaa3dParamsFor(Preset preset) { return detail::withPreset(Fxaa3dParams{}, preset); }

void fxaa3d(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Fxaa3dParams& p, const Exec& exec) {
    detail::run(in, out, p, exec, false);
}
ImageRgba8 fxaa3d(ImageView<const Rgba8> in, const Fxaa3dParams& p, const Exec& exec) {
    return detail::newOutput("fxaa3d", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, exec, false); });
}
ImageRgba8 fxaa3dReference(ImageView<const Rgba8> in, const Fxaa3dParams& p) {
    return detail::newOutput("fxaa3d", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, Exec{1}, true); });
}

}  // namespace ssfx::aa
#endif  // HWY_ONCE
