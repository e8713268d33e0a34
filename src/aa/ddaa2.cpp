// ddaa2: directional diffusion combined with a clean edge search (Klein, DDAA, sections
// 2.3-2.5; spec ppaa.md "ddaa2"). The diffusion comes from ddaa_kernel.hpp (ddaa1).
//
// The edge search walks along the edge half a pixel towards the steeper side, one pixel
// per step (no skipping, unlike FXAA: skipping misses obstructions and leaves stipples,
// paper Fig. 7), 3 reads per round ("batched sampling", section 2.5: one texture
// coordinate plus integer texel offsets, so a GPU issues them together). The first
// position of each side is computed from lumas already known (section 2.5, last paragraph).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/aa/ddaa-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/aa/ddaa-inl.h"

#if HWY_ONCE
#include "src/aa/ddaa_kernel.hpp"
#include "src/aa/luma_driver.hpp"
#include "ssfx/aa/ddaa.hpp"

namespace ssfx::aa {

namespace detail {
HWY_EXPORT(Ddaa2RowSimd);

namespace {

constexpr int kBatch = 3;  // samples per round: EDGE_STEP_LIST = [3, 3, 3, 3, 3]

struct SideResult {
    float distance;  // pixels to the end of the edge (maxDistance + 1 when not found)
    float delta;     // luma - localAverage at the end (or at the last read)
};

// Offset across the edge, in pixels (signed: towards the steep side), from the distances
// to both ends of the edge (FXAA 3.11 quality's span rule, without skipping).
float edgeSearchOffset(const Texture& tex, int x, int y, const Luma3x3& n, const EdgeSides& s, int rounds,
                       float chromaWeight) {
    const bool steep2 = std::fabs(s.g2) > std::fabs(s.g1);  // ties go to side 1
    const float lumaSteep = steep2 ? s.luma2 : s.luma1;
    const float gradientScaled = 0.25f * maxf(std::fabs(s.g1), std::fabs(s.g2));
    const float localAverage = (lumaSteep + n.C) * 0.5f;
    const int across = steep2 ? 1 : -1;

    // First positions, free: the neighbours along the edge and their diagonals on the steep side.
    float first1, first2;
    if (s.horizontal) {
        first1 = (n.W + (steep2 ? n.NW : n.SW)) * 0.5f;
        first2 = (n.E + (steep2 ? n.NE : n.SE)) * 0.5f;
    } else {
        first1 = (n.S + (steep2 ? n.SE : n.SW)) * 0.5f;
        first2 = (n.N + (steep2 ? n.NE : n.NW)) * 0.5f;
    }

    // c: centre moved half a pixel across, towards the steep side.
    float cu = tex.centreU(x), cv = tex.centreV(y);
    if (s.horizontal)
        cv += float(across) * 0.5f * tex.invH();
    else
        cu += float(across) * 0.5f * tex.invW();
    const float invAlong = s.horizontal ? tex.invW() : tex.invH();

    // The coordinate across the edge is the same for every read: split it once.
    const Texture::AxisPos acrossPos = s.horizontal ? tex.axisV(cv) : tex.axisU(cu);
    // Delta of a read at `along` (split coordinate along the edge) plus an integer texel
    // offset along the edge.
    auto deltaAt = [&](const Texture::AxisPos& along, int texelOffset) {
        const Rgb c =
            s.horizontal ? tex.sample(along, acrossPos, texelOffset, 0) : tex.sample(acrossPos, along, 0, texelOffset);
        return edgeLuma(c, chromaWeight) - localAverage;
    };
    auto alongAxis = [&](float move) { return s.horizontal ? tex.axisU(cu + move) : tex.axisV(cv + move); };

    const int maxDistance = kBatch * rounds;
    auto searchSide = [&](int sign, float first) -> SideResult {
        // Round 0: the free position 1, then reads at texel offsets 2 and 3 from c.
        float delta = first;
        if (std::fabs(delta) >= gradientScaled) return {1.0f, delta};
        const Texture::AxisPos round0 = alongAxis(0.0f);
        for (int k = 2; k <= kBatch; ++k) {
            delta = deltaAt(round0, sign * k);
            if (std::fabs(delta) >= gradientScaled) return {float(k), delta};
        }
        // Later rounds: one coordinate (c moved offset + 2 pixels) and texel offsets
        // -1, 0, +1 around it, nearest position first.
        for (int r = 1; r < rounds; ++r) {
            const int offset = kBatch * r;
            const Texture::AxisPos along = alongAxis(float(sign) * (float(offset + 2) * invAlong));
            for (int k = -1; k <= 1; ++k) {
                delta = deltaAt(along, sign * k);
                if (std::fabs(delta) >= gradientScaled) return {float(offset + 2 + k), delta};
            }
        }
        return {float(maxDistance + 1), delta};
    };
    const SideResult side1 = searchSide(-1, first1 - localAverage);
    const SideResult side2 = searchSide(+1, first2 - localAverage);

    const float d1 = side1.distance, d2 = side2.distance;
    const float pixelOffset = 0.5f - minf(d1, d2) / (d1 + d2);
    const float deltaNear = d1 < d2 ? side1.delta : side2.delta;  // ties: side 2
    // "Correct variation": the luma at the nearer end lies on the other side of the
    // local average than the centre, so the edge really ends there.
    const bool correct = (deltaNear < 0.0f) != (n.C < localAverage);
    return correct ? pixelOffset * float(across) : 0.0f;
}

}  // namespace

// True when, for this image size, every read of the edge search lands exactly half-way
// between two texels across the edge and exactly on a texel along it (GPU model: weights
// 128 and 0/256), on the very texels the pair planes pair up, so each read equals a
// pair-luma plane value. Mirrors the coordinate arithmetic of edgeSearchOffset(),
// including clamp-to-edge. O(W + H); true for every realistic size.
bool searchReadsArePairReads(const Texture& tex, int rounds) {
    auto axisOk = [&](int n, float inv, auto centre, auto split) {
        auto clampN = [n](int i) { return std::clamp(i, 0, n - 1); };
        // The texel a read uses along the axis: split position plus texel offset.
        auto texel = [&](const Texture::AxisPos& a, int offset) {
            return a.w == 0 ? clampN(a.index + offset) : (a.w == 256 ? clampN(a.index + offset + 1) : INT_MIN);
        };
        for (int i = 0; i < n; ++i) {
            const float c = centre(i);
            for (int sign : {-1, 1}) {
                const Texture::AxisPos a0 = split(c + 0.0f);
                for (int k = 2; k <= 3; ++k)
                    if (texel(a0, sign * k) != clampN(i + sign * k)) return false;
                for (int r = 1; r < rounds; ++r) {
                    const Texture::AxisPos a = split(c + float(sign) * (float(3 * r + 2) * inv));
                    for (int k = -1; k <= 1; ++k)
                        if (texel(a, sign * k) != clampN(i + sign * (3 * r + 2 + k))) return false;
                }
            }
            if (!acrossIsHalfWay(n, inv, c, i, split)) return false;
        }
        return true;
    };
    return forBothAxes(tex, axisOk);
}

namespace {

void validate(const Ddaa2Params& p) { validateParams(kDdaa2Params, &p, "ddaa2"); }

void run(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa2Params& p, const Exec& exec, bool reference) {
    checkInput("ddaa2", in);
    checkOutput("ddaa2", in, out);
    validate(p);
    const Texture tex(in, p.filtering, p.texture);
    // The colour-aware measure (chromaWeight > 0) runs the scalar kernel, on all threads.
    const bool scalar = reference || p.chromaWeight != 0.0f;
    // The vector kernel across pixels: GPU filtering model, and search reads provably equal
    // to pair-plane lookups for this size (else everything takes the scalar kernel).
    const bool vector = !scalar && p.filtering == Filtering::Gpu &&
                        ddaa2SearchReadsArePairReads(in.width(), in.height(), p.searchRounds) &&
                        planesFitGatherIndices(in.width());
    // The search reads up to 3 searchRounds texels along the edge: plane rows y - 3 r .. y + 3 r.
    PlaneNeeds needs;
    needs.planes = vector;
    needs.reach = 3 * p.searchRounds + 1;
    auto rows = [&](int y, const LumaRows& band, const LumaPlanes& planes, std::uint8_t* mask, const Rgba8* src,
                    Rgba8* dst) {
        if (vector) HWY_DYNAMIC_DISPATCH(Ddaa2RowSimd)(tex, band, planes, y, mask, p, src, dst);
    };
    runLumaMethod(
        in, out, scalar, p.chromaWeight, p.texture, p.edgeThresholdMin, p.edgeThreshold, exec, needs,
        [&](int x, int y, const Luma3x3& n, float) {
            const EdgeSides s = edgeSides(n);
            Diffusion d = diffusion(n, s, p);
            const float offset = edgeSearchOffset(tex, x, y, n, s, p.searchRounds, p.chromaWeight);
            // Combination (section 2.3): the search offset moves both diffusion
            // reads, and a large offset (near an edge's end) weakens the diffusion.
            const float edgeStrength = minf(1.0f, 2.0f * std::fabs(offset));
            d.strength *= 1.0f - edgeStrength;
            const float offU = s.horizontal ? 0.0f : offset * tex.invW();
            const float offV = s.horizontal ? offset * tex.invH() : 0.0f;
            return diffuse(tex, x, y, d, p.maxDiffusion, offU, offV);
        },
        rows);
}

}  // namespace
}  // namespace detail

Ddaa2Params ddaa2ParamsFor(Preset preset) { return detail::withPreset(Ddaa2Params{}, preset); }

void ddaa2(ImageView<const Rgba8> in, ImageView<Rgba8> out, const Ddaa2Params& p, const Exec& exec) {
    detail::run(in, out, p, exec, false);
}
ImageRgba8 ddaa2(ImageView<const Rgba8> in, const Ddaa2Params& p, const Exec& exec) {
    return detail::newOutput("ddaa2", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, exec, false); });
}
bool ddaa2SearchReadsArePairReads(int width, int height, int searchRounds) {
    // The check only splits coordinates: a texture of that size with no pixels. Remembered
    // for the last size (per thread), as a frame loop asks once per frame.
    return detail::oncePerSize(width, height, searchRounds, [&] {
        return detail::searchReadsArePairReads(Texture(ImageView<const Rgba8>(nullptr, width, height), Filtering::Gpu),
                                               searchRounds);
    });
}
ImageRgba8 ddaa2Reference(ImageView<const Rgba8> in, const Ddaa2Params& p) {
    return detail::newOutput("ddaa2", in, [&](ImageView<Rgba8> out) { detail::run(in, out, p, Exec{1}, true); });
}

}  // namespace ssfx::aa
#endif  // HWY_ONCE
