// The screen-space sample loop shared by SAO and the AlchemyAO baseline (sao.cpp,
// alchemy.cpp): position and face normal from the z buffer, spiral taps with the hash
// rotation, a pyramid level per tap; the estimator is a template parameter.
#pragma once

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "src/ao/ao_simd.hpp"
#include "ssfx/ao/depth.hpp"
#include "ssfx/ao/sao.hpp"
#include "ssfx/core/error.hpp"

namespace ssfx::ao::detail {

//! The bilateral blur's rule across fields (the table checks each field's range).
inline void checkBilateral(const char* method, const BilateralParams& b) {
    if (b.blurReleasedWeights && b.blurRadius > 4)
        throw Error(
            fmt::format("{}: blurReleasedWeights has weights for blurRadius <= 4 (got {})", method, b.blurRadius));
}

inline Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

//! The two pixels of `v`'s 2x2-quad pair along one axis (clamped into [0, n) for an odd n).
inline void quadPair(int v, int n, int& a, int& b) {
    a = v & ~1, b = a + 1;
    if (b >= n) a = n - 2, b = n - 1;
}

struct SampleSetup {
    int numSamples, spiralTurns, logQ, maxMip;
    float radius;
    bool usePyramid;
    bool vector = true;                         //!< false: the scalar loop only (the reference)
    double turnAngle = 2.0 * std::numbers::pi;  //!< SaoParams::spiralTurnAngle
    bool spinInFloat = false;                   //!< SaoParams::spinInFloat
};

//! floor(log2(n)) for n >= 1, -1 for n <= 0 (GLSL findMSB on a non-negative int).
inline int findMsb(int n) { return n <= 0 ? -1 : int(std::bit_width(unsigned(n))) - 1; }

// Per-column and per-row factors of the position reconstruction (paper eq. 3):
// C = (z * fx(x), z * fy(y), z) at pixel centres, with fx and fy affine in the pixel index
// (fx(x) = (1 - 2 (x + 0.5) / w) / P00 = ax + bx x, likewise fy), evaluated in float as
// ax + bx * x everywhere: the tables, taps beyond the buffer and the vector kernel's taps
// (two operations instead of a division) all give the same bits.
struct PositionTables {
    float ax, bx, ay, by;
    std::vector<float> fx, fy;
    PositionTables(const Projection& p) : PositionTables(p, positionFactors(p)) {}
    PositionTables(const Projection& p, PositionFactors f)
        : ax(f.ax), bx(f.bx), ay(f.ay), by(f.by), fx(std::size_t(p.width)), fy(std::size_t(p.height)) {
        for (int x = 0; x < p.width; ++x) fx[std::size_t(x)] = fxAt(x);
        for (int y = 0; y < p.height; ++y) fy[std::size_t(y)] = fyAt(y);
    }
    float fxAt(int x) const { return ax + bx * float(x); }
    float fyAt(int y) const { return ay + by * float(y); }
    Vec3 at(int x, int y, float z) const { return {z * fxAt(x), z * fyAt(y), z}; }
};

//! Face normal at (x, y) from the quad-pair differences a GPU's fine derivatives take
//! (paper eq. 4): n = normalize(dC/dy x dC/dx). False where it cannot be formed (a sky
//! neighbour, a degenerate quad).
inline bool faceNormal(ImageView<const float> z0, const PositionTables& pos, int x, int y, Vec3& n) {
    const int w = z0.width(), h = z0.height();
    if (w < 2 || h < 2) return false;
    int xa, xb, ya, yb;
    quadPair(x, w, xa, xb);
    quadPair(y, h, ya, yb);
    const Vec3 ddx = sub(pos.at(xb, y, z0(xb, y)), pos.at(xa, y, z0(xa, y)));
    const Vec3 ddy = sub(pos.at(x, yb, z0(x, yb)), pos.at(x, ya, z0(x, ya)));
    n = cross(ddy, ddx);
    const float len = std::sqrt(dot(n, n));
    if (!(len > 0.0f) || !std::isfinite(len)) return false;
    const float inv = 1.0f / len;
    n = {n.x * inv, n.y * inv, n.z * inv};
    return true;
}

//! Copies a pyramid made level by level (the std::vector<ImageF> entry points) into `out`.
inline void copyPyramid(const std::vector<ImageF>& pyr, ZPyramid& out) {
    out.shape(pyr[0].width(), pyr[0].height(), int(pyr.size()) - 1);
    for (int m = 0; m < out.levels(); ++m) {
        const ImageF& l = pyr[std::size_t(m)];
        if (l.width() != out.width[std::size_t(m)] || l.height() != out.height[std::size_t(m)])
            throw Error(fmt::format("z pyramid: level {} is {}x{}, expected {}x{}", m, l.width(), l.height(),
                                    out.width[std::size_t(m)], out.height[std::size_t(m)]));
        std::copy(l.pixels().begin(), l.pixels().end(), out.data.begin() + out.offset[std::size_t(m)]);
    }
}

//! The spiral (eqs. 6-7), once per pass: tap k's alpha_k = (k + 0.5) / s and its unit
//! direction at angle alpha_k 2 pi tau (in double, rounded); with spinInFloat, alpha_k =
//! (k + 0.5) float(1 / s) and tapAngle_k = alpha_k float(tau turnAngle) (releasedTapAngle()
//! with phi = 0: the pixel adds its phi in float), else tapAngle is empty.
inline void spiral(const SampleSetup& s, std::vector<float>& alpha, std::vector<float>& dirX, std::vector<float>& dirY,
                   std::vector<float>& tapAngle) {
    alpha.assign(std::size_t(s.numSamples), 0.0f), dirX.assign(alpha.size(), 0.0f), dirY.assign(alpha.size(), 0.0f);
    tapAngle.assign(s.spinInFloat ? alpha.size() : 0, 0.0f);
    for (int k = 0; k < s.numSamples; ++k) {
        const double a = (k + 0.5) / s.numSamples, theta = a * s.turnAngle * s.spiralTurns;
        alpha[std::size_t(k)] = float(a), dirX[std::size_t(k)] = float(std::cos(theta)),
        dirY[std::size_t(k)] = float(std::sin(theta));
        if (s.spinInFloat) {
            alpha[std::size_t(k)] = (float(k) + 0.5f) * (1.0f / float(s.numSamples));
            tapAngle[std::size_t(k)] = releasedTapAngle(k, s.numSamples, s.spiralTurns, s.turnAngle, 0.0f);
        }
    }
}

//! Runs the sample loop for every pixel of `region`; est.term(vv, vn, zC) accumulates one
//! tap, est.finish(sum) gives A.
//!
//! The spiral (eqs. 6-7) is precomputed once: tap k has alpha_k = (k + 0.5) / s and the
//! unit direction at angle alpha_k * 2 pi tau; each pixel rotates the whole spiral by its
//! hash angle phi (eq. 8) with one sine and cosine. This is cos/sin(alpha 2 pi tau + phi)
//! evaluated as a rotation: the same directions up to rounding, at a ninth of the cost.
//! With spinInFloat (the released shader's tapLocation()), alpha_k = (k + 0.5) * float(1 / s)
//! and each tap's angle is alpha_k * float(tau turnAngle) + phi in float (no FMA), its cos
//! and sin taken per tap.
template <class Estimator>
void samplePass(const ZPyramid& pyr, const Projection& proj, Region region, const SampleSetup& s, const Estimator& est,
                const Exec& exec, ImageF& out) {
    const ImageView<const float> z0 = pyr.level(0);
    const int w = z0.width(), h = z0.height();
    if (out.width() != region.width || out.height() != region.height) out = ImageF(region.width, region.height);
    const int levels = s.usePyramid ? std::min<int>(s.maxMip, pyr.levels() - 1) : 0;
    std::vector<float> alpha, dirX, dirY, tapAngle;
    spiral(s, alpha, dirX, dirY, tapAngle);
    const PositionTables pos(proj);
    const bool vector = s.vector && w >= 2 && h >= 2;
    SimdSampleInput vin{};
    if (vector) {
        vin = {pyr.data.data(),
               pyr.offset.data(),
               pyr.width.data(),
               pyr.height.data(),
               levels,
               w,
               h,
               pos.fx.data(),
               pos.fy.data(),
               pos.ax,
               pos.bx,
               pos.ay,
               pos.by,
               proj.pixelsPerMeter,
               s.radius,
               s.numSamples,
               s.logQ,
               alpha.data(),
               dirX.data(),
               dirY.data(),
               0,
               0,
               0,
               0,
               0,
               0,
               1.0f,
               s.spinInFloat ? tapAngle.data() : nullptr};
        est.fill(vin);
    }
    parallelRows(region.height, exec, [&](int r0, int r1) {
        for (int j = r0; j < r1; ++j) {
            const int y = region.y0 + j;
            int first = 0;
            if (vector) {
                float* row = &out(0, j);
                first = sampleRowSimd(vin, y, region.x0, region.x0 + region.width, row) - region.x0;
                for (int i = 0; i < first; ++i) row[i] = est.post(row[i]);
            }
            for (int i = first; i < region.width; ++i) {
                const int x = region.x0 + i;
                const float zc = z0(x, y);
                if (std::isinf(zc) || w < 2 || h < 2) {
                    out(i, j) = 1.0f;
                    continue;
                }
                const Vec3 c = pos.at(x, y, zc);
                Vec3 n;
                if (!faceNormal(z0, pos, x, y, n)) {  // a sky neighbour: no surface to shade
                    out(i, j) = 1.0f;
                    continue;
                }
                // Screen-space radius (eq. 5) and the per-pixel rotation (eq. 8).
                const float ssRadius = -s.radius * proj.pixelsPerMeter / zc;
                const float phiF = hashAngle(x, y);
                const double phi = double(phiF);
                const float cphi = float(std::cos(phi)), sphi = float(std::sin(phi));
                float sum = 0.0f;
                for (int k = 0; k < s.numSamples; ++k) {
                    const float hk = ssRadius * alpha[std::size_t(k)];
                    float ux, uy;
                    if (s.spinInFloat) {  // cos/sin of the float angle, exactly (in double)
                        const double angle = double(tapAngle[std::size_t(k)] + phiF);
                        ux = float(std::cos(angle)), uy = float(std::sin(angle));
                    } else {
                        ux = dirX[std::size_t(k)] * cphi - dirY[std::size_t(k)] * sphi;
                        uy = dirX[std::size_t(k)] * sphi + dirY[std::size_t(k)] * cphi;
                    }
                    // GLSL ivec2(float): truncation toward zero.
                    const int sx = x + int(hk * ux), sy = y + int(hk * uy);
                    // Level (eqs. 9-10): m = clamp(findMSB(int(h)) - log2 q', 0, MAX_MIP).
                    const int m = std::clamp(findMsb(int(hk)) - s.logQ, 0, levels);
                    const ImageView<const float> zm = pyr.level(m);
                    const float zq = zm.clamped(sx >> m, sy >> m);
                    if (std::isinf(zq)) continue;  // sky occludes nothing
                    const Vec3 v = sub(pos.at(sx, sy, zq), c);
                    sum += est.term(dot(v, v), dot(v, n), zc);
                }
                out(i, j) = est.finish(sum);
            }
        }
    });
}

}  // namespace ssfx::ao::detail
