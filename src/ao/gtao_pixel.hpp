// GTAO's per-pixel code (spec gtao.md sections 5, 6, 8, 9): the scalar oracle of the main
// pass, the edges, the normals from depth and the denoiser. gtao.cpp runs them over the
// buffer (rows in parallel).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "src/ao/ao_sampling.hpp"
#include "ssfx/ao/gtao.hpp"

namespace ssfx::ao::detail {

inline constexpr int kGtaoChainLevels = 5;  //!< levels 0..4 (spec section 4)
inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kHalfPi = kPi / 2.0f;

//! XeGTAO's acos approximation and its square root from the bit pattern (spec section 5).
inline float gtaoFastAcos(float x) {
    const float ax = std::abs(x);
    const float root = std::bit_cast<float>(0x1FBD1DF5 + (std::bit_cast<std::int32_t>(1.0f - ax) >> 1));
    const float r = (kHalfPi - 0.156583f * ax) * root;
    return x >= 0.0f ? r : kPi - r;
}

//! Slice k of S's screen angle phi from the cell's slice noise xs (sections 5.3, 7).
inline float gtaoSliceAngle(int k, int slices, float xs) { return (float(k) + xs) / float(slices) * kPi; }
//! ((j + xj) / J)^power: power 2 as one product (what a correctly rounded pow gives).
inline float gtaoSpacing(float u, float power) { return power == 2.0f ? u * u : std::pow(u, power); }
//! Step j's distance along slice k as a fraction of r before the closest step's offset:
//! spacing((j + xj) / J) with xj the cell's step noise xt turned by the golden ratio
//! (sections 5.5, 7).
inline float gtaoStepSpacing(int k, int j, int steps, float power, float xt) {
    const float base = float(k + j * steps) * 0.6180339887498948f;
    const float xjRaw = xt + base;
    const float xj = xjRaw - std::floor(xjRaw);
    return gtaoSpacing((float(j) + xj) / float(steps), power);
}

//! The unit vector of n, or (0, 0, 0) where it has none (zero length, not finite).
inline Vec3 unitOrZero(Vec3 n) {
    const float len = std::sqrt(dot(n, n));
    if (!(len > 0.0f) || !std::isfinite(len)) return {0, 0, 0};
    return {n.x / len, n.y / len, n.z / len};
}

//! What every pass reads: the depth chain, positions, and the parameters as the CPU's floats.
struct GtaoSetup {
    const ZPyramid& chain;
    ImageView<const float> t0;  //!< level 0: t = -z (+infinity: sky)
    PositionTables pos;
    int width, height, guard;
    float re;       //!< Re = R radiusMultiplier
    float rp, fRp;  //!< the prefilter's 0.75 Re and f 0.75 Re
    float fRe;      //!< f Re: w(x) = clamp((Re - x) / (f Re), 0, 1)
    float rNum;     //!< r = rNum / t px: Re (W P00 / 2), XeGTAO's horizontal footprint
    float spacingPower, finalPower, mipOffset, toc1, thickness;
    int slices, steps;
    bool lift, nearFade, fastAcos, discard, minusOne;
    //! xs and xt at 64 (y mod 64) + (x mod 64), frame 0 (two arrays: the vector pass gathers each)
    std::array<float, 64 * 64> noiseS, noiseT;
    //! Point sampling of level m at buffer column / row p: floor((p + 0.5) W_m / W) at
    //! [m W + p] (tables: a 64-bit division per sample is otherwise the pass's costliest
    //! operation). A p beyond the buffer reads the edge's entry, which is that formula
    //! clamped into [0, W_m - 1] (entry 0 is 0, entry W - 1 is W_m - 1).
    std::vector<std::int32_t> texelX, texelY;

    GtaoSetup(const ZPyramid& c, const Projection& proj, const GtaoParams& p)
        : GtaoSetup(c, proj, p, gtaoConstants(p, proj)) {}
    GtaoSetup(const ZPyramid& c, const Projection& proj, const GtaoParams& p, const GtaoConstants& k)
        : chain(c),
          t0(c.level(0)),
          pos(proj),
          width(proj.width),
          height(proj.height),
          guard(p.guardBand),
          re(k.re),
          rp(k.rp),
          fRp(k.fRp),
          fRe(k.fRe),
          rNum(k.rNum),
          spacingPower(p.sampleDistributionPower),
          finalPower(p.finalValuePower),
          mipOffset(p.depthMipSamplingOffset),
          toc1(1.0f + p.thinOccluderCompensation),
          thickness(p.thickness),
          slices(p.sliceCount),
          steps(p.stepsPerSlice),
          lift(p.projectedNormalLift),
          nearFade(p.nearFade),
          fastAcos(p.fastAcos),
          discard(p.offscreen == Offscreen::Discard),
          minusOne(p.horizonStart == HorizonStart::MinusOne) {
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                const std::array<float, 2> n = gtaoNoise(x, y);
                noiseS[std::size_t(y * 64 + x)] = n[0], noiseT[std::size_t(y * 64 + x)] = n[1];
            }
        auto texel = [](int q, int wm, int w) { return int((2 * std::int64_t(q) + 1) * wm / (2 * std::int64_t(w))); };
        for (int m = 0; m < kGtaoChainLevels; ++m) {
            const ImageView<const float> level = c.level(m);
            for (int x = 0; x < width; ++x) texelX.push_back(texel(x, level.width(), width));
            for (int y = 0; y < height; ++y) texelY.push_back(texel(y, level.height(), height));
        }
    }
    float acos(float x) const { return fastAcos ? gtaoFastAcos(x) : std::acos(x); }
    float sliceAngle(int k, float xs) const { return gtaoSliceAngle(k, slices, xs); }
    float stepSpacing(int k, int j, float xt) const { return gtaoStepSpacing(k, j, steps, spacingPower, xt); }
};

//! Section 5.1: the edges L, R, T, B of (x, y) from level-0 t (1 = connected), unquantised;
//! 0 for a sky pixel. Neighbours beyond the buffer are clamped (dt = 0); a sky neighbour's
//! edge is 0 and the opposite side then uses |dt| alone (ours).
inline void gtaoEdges(ImageView<const float> t, int x, int y, float e[4]) {
    const float tc = t(x, y);
    e[0] = e[1] = e[2] = e[3] = 0.0f;
    if (std::isinf(tc)) return;
    const float nb[4] = {t.clamped(x - 1, y), t.clamped(x + 1, y), t.clamped(x, y - 1), t.clamped(x, y + 1)};
    bool sky[4];
    float dt[4];
    for (int i = 0; i < 4; ++i) sky[i] = std::isinf(nb[i]), dt[i] = sky[i] ? 0.0f : nb[i] - tc;
    // The slopes through the centre, and each side's difference with the slope taken out.
    const float sLR = (dt[1] - dt[0]) * 0.5f, sTB = (dt[3] - dt[2]) * 0.5f;
    const float adj[4] = {dt[0] + sLR, dt[1] - sLR, dt[2] + sTB, dt[3] - sTB};
    const float scale = tc * 0.011f;
    for (int i = 0; i < 4; ++i) {
        if (sky[i]) continue;
        const float m = sky[i ^ 1] ? std::abs(dt[i]) : std::min(std::abs(dt[i]), std::abs(adj[i]));
        e[i] = std::clamp(1.25f - m / scale, 0.0f, 1.0f);
    }
}

//! The edges stored as XeGTAO does: roundEven(2.9 e) in 0..3 each, L + 4 R + 16 T + 64 B.
inline std::uint8_t quantiseEdges(const float e[4]) {
    int packed = 0;
    for (int i = 0; i < 4; ++i) packed |= int(std::nearbyint(2.9f * e[i])) << (2 * i);
    return std::uint8_t(packed);
}
inline float edgeOf(std::uint8_t packed, int side) { return float((packed >> (2 * side)) & 3) / 3.0f; }

//! Section 6: the normal from the positions of (x, y) and its four neighbours, weighted by the
//! unquantised edges; (0, 0, 0) where none can be formed. Neighbours beyond the buffer keep
//! their own position with the edge texel's t (section 10); a sky neighbour's two weights are 0.
inline Vec3 gtaoNormalFromDepth(const GtaoSetup& s, int x, int y, const float e[4]) {
    const ImageView<const float> t = s.t0;
    const Vec3 c = s.pos.at(x, y, -t(x, y));
    const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
    Vec3 u[4];
    bool sky[4];
    for (int i = 0; i < 4; ++i) {
        const float tn = t.clamped(nx[i], ny[i]);
        sky[i] = std::isinf(tn);
        u[i] = sky[i] ? Vec3{0, 0, 0} : unitOrZero(sub(s.pos.at(nx[i], ny[i], -tn), c));
    }
    enum { L, R, T, B };
    auto weight = [&](int a, int b) { return sky[a] || sky[b] ? 0.0f : std::clamp(e[a] * e[b] + 0.01f, 0.0f, 1.0f); };
    const float aLT = weight(L, T), aTR = weight(T, R), aRB = weight(R, B), aBL = weight(B, L);
    // Right-handed camera space: the reverse of XeGTAO's order (spec section 6).
    const Vec3 cLT = cross(u[T], u[L]), cTR = cross(u[R], u[T]), cRB = cross(u[B], u[R]), cBL = cross(u[L], u[B]);
    const Vec3 n{aLT * cLT.x + aTR * cTR.x + aRB * cRB.x + aBL * cBL.x,
                 aLT * cLT.y + aTR * cTR.y + aRB * cRB.y + aBL * cBL.y,
                 aLT * cLT.z + aTR * cTR.z + aRB * cRB.z + aBL * cBL.z};
    return unitOrZero(n);
}

//! The main pass (section 5) over a work region whose normals are given ((0, 0, 0): none).
struct GtaoMain {
    const GtaoSetup& s;
    Region work;
    const Vec3* normals;  //!< work region, row-major

    GtaoMain(const GtaoSetup& setup, Region w, const Vec3* n) : s(setup), work(w), normals(n) {}

    //! V = normalize(-C) of pixel (x, y) (for sky: of its ray).
    Vec3 viewVector(int x, int y) const {
        const float t = s.t0(x, y);
        const Vec3 c = s.pos.at(x, y, std::isinf(t) ? -1.0f : -t);
        const float inv = 1.0f / std::sqrt(dot(c, c));
        return {-c.x * inv, -c.y * inv, -c.z * inv};
    }

    //! A of (x, y) before the denoiser (may exceed 1); with `bent`, the unit bent normal.
    float pixel(int x, int y, Vec3* bent) const {
        const float t0 = s.t0(x, y);
        if (std::isinf(t0)) {  // sky: unoccluded (ours, as sao.md)
            if (bent) *bent = {0, 0, 1};
            return 1.0f;
        }
        // Step 3: the pull against depth imprecision; C and V use it.
        const float t = t0 * 0.99999f;
        const Vec3 c = s.pos.at(x, y, -t);
        const float invLen = 1.0f / std::sqrt(dot(c, c));
        const Vec3 v{-c.x * invLen, -c.y * invLen, -c.z * invLen};
        Vec3 n = normals[std::size_t(y - work.y0) * std::size_t(work.width) + std::size_t(x - work.x0)];
        if (n.x == 0.0f && n.y == 0.0f && n.z == 0.0f) n = v;
        // Step 4: the radius in pixels, the fade for small radii, the closest step.
        const float r = s.rNum / t;
        const float v0 = s.nearFade ? 0.5f * std::clamp((10.0f - r) / 100.0f, 0.0f, 1.0f) : 0.0f;
        const float smin = 1.3f / r;
        const std::size_t ni = std::size_t(((y - s.guard) & 63) * 64 + ((x - s.guard) & 63));
        const std::array<float, 2> noise{s.noiseS[ni], s.noiseT[ni]};
        float sum = 0.0f;
        Vec3 bentSum{0, 0, 0};
        for (int k = 0; k < s.slices; ++k) {
            const float phi = s.sliceAngle(k, noise[0]);
            const float cphi = std::cos(phi), sphi = std::sin(phi);
            const Vec3 d{cphi, sphi, 0.0f};
            const float ox = cphi * r, oy = -sphi * r;  // screen y is down
            const float dv = dot(d, v);
            const Vec3 dp{d.x - dv * v.x, d.y - dv * v.y, d.z - dv * v.z};
            const Vec3 axis = unitOrZero(cross(dp, v));
            const float na = dot(n, axis);
            const Vec3 np{n.x - na * axis.x, n.y - na * axis.y, n.z - na * axis.z};
            const float l = std::sqrt(dot(np, np));
            float cg = 1.0f, gamma = 0.0f;
            if (l > 0.0f) {
                cg = std::clamp(dot(np, v) / l, 0.0f, 1.0f);
                const float side = dot(dp, np);
                gamma = (side > 0.0f ? 1.0f : side < 0.0f ? -1.0f : 0.0f) * s.acos(cg);
            }
            const float sg = std::sin(gamma);
            // The horizon cosines' starts: on the hemisphere of n (XeGTAO) or at -1 (the paper).
            const float lowPos = std::cos(gamma + kHalfPi), lowNeg = std::cos(gamma - kHalfPi);
            const float startPos = s.minusOne ? -1.0f : lowPos, startNeg = s.minusOne ? -1.0f : lowNeg;
            float hp = startPos, hn = startNeg;
            for (int j = 0; j < s.steps; ++j) {
                const float u = s.stepSpacing(k, j, noise[1]) + smin;
                const float sx = u * ox, sy = u * oy;
                const float lod = std::clamp(std::log2(std::sqrt(sx * sx + sy * sy)) - s.mipOffset, 0.0f, 5.0f);
                const int m = std::min(kGtaoChainLevels - 1, int(std::floor(lod + 0.5f)));
                const int qx = int(std::nearbyint(sx)), qy = int(std::nearbyint(sy));
                sample(x + qx, y + qy, m, c, v, startPos, hp);
                sample(x - qx, y - qy, m, c, v, startNeg, hn);
            }
            if (s.minusOne) hp = std::max(hp, lowPos), hn = std::max(hn, lowNeg);  // onto the hemisphere
            const float h1 = s.acos(hp), h0 = -s.acos(hn);
            const float lp = s.lift ? 0.95f * l + 0.05f : l;
            auto iota = [&](float h) { return (cg + 2.0f * h * sg - std::cos(2.0f * h - gamma)) * 0.25f; };
            sum += lp * (iota(h0) + iota(h1));
            if (bent) {  // section 9: the slice's bent direction in the frame where v is +z
                const float t0b =
                    (6.0f * std::sin(h0 - gamma) - std::sin(3.0f * h0 - gamma) + 6.0f * std::sin(h1 - gamma) -
                     std::sin(3.0f * h1 - gamma) + 16.0f * sg - 3.0f * (std::sin(h0 + gamma) + std::sin(h1 + gamma))) /
                    12.0f;
                const float t1b = (-std::cos(3.0f * h0 - gamma) - std::cos(3.0f * h1 - gamma) + 8.0f * cg -
                                   3.0f * (std::cos(h0 + gamma) + std::cos(h1 + gamma))) /
                                  12.0f;
                bentSum = {bentSum.x + lp * d.x * t0b, bentSum.y + lp * d.y * t0b, bentSum.z + lp * t1b};
            }
        }
        if (bent) *bent = unitOrZero(rotateZTo(v, bentSum));
        const float a = std::max(0.0f, (v0 + sum) / float(s.slices));
        return std::max(0.03f, s.finalPower == 1.0f ? a : std::pow(a, s.finalPower));
    }

private:
    // One step's sample on one side: the horizon cosine h moves up to the sample's (section 5.6).
    void sample(int px, int py, int m, Vec3 c, Vec3 v, float start, float& h) const {
        const bool inside = px >= 0 && py >= 0 && px < s.width && py < s.height;
        if (!inside && s.discard) return;  // weight 0: no change
        const ImageView<const float> level = s.chain.level(m);
        const std::size_t tx = std::size_t(m * s.width + std::clamp(px, 0, s.width - 1));
        const std::size_t ty = std::size_t(m * s.height + std::clamp(py, 0, s.height - 1));
        const float ts = level(s.texelX[tx], s.texelY[ty]);
        if (std::isinf(ts)) return;  // sky: weight 0
        const Vec3 q = s.pos.at(px, py, -ts);
        const Vec3 dv = sub(q, c);
        const float len = std::sqrt(dot(dv, dv));
        const float cs = dot(dv, v) / len;
        const float lenW =
            s.toc1 == 1.0f ? len : std::sqrt(dv.x * dv.x + dv.y * dv.y + (s.toc1 * dv.z) * (s.toc1 * dv.z));
        const float w = std::clamp((s.re - lenW) / s.fRe, 0.0f, 1.0f);
        const float cw = start + w * (cs - start);
        if (s.thickness > 0.0f && cw < h)
            h = h + s.thickness * (cw - h);  // the paper's thickness heuristic
        else
            h = std::max(h, cw);
    }

    //! The minimal rotation taking +z to v (Moller and Hughes 1999), applied to b; identity
    //! when |v.z| > 1 - 3e-4.
    static Vec3 rotateZTo(Vec3 v, Vec3 b) {
        if (std::abs(v.z) > 1.0f - 3e-4f) return b;
        const float e = v.z, hh = 1.0f / (1.0f + e), ax = -v.y, ay = v.x;  // axis = z x v, az = 0
        return {(e + hh * ax * ax) * b.x + (hh * ax * ay) * b.y + ay * b.z,
                (hh * ax * ay) * b.x + (e + hh * ay * ay) * b.y - ax * b.z, -ay * b.x + ax * b.y + e * b.z};
    }
};

//! One 3x3 pass of the denoiser (section 8) with blur weight `beta`, reading A (and bent
//! normals) of the work region; sky pixels give 1, sky neighbours weigh 0.
struct GtaoDenoise {
    ImageView<const float> t0;
    Region work;
    const std::uint8_t* edges;  //!< work region, row-major
    float beta;

    float pixel(ImageView<const float> a, int x, int y, ImageView<const Vec3> bentIn, Vec3* bentOut) const {
        if (std::isinf(t0(x, y))) {
            if (bentOut) *bentOut = {0, 0, 1};
            return 1.0f;
        }
        auto cx = [&](int v) { return std::clamp(v, work.x0, work.x0 + work.width - 1); };
        auto cy = [&](int v) { return std::clamp(v, work.y0, work.y0 + work.height - 1); };
        // Neighbours C, L, R, T, B, TL, TR, BL, BR (clamped at the borders).
        const int px[9] = {x, cx(x - 1), cx(x + 1), x, x, cx(x - 1), cx(x + 1), cx(x - 1), cx(x + 1)};
        const int py[9] = {y, y, y, cy(y - 1), cy(y + 1), cy(y - 1), cy(y - 1), cy(y + 1), cy(y + 1)};
        std::uint8_t e[9];
        bool sky[9];
        for (int i = 0; i < 9; ++i) {
            e[i] = edges[std::size_t(py[i] - work.y0) * std::size_t(work.width) + std::size_t(px[i] - work.x0)];
            sky[i] = std::isinf(t0(px[i], py[i]));
        }
        enum { C, L, R, T, B, TL, TR, BL, BR };
        enum { SL, SR, ST, SB };  // sides within a pixel's packed edges
        float eL = edgeOf(e[C], SL) * edgeOf(e[L], SR), eR = edgeOf(e[C], SR) * edgeOf(e[R], SL);
        float eT = edgeOf(e[C], ST) * edgeOf(e[T], SB), eB = edgeOf(e[C], SB) * edgeOf(e[B], ST);
        const float leak = std::clamp(1.5f - (eL + eR + eT + eB), 0.0f, 1.0f) / 1.5f * 0.5f;
        eL = std::clamp(eL + leak, 0.0f, 1.0f), eR = std::clamp(eR + leak, 0.0f, 1.0f);
        eT = std::clamp(eT + leak, 0.0f, 1.0f), eB = std::clamp(eB + leak, 0.0f, 1.0f);
        float w[9];
        w[C] = beta, w[L] = eL, w[R] = eR, w[T] = eT, w[B] = eB;
        w[TL] = 0.425f * (eL * edgeOf(e[L], ST) + eT * edgeOf(e[T], SL));
        w[TR] = 0.425f * (eT * edgeOf(e[T], SR) + eR * edgeOf(e[R], ST));
        w[BL] = 0.425f * (eB * edgeOf(e[B], SL) + eL * edgeOf(e[L], SB));
        w[BR] = 0.425f * (eR * edgeOf(e[R], SB) + eB * edgeOf(e[B], SR));
        float sum = 0.0f, wsum = 0.0f;
        Vec3 bsum{0, 0, 0};
        for (int i = 0; i < 9; ++i) {
            if (sky[i]) continue;
            const int wi = px[i] - work.x0, wj = py[i] - work.y0;
            sum += w[i] * a(wi, wj), wsum += w[i];
            if (bentOut) {
                const Vec3 b = bentIn(wi, wj);
                bsum = {bsum.x + w[i] * b.x, bsum.y + w[i] * b.y, bsum.z + w[i] * b.z};
            }
        }
        if (bentOut) *bentOut = {bsum.x / wsum, bsum.y / wsum, bsum.z / wsum};
        return sum / wsum;
    }
};

}  // namespace ssfx::ao::detail
