// Highway body of the AO sample pass (SAO and AlchemyAO; see ao_sampling.hpp for the
// scalar loop it follows): one lane per pixel along a row, taps gathered from all pyramid
// levels stored in one buffer. The lanes follow the scalar operations except one: the sine
// and cosine of the hash angle (and, with spinInFloat, of each tap's float angle) come from
// Highway's float approximations after a double-precision range reduction (the scalar loop
// uses std::cos/sin in double). That moves a tap's position
// by a few ulps, which can move a truncated tap offset by one pixel in rare pixels; the test
// holds the vector path to the scalar one within a stated tolerance.
#if defined(SSFX_AO_SAO_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AO_SAO_SIMD_INL_H_
#undef SSFX_AO_SAO_SIMD_INL_H_
#else
#define SSFX_AO_SAO_SIMD_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include "src/ao/ao_simd.hpp"
#include "src/ao/bilateral-inl.h"
#include "src/ao/depth-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::ao::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A float angle reduced to about [-pi, pi] for Highway's Cos/Sin: a - 2 pi nearbyint(a / 2 pi)
// in double (every float angle is exact in double), then rounded to float.
template <class DF>
hn::Vec<DF> ReduceAngle(DF df, hn::Vec<DF> a) {
#if HWY_TARGET == HWY_SCALAR
    HWY_ALIGN float v[hn::MaxLanes(df)];
    hn::Store(a, df, v);
    for (std::size_t l = 0; l < hn::Lanes(df); ++l) {
        const double x = double(v[l]);
        v[l] = float(x - 6.283185307179586 * std::nearbyint(x / 6.283185307179586));
    }
    return hn::Load(df, v);
#else
    // Half a vector at a time: the scalar reduction's operations, so the same bits.
    const hn::Half<DF> dh;
    const hn::Repartition<double, DF> dd;
    const auto twoPi = hn::Set(dd, 6.283185307179586);
    auto reduce = [&](hn::Vec<decltype(dh)> v) {
        const auto x = hn::PromoteTo(dd, v);
        return hn::DemoteTo(dh, hn::Sub(x, hn::Mul(twoPi, hn::Round(hn::Div(x, twoPi)))));
    };
    return hn::Combine(df, reduce(hn::UpperHalf(dh, a)), reduce(hn::LowerHalf(dh, a)));
#endif
}

// Pixels [x0, x1) of buffer row y; returns the first x it did not do (whole vectors only,
// and only where every lane's quad partner lies inside the buffer).
inline int SampleRowSimd(const SimdSampleInput& in, int y, int x0, int x1, float* HWY_RESTRICT out) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const int n = int(hn::Lanes(df));
    const int w = in.width, h = in.height;
    int ya = y & ~1, yb = ya + 1;
    if (yb >= h) ya = h - 2, yb = h - 1;
    const float* z0 = in.levels;  // level 0 first
    const float* rowY = z0 + std::ptrdiff_t(y) * w;
    const float* rowA = z0 + std::ptrdiff_t(ya) * w;
    const float* rowB = z0 + std::ptrdiff_t(yb) * w;
    const auto fyY = hn::Set(df, in.fy[y]), fyA = hn::Set(df, in.fy[ya]), fyB = hn::Set(df, in.fy[yb]);
    const auto one = hn::Set(df, 1.0f), zero = hn::Zero(df);
    const auto negInf = hn::Set(df, -HUGE_VALF);
    const auto iota = hn::Iota(di, 0);
    const auto radiusS = hn::Set(df, -in.radius * in.pixelsPerMeter);
    const auto ax = hn::Set(df, in.ax), bx = hn::Set(df, in.bx), ay = hn::Set(df, in.ay), by = hn::Set(df, in.by);
    // Per-level geometry as vectors when the levels fit in one (maxMip < lanes): a lane
    // permutation per tap instead of gathers. Sizes halve, rounding down, at least 1.
    const bool levelsInVector = in.maxLevel < n;
    HWY_ALIGN std::int32_t offs[hn::MaxLanes(di)] = {}, lastX[hn::MaxLanes(di)] = {}, lastY[hn::MaxLanes(di)] = {},
                           widths[hn::MaxLanes(di)] = {};
    for (int l = 0; l <= in.maxLevel && l < n; ++l)
        offs[l] = in.levelOffset[l], widths[l] = in.levelW[l], lastX[l] = in.levelW[l] - 1, lastY[l] = in.levelH[l] - 1;
    const auto offVec = hn::Load(di, offs), wVec = hn::Load(di, widths), lastXVec = hn::Load(di, lastX),
               lastYVec = hn::Load(di, lastY);
    const auto expBias = hn::Set(di, 127 + in.logQ), maxLevel = hn::Set(di, in.maxLevel);
    const auto hugeTap = hn::Set(df, 2147483648.0f);
    // Vectors that start on an even column hold whole quad pairs (x & ~1, x | 1).
    [[maybe_unused]] const bool pairsInVector = x0 % 2 == 0;
    int x = x0;
    // Every lane's partner xb = (x | 1) must be < w.
    for (; x + n <= x1 && ((x + n - 1) | 1) < w; x += n) {
        const auto xi = hn::Add(hn::Set(di, x), iota);
        const auto zc = hn::LoadU(df, rowY + x);
        const auto fxC = hn::LoadU(df, in.fx + x);
        const auto cx = hn::Mul(zc, fxC), cy = hn::Mul(zc, fyY);
        // Quad-pair normal (eq. 4): lanes x&~1 and x|1 of this row; rows ya, yb of this column.
        hn::Vec<decltype(df)> zxa, zxb, fxa, fxb;
#if HWY_TARGET != HWY_SCALAR
        if (pairsInVector) {  // the pair of lanes 2i, 2i + 1 is the quad pair: same values, no gathers
            zxa = hn::DupEven(zc), zxb = hn::DupOdd(zc), fxa = hn::DupEven(fxC), fxb = hn::DupOdd(fxC);
        } else
#endif
        {
            const auto xa = hn::And(xi, hn::Set(di, ~1)), xb = hn::Or(xi, hn::Set(di, 1));
            zxa = hn::GatherIndex(df, rowY, xa), zxb = hn::GatherIndex(df, rowY, xb);
            fxa = hn::GatherIndex(df, in.fx, xa), fxb = hn::GatherIndex(df, in.fx, xb);
        }
        const auto zya = hn::LoadU(df, rowA + x), zyb = hn::LoadU(df, rowB + x);
        const auto ddxX = hn::Sub(hn::Mul(zxb, fxb), hn::Mul(zxa, fxa));
        const auto ddxY = hn::Sub(hn::Mul(zxb, fyY), hn::Mul(zxa, fyY));
        const auto ddxZ = hn::Sub(zxb, zxa);
        const auto ddyX = hn::Sub(hn::Mul(zyb, fxC), hn::Mul(zya, fxC));
        const auto ddyY = hn::Sub(hn::Mul(zyb, fyB), hn::Mul(zya, fyA));
        const auto ddyZ = hn::Sub(zyb, zya);
        // n = ddy x ddx
        auto nx = hn::Sub(hn::Mul(ddyY, ddxZ), hn::Mul(ddyZ, ddxY));
        auto ny = hn::Sub(hn::Mul(ddyZ, ddxX), hn::Mul(ddyX, ddxZ));
        auto nz = hn::Sub(hn::Mul(ddyX, ddxY), hn::Mul(ddyY, ddxX));
        const auto len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
        // Valid: a finite, non-zero normal and a finite centre (no sky in the quad).
        const auto valid = hn::And(hn::And(hn::Gt(len, zero), hn::Lt(len, hn::Set(df, HUGE_VALF))), hn::Gt(zc, negInf));
        const auto inv = hn::Div(one, len);
        nx = hn::Mul(nx, inv), ny = hn::Mul(ny, inv), nz = hn::Mul(nz, inv);
        const auto ssRadius = hn::Div(radiusS, zc);
        // Hash angle phi = 10 * ((3x) ^ (y + xy)) (eq. 8), reduced to [-pi, pi] in double.
        const auto k = hn::Xor(hn::Mul(xi, hn::Set(di, 3)), hn::Add(hn::Set(di, y), hn::Mul(xi, hn::Set(di, y))));
        // hashAngle() (float): phi = 10 * float(k).
        const auto phiF = hn::Mul(hn::Set(df, 10.0f), hn::ConvertTo(df, k));
        const auto pr = ReduceAngle(df, phiF);
        const auto cphi = hn::Cos(df, pr), sphi = hn::Sin(df, pr);
        auto sum = zero;
        for (int s = 0; s < in.numSamples; ++s) {
            const auto hk = hn::Mul(ssRadius, hn::Set(df, in.alpha[s]));
            hn::Vec<decltype(df)> ux, uy;
            if (in.tapAngle) {  // spinInFloat: the tap's angle alpha_k float(tau turnAngle) + phi in float
                const auto angle = ReduceAngle(df, hn::Add(hn::Set(df, in.tapAngle[s]), phiF));
                ux = hn::Cos(df, angle), uy = hn::Sin(df, angle);
            } else {
                const auto dX = hn::Set(df, in.dirX[s]), dY = hn::Set(df, in.dirY[s]);
                ux = hn::Sub(hn::Mul(dX, cphi), hn::Mul(dY, sphi));
                uy = hn::Add(hn::Mul(dX, sphi), hn::Mul(dY, cphi));
            }
            const auto sx = hn::Add(xi, hn::ConvertTo(di, hn::Mul(hk, ux)));  // truncation toward 0
            const auto sy = hn::Add(hn::Set(di, y), hn::ConvertTo(di, hn::Mul(hk, uy)));
            // m = clamp(findMSB(int(h)) - logQ, 0, maxLevel). For 1 <= h < 2^31, findMSB(int(h))
            // is h's binary exponent; below 1 the exponent is negative and m clamps to 0, as
            // findMSB's -1 does; from 2^31 int(h) overflows to INT_MIN (x86), findMSB gives -1.
            const auto expo = hn::Sub(hn::ShiftRight<23>(hn::BitCast(di, hk)), expBias);
            const auto m = hn::IfThenElseZero(hn::RebindMask(di, hn::Lt(hk, hugeTap)),
                                              hn::Min(hn::Max(expo, hn::Zero(di)), maxLevel));
            hn::Vec<decltype(di)> lo, lw, lastx, lasty;
            if (levelsInVector) {
                const auto idx = hn::IndicesFromVec(di, m);
                lo = hn::TableLookupLanes(offVec, idx), lw = hn::TableLookupLanes(wVec, idx);
                lastx = hn::TableLookupLanes(lastXVec, idx), lasty = hn::TableLookupLanes(lastYVec, idx);
            } else {
                lo = hn::GatherIndex(di, in.levelOffset, m), lw = hn::GatherIndex(di, in.levelW, m);
                lastx = hn::Sub(lw, hn::Set(di, 1)), lasty = hn::Sub(hn::GatherIndex(di, in.levelH, m), hn::Set(di, 1));
            }
            const auto ix = hn::Min(hn::Max(hn::Shr(sx, m), hn::Zero(di)), lastx);
            const auto iy = hn::Min(hn::Max(hn::Shr(sy, m), hn::Zero(di)), lasty);
            const auto zq = hn::GatherIndex(df, in.levels, hn::Add(lo, hn::Add(hn::Mul(iy, lw), ix)));
            // Position at the tap's centre: z * fx(sx), fx(sx) = ax + bx * sx (PositionTables).
            const auto fxq = hn::Add(ax, hn::Mul(bx, hn::ConvertTo(df, sx)));
            const auto fyq = hn::Add(ay, hn::Mul(by, hn::ConvertTo(df, sy)));
            const auto vx = hn::Sub(hn::Mul(zq, fxq), cx), vy = hn::Sub(hn::Mul(zq, fyq), cy);
            const auto vz = hn::Sub(zq, zc);
            const auto vv = hn::Add(hn::Add(hn::Mul(vx, vx), hn::Mul(vy, vy)), hn::Mul(vz, vz));
            const auto vn = hn::Add(hn::Add(hn::Mul(vx, nx), hn::Mul(vy, ny)), hn::Mul(vz, nz));
            hn::Vec<decltype(df)> term;
            if (in.estimator == 0) {  // SAO's updated falloff
                const auto f = hn::Max(hn::Sub(hn::Set(df, in.r2), vv), zero);
                term = hn::Mul(
                    hn::Mul(hn::Mul(f, f), f),
                    hn::Max(hn::Div(hn::Sub(vn, hn::Set(df, in.bias)), hn::Add(vv, hn::Set(df, in.epsilon))), zero));
            } else {  // AlchemyAO, eq. 1
                term = hn::Div(hn::Max(zero, hn::Add(vn, hn::Mul(zc, hn::Set(df, in.beta)))),
                               hn::Add(vv, hn::Set(df, in.epsilon)));
            }
            // Sky taps (z = -inf) add nothing.
            sum = hn::Add(sum, hn::IfThenElseZero(hn::Gt(zq, negInf), term));
        }
        auto a = hn::Max(zero, hn::Sub(one, hn::Mul(hn::Mul(sum, hn::Set(df, in.scale)), hn::Set(df, in.scale2))));
        a = hn::IfThenElse(valid, a, one);
        hn::StoreU(a, df, out + (x - x0));
    }
    return x;
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::ao::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
