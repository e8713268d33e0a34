// Highway body of GTAO's main pass (spec gtao.md section 5; the scalar oracle is
// GtaoMain::pixel in gtao_pixel.hpp, whose operations the lanes follow one for one): one lane
// per pixel along a row, every sample gathered from the depth chain stored in one buffer.
// What differs from the oracle: the arc cosines and the final power come from Highway's float
// approximations (a few ulps) instead of libm; each sample's position, distance and weight use
// fused multiply-adds; the slice directions and step spacings are the oracle's own bits, read
// from the setup's noise planes (GtaoNoisePlanes; without them, Highway's cosine and sine); with
// the exact arc cosine sin(gamma), cos(gamma +- pi/2) and the integral's cos(2 h - gamma) come
// from the cosines they are functions of (sqrt(1 - c^2), angle-sum identities); the falloff
// multiplies by 1 / (f Re), the level is read from the exponent of |s|^2 scaled (the
// thresholds of round(log2 |s| - mipOffset)) instead of taking a logarithm, and (without the
// planes) slice k's direction is slice 0's turned by k pi / slices (angle sums). That moves A
// by ulps and, in rare pixels, a rounded sample offset or its chain level by one; the tests
// hold this path to the oracle within a stated bound (tests/ao/test_gtao.cpp).
#if defined(SSFX_AO_GTAO_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AO_GTAO_INL_H_
#undef SSFX_AO_GTAO_INL_H_
#else
#define SSFX_AO_GTAO_INL_H_
#endif

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "src/ao/gtao_simd.hpp"
#include "src/core/iota-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ssfx::ao::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class DF, class V = hn::Vec<DF>>
struct GtaoLanes {
    const GtaoSimdInput& in;
    DF df;
    hn::RebindToSigned<DF> di;

    V Clamp01(V v) const { return hn::Min(hn::Max(v, hn::Zero(df)), hn::Set(df, 1.0f)); }
    V Dot(V ax, V ay, V az, V bx, V by, V bz) const {  // (a.x b.x + a.y b.y) + a.z b.z, as dot()
        return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
    }
    V FusedDot(V ax, V ay, V az, V bx, V by, V bz) const {  // dot() in two fused multiply-adds
        return hn::MulAdd(az, bz, hn::MulAdd(ay, by, hn::Mul(ax, bx)));
    }
    //! XeGTAO's approximation (gtaoFastAcos) or Highway's acos.
    V Acos(V x) const {
        if (!in.fastAcos) return hn::Acos(df, x);
        const V ax = hn::Abs(x);
        const auto bits = hn::ShiftRight<1>(hn::BitCast(di, hn::Sub(hn::Set(df, 1.0f), ax)));
        const V root = hn::BitCast(df, hn::Add(hn::Set(di, 0x1FBD1DF5), bits));
        const float halfPi = 1.5707963267948966f;
        const V r = hn::Mul(hn::Sub(hn::Set(df, halfPi), hn::Mul(hn::Set(df, 0.156583f), ax)), root);
        return hn::IfThenElse(hn::Ge(x, hn::Zero(df)), r, hn::Sub(hn::Set(df, 2.0f * halfPi), r));
    }

    //! Entry m (a chain level, 0 .. 4) of a 16-entry table per lane: a register table lookup
    //! where a vector holds all five levels, else selects.
    template <class D, class VI>
    hn::Vec<D> Pick(D d, const hn::TFromD<D>* table16, VI m) const {
        if (hn::Lanes(d) >= 8) return hn::TableLookupLanes(hn::LoadU(d, table16), hn::IndicesFromVec(d, m));
        hn::Vec<D> r = hn::Set(d, table16[0]);
        for (int l = 1; l < 5; ++l)
            r = hn::IfThenElse(hn::RebindMask(d, hn::Eq(m, hn::Set(di, l))), hn::Set(d, table16[l]), r);
        return r;
    }
    //! The integer of an integer-valued float in [0, 2^23): its bits after adding 2^23 (a
    //! conversion instruction would also check for overflow, which costs four more here).
    hn::Vec<hn::RebindToSigned<DF>> ToIndex(V f) const {
        return hn::Sub(hn::BitCast(di, hn::Add(f, hn::Set(df, 8388608.0f))), hn::Set(di, 0x4B000000));
    }
    //! GtaoSetup's texel table entry computed: floor((2 p + 1) wm / 2 n) for p in [0, n),
    //! exactly (a float estimate within one of it, then one integer correction).
    template <class VI>
    VI TexelOf(VI p, VI wm, int n) const {
        const VI one = hn::Set(di, 1), den = hn::Set(di, 2 * n);
        const VI num = hn::Mul(hn::Add(hn::Add(p, p), one), wm);
        VI q = hn::ConvertTo(di, hn::Floor(hn::Mul(hn::ConvertTo(df, num), hn::Set(df, 1.0f / float(2 * n)))));
        const VI r = hn::Sub(num, hn::Mul(q, den));
        q = hn::Sub(q, hn::IfThenElseZero(hn::Lt(r, hn::Zero(di)), one));
        return hn::Add(q, hn::IfThenElseZero(hn::Not(hn::Lt(r, den)), one));
    }

    //! The chain value (t, +infinity for sky) of one step's sample on one side: buffer pixel
    //! (px, py), integers held as floats (exact: the buffer is far below 2^24 a side), at
    //! chain level m, a pixel beyond the buffer reading the edge texel's column or row
    //! (texel tables, clamped). kInside: the caller knows every lane's pixel is in the buffer.
    template <bool kInside, class VI>
    V Fetch(V px, V py, VI m) const {
        if (!kInside) {
            px = hn::Min(hn::Max(px, hn::Zero(df)), hn::Set(df, float(in.width - 1)));
            py = hn::Min(hn::Max(py, hn::Zero(df)), hn::Set(df, float(in.height - 1)));
        }
        const VI off = Pick(di, in.levelStart16, m), lw = Pick(di, in.levelWidth16, m);
        VI tx, ty;
        if (in.floatTexels) {  // one product each (exact here: checked by the setup)
            const V two = hn::Set(df, 2.0f), one = hn::Set(df, 1.0f);  // 2 p + 1, exact
            const V fx = hn::Trunc(hn::Mul(hn::MulAdd(two, px, one), Pick(df, in.texelScaleX16, m)));
            const V fy = hn::Trunc(hn::Mul(hn::MulAdd(two, py, one), Pick(df, in.texelScaleY16, m)));
            if (in.floatIndex)  // start + y width + x, exact in floats below 2^23
                return hn::GatherIndex(
                    df, in.chain,
                    ToIndex(hn::MulAdd(fy, Pick(df, in.levelWidthF16, m), hn::Add(fx, Pick(df, in.levelStartF16, m)))));
            tx = ToIndex(fx), ty = ToIndex(fy);
        } else if (in.arithmeticTexels) {  // two gathers cost more than the arithmetic
            tx = TexelOf(hn::ConvertTo(di, px), lw, in.width);
            ty = TexelOf(hn::ConvertTo(di, py), Pick(di, in.levelHeight16, m), in.height);
        } else {
            tx = hn::GatherIndex(di, in.texelX, hn::Add(hn::Mul(m, hn::Set(di, in.width)), hn::ConvertTo(di, px)));
            ty = hn::GatherIndex(di, in.texelY, hn::Add(hn::Mul(m, hn::Set(di, in.height)), hn::ConvertTo(di, py)));
        }
        return hn::GatherIndex(df, in.chain, hn::Add(off, hn::Add(hn::Mul(ty, lw), tx)));
    }

    //! One step's sample on one side at buffer pixel (px, py) (integer-valued floats), its
    //! chain value ts (Fetch): the horizon cosine h moves up to the sample's (GtaoMain::sample).
    template <bool kInside>
    V Sample(V px, V py, V ts, V cx, V cy, V cz, V vx, V vy, V vz, V start, V h) const {
        auto valid = hn::Not(hn::IsInf(ts));  // sky: weight 0
        if (in.discard && !kInside) {
            const V minus1 = hn::Set(df, -1.0f);
            const auto inside =
                hn::And(hn::And(hn::Gt(px, minus1), hn::Gt(py, minus1)),
                        hn::And(hn::Lt(px, hn::Set(df, float(in.width))), hn::Lt(py, hn::Set(df, float(in.height)))));
            valid = hn::And(valid, inside);
        }
        // Fused multiply-adds where the oracle rounds twice (a few ulps; the tests' bound).
        const V z = hn::Neg(ts);
        const V fx = hn::MulAdd(hn::Set(df, in.bx), px, hn::Set(df, in.ax));
        const V fy = hn::MulAdd(hn::Set(df, in.by), py, hn::Set(df, in.ay));
        const V dx = hn::MulSub(z, fx, cx), dy = hn::MulSub(z, fy, cy), dz = hn::Sub(z, cz);
        const V len = hn::Sqrt(FusedDot(dx, dy, dz, dx, dy, dz));
        const V cs = hn::Div(FusedDot(dx, dy, dz, vx, vy, vz), len);
        V lenW = len;
        if (in.toc1 != 1.0f) {
            const V tz = hn::Mul(hn::Set(df, in.toc1), dz);
            lenW = hn::Sqrt(FusedDot(dx, dy, tz, dx, dy, tz));
        }
        const V invFRe = hn::Set(df, 1.0f / in.fRe);
        const V w = Clamp01(hn::NegMulAdd(lenW, invFRe, hn::Mul(hn::Set(df, in.re), invFRe)));
        const V cw = hn::MulAdd(w, hn::Sub(cs, start), start);
        V next = hn::Max(h, cw);
        if (in.thickness > 0.0f)  // the paper's thickness heuristic
            next = hn::IfThenElse(hn::Lt(cw, h), hn::Add(h, hn::Mul(hn::Set(df, in.thickness), hn::Sub(cw, h))), next);
        return hn::IfThenElse(valid, next, h);
    }

    //! A (before the denoiser) of the lanes' pixels x, x + 1, ... of row y.
    V Pixels(int x, int y) const {
        const float kPi = 3.14159265358979323846f;
        const V one = hn::Set(df, 1.0f), zero = hn::Zero(df);
        const auto xi = ssfx::HWY_NAMESPACE::IotaFrom(di, x);
        const V t0 = hn::LoadU(df, in.chain + std::ptrdiff_t(y) * in.width + x);
        const auto sky = hn::IsInf(t0);
        // Step 3: the pull against depth imprecision; C and V use it.
        const V t = hn::Mul(t0, hn::Set(df, 0.99999f));
        const V cz = hn::Neg(t);
        const V cx = hn::Mul(cz, hn::Add(hn::Set(df, in.ax), hn::Mul(hn::Set(df, in.bx), hn::ConvertTo(df, xi))));
        const V cy = hn::Mul(cz, hn::Set(df, in.ay + in.by * float(y)));
        const V invLen = hn::Div(one, hn::Sqrt(Dot(cx, cy, cz, cx, cy, cz)));
        const V vx = hn::Neg(hn::Mul(cx, invLen)), vy = hn::Neg(hn::Mul(cy, invLen)), vz = hn::Neg(hn::Mul(cz, invLen));
        V nx, ny, nz;
        hn::LoadInterleaved3(df, in.normals + 3 * (std::ptrdiff_t(y - in.workY0) * in.workWidth + (x - in.workX0)), nx,
                             ny, nz);
        const auto none = hn::And(hn::And(hn::Eq(nx, zero), hn::Eq(ny, zero)), hn::Eq(nz, zero));
        nx = hn::IfThenElse(none, vx, nx), ny = hn::IfThenElse(none, vy, ny), nz = hn::IfThenElse(none, vz, nz);
        // Step 4: the radius in pixels, the fade for small radii, the closest step.
        const V r = hn::Div(hn::Set(df, in.rNum), t);
        const V v0 = in.nearFade ? hn::Mul(hn::Set(df, 0.5f),
                                           Clamp01(hn::Div(hn::Sub(hn::Set(df, 10.0f), r), hn::Set(df, 100.0f))))
                                 : zero;
        // (0 for sky, where r = 0: those lanes then sample their own pixel, not NaN offsets;
        // their A is 1 whatever they find.)
        const V smin = hn::IfThenZeroElse(sky, hn::Div(hn::Set(df, 1.3f), r));
        // Every sample of these lanes inside the buffer (no clamping, and nothing to discard)
        // where their farthest, |round(u (cos phi, -sin phi) r)| <= u r + 1 with u <= 1 + smin,
        // i.e. r + 2.3 pixels (sky: r = 0), stays within it. NaN fails the test.
        const float reach = hn::GetLane(hn::MaxOfLanes(df, hn::Add(r, hn::Set(df, 2.3f))));
        const bool inside = !in.clampEverywhere && float(x) - reach >= 0.0f &&
                            float(x + int(hn::Lanes(df)) - 1) + reach <= float(in.width - 1) &&
                            float(y) - reach >= 0.0f && float(y) + reach <= float(in.height - 1);
        const V xf = hn::ConvertTo(df, xi), yf = hn::Set(df, float(y));
        const auto mask63 = hn::Set(di, 63);
        const auto column = hn::And(hn::Sub(xi, hn::Set(di, in.guard)), mask63);  // the noise cells' x
        const V slices = hn::Set(df, float(in.slices)), stepCount = hn::Set(df, float(in.steps));
        // What the noise gives (section 7): read from the setup's planes, the scalar oracle's
        // bits; else derived here from the noise, slice k's cosine and sine from slice 0's by
        // the angle-sum identities (phi_k = phi_0 + k pi / S).
        using Planes = GtaoNoisePlanes;
        const float* planeRow =
            in.noisePlanes ? in.noisePlanes + std::ptrdiff_t((y - in.guard) & 63) * Planes::kStride : nullptr;
        auto plane = [&](int q) {  // plane q at the lanes' cells: one load where the row's copy allows
            const float* row = planeRow + std::ptrdiff_t(q) * Planes::kPlaneFloats;
            if (hn::Lanes(df) <= std::size_t(Planes::kStride - 64)) return hn::LoadU(df, row + ((x - in.guard) & 63));
            return hn::GatherIndex(df, row, column);
        };
        V ns = zero, nt = zero, cphi0 = zero, sphi0 = zero;
        if (!in.noisePlanes) {
            const auto noiseIdx = hn::Add(hn::Set(di, ((y - in.guard) & 63) * 64), column);
            ns = hn::GatherIndex(df, in.noiseS, noiseIdx), nt = hn::GatherIndex(df, in.noiseT, noiseIdx);
            const V phi0 = hn::Mul(hn::Div(ns, slices), hn::Set(df, kPi));
            cphi0 = hn::Cos(df, phi0), sphi0 = hn::Sin(df, phi0);
        }
        V sum = zero;
        for (int k = 0; k < in.slices; ++k) {
            V cphi = cphi0, sphi = sphi0;
            if (in.noisePlanes) {
                cphi = plane(2 * k), sphi = plane(2 * k + 1);
            } else if (k > 0) {
                const double turn = double(k) * 3.14159265358979323846 / double(in.slices);
                const V ck = hn::Set(df, float(std::cos(turn))), sk = hn::Set(df, float(std::sin(turn)));
                cphi = hn::Sub(hn::Mul(cphi0, ck), hn::Mul(sphi0, sk));
                sphi = hn::Add(hn::Mul(sphi0, ck), hn::Mul(cphi0, sk));
            }
            const V ox = hn::Mul(cphi, r), oy = hn::Mul(hn::Neg(sphi), r);  // screen y is down
            const V dv = Dot(cphi, sphi, zero, vx, vy, vz);
            const V dpx = hn::Sub(cphi, hn::Mul(dv, vx)), dpy = hn::Sub(sphi, hn::Mul(dv, vy)),
                    dpz = hn::Sub(zero, hn::Mul(dv, vz));
            // axis = unitOrZero(cross(dp, v))
            V axx = hn::Sub(hn::Mul(dpy, vz), hn::Mul(dpz, vy)), axy = hn::Sub(hn::Mul(dpz, vx), hn::Mul(dpx, vz)),
              axz = hn::Sub(hn::Mul(dpx, vy), hn::Mul(dpy, vx));
            const V alen = hn::Sqrt(Dot(axx, axy, axz, axx, axy, axz));
            const auto aok = hn::And(hn::Gt(alen, zero), hn::Not(hn::IsInf(alen)));
            axx = hn::IfThenElseZero(aok, hn::Div(axx, alen)), axy = hn::IfThenElseZero(aok, hn::Div(axy, alen)),
            axz = hn::IfThenElseZero(aok, hn::Div(axz, alen));
            const V na = Dot(nx, ny, nz, axx, axy, axz);
            const V npx = hn::Sub(nx, hn::Mul(na, axx)), npy = hn::Sub(ny, hn::Mul(na, axy)),
                    npz = hn::Sub(nz, hn::Mul(na, axz));
            const V l = hn::Sqrt(Dot(npx, npy, npz, npx, npy, npz));
            const auto lpos = hn::Gt(l, zero);
            const V cg = hn::IfThenElse(lpos, Clamp01(hn::Div(Dot(npx, npy, npz, vx, vy, vz), l)), one);
            const V side = Dot(dpx, dpy, dpz, npx, npy, npz);
            const V ac = Acos(cg);
            const V gamma = hn::IfThenElseZero(
                lpos, hn::IfThenElse(hn::Gt(side, zero), ac, hn::IfThenElse(hn::Lt(side, zero), hn::Neg(ac), zero)));
            // sin(gamma); with an exact arc cosine (cos gamma = cg) as +-sqrt(1 - cg^2).
            auto sine = [&](V c) { return hn::Sqrt(hn::Max(hn::Sub(one, hn::Mul(c, c)), zero)); };
            const V sg = in.fastAcos ? hn::Sin(df, gamma)
                                     : hn::Sub(hn::IfThenElseZero(hn::Gt(gamma, zero), sine(cg)),
                                               hn::IfThenElseZero(hn::Lt(gamma, zero), sine(cg)));
            // cos(gamma +- pi/2) = -+sin(gamma).
            const V lowPos = hn::Neg(sg), lowNeg = sg;
            const V startPos = in.minusOne ? hn::Set(df, -1.0f) : lowPos;
            const V startNeg = in.minusOne ? hn::Set(df, -1.0f) : lowNeg;
            V hp = startPos, hneg = startNeg;
            // The steps in batches: every depth of a batch is gathered before the first is used,
            // so that the gathers' cache misses overlap (the horizons are updated in step order).
            auto steps = [&](auto insideTag) {
                constexpr bool kInside = decltype(insideTag)::value;
                constexpr int kBatch = 3;
                for (int j0 = 0; j0 < in.steps; j0 += kBatch) {
                    const int count = std::min(kBatch, in.steps - j0);
                    V pxP[kBatch], pyP[kBatch], pxN[kBatch], pyN[kBatch], tsP[kBatch], tsN[kBatch];
                    for (int b = 0; b < count; ++b) {
                        const int j = j0 + b;
                        V spacing;  // ((j + xj) / J)^2: sampleDistributionPower 2
                        if (in.noisePlanes) {
                            spacing = plane(2 * in.slices + k * in.steps + j);
                        } else {
                            const float base = float(k + j * in.steps) * 0.6180339887498948f;
                            const V xjRaw = hn::Add(nt, hn::Set(df, base));
                            const V xj = hn::Sub(xjRaw, hn::Floor(xjRaw));
                            const V s = hn::Div(hn::Add(hn::Set(df, float(j)), xj), stepCount);
                            spacing = hn::Mul(s, s);
                        }
                        const V u = hn::Add(spacing, smin);
                        const V sx = hn::Mul(u, ox), sy = hn::Mul(u, oy);
                        // The level round(log2 |s| - mipOffset) clamped to [0, 4]: level k is
                        // reached where |s|^2 >= 2^(2 k - 1 + 2 mipOffset), i.e. where the
                        // exponent E of |s|^2 2^(2 - 2 mipOffset) is at least 2 k + 1, so the
                        // level is floor((E - 1) / 2) = (its bits >> 24) - 64, clamped.
                        const V q = hn::Mul(hn::MulAdd(sy, sy, hn::Mul(sx, sx)), hn::Set(df, in.lodScale));
                        const auto m = hn::Min(
                            hn::Max(hn::Sub(hn::ShiftRight<24>(hn::BitCast(di, q)), hn::Set(di, 64)), hn::Zero(di)),
                            hn::Set(di, 4));
                        // The offset rounded to the nearest pixel (ties to even, as nearbyint), as
                        // floats: the pixels' coordinates stay exact integers.
                        const V qx = hn::Round(sx), qy = hn::Round(sy);
                        pxP[b] = hn::Add(xf, qx), pyP[b] = hn::Add(yf, qy);
                        pxN[b] = hn::Sub(xf, qx), pyN[b] = hn::Sub(yf, qy);
                        tsP[b] = Fetch<kInside>(pxP[b], pyP[b], m);
                        tsN[b] = Fetch<kInside>(pxN[b], pyN[b], m);
                    }
                    for (int b = 0; b < count; ++b) {
                        hp = Sample<kInside>(pxP[b], pyP[b], tsP[b], cx, cy, cz, vx, vy, vz, startPos, hp);
                        hneg = Sample<kInside>(pxN[b], pyN[b], tsN[b], cx, cy, cz, vx, vy, vz, startNeg, hneg);
                    }
                }
            };
            if (inside)
                steps(std::true_type{});
            else
                steps(std::false_type{});
            if (in.minusOne) hp = hn::Max(hp, lowPos), hneg = hn::Max(hneg, lowNeg);  // onto the hemisphere
            const V h1 = Acos(hp), h0 = hn::Neg(Acos(hneg));
            const V lp = in.lift ? hn::Add(hn::Mul(hn::Set(df, 0.95f), l), hn::Set(df, 0.05f)) : l;
            // The slice's integral, (cg + 2 h sin(gamma) - cos(2 h - gamma)) / 4 per side. With an
            // exact arc cosine, cos h and sin h are the horizon's cosine c and +-sqrt(1 - c^2),
            // so cos(2 h - gamma) = (2 c^2 - 1) cg + 2 c sin(h) sin(gamma) without a cosine.
            const V two = hn::Set(df, 2.0f);
            auto iota = [&](V h, V c, V sinH) {
                const V c2 = in.fastAcos ? hn::Cos(df, hn::Sub(hn::Mul(two, h), gamma))
                                         : hn::Add(hn::Mul(hn::Sub(hn::Mul(two, hn::Mul(c, c)), one), cg),
                                                   hn::Mul(hn::Mul(two, hn::Mul(c, sinH)), sg));
                return hn::Mul(hn::Sub(hn::Add(cg, hn::Mul(hn::Mul(two, h), sg)), c2), hn::Set(df, 0.25f));
            };
            sum = hn::Add(sum, hn::Mul(lp, hn::Add(iota(h0, hneg, hn::Neg(sine(hneg))), iota(h1, hp, sine(hp)))));
        }
        V a = hn::Max(zero, hn::Div(hn::Add(v0, sum), slices));
        if (in.finalPower != 1.0f)  // a^p = exp(p ln a), 0 for a = 0
            a = hn::IfThenElseZero(hn::Gt(a, zero), hn::Exp(df, hn::Mul(hn::Set(df, in.finalPower), hn::Log(df, a))));
        a = hn::Max(hn::Set(df, 0.03f), a);
        return hn::IfThenElse(sky, one, a);
    }
};

// Sections 5.1 and 6 per lane: gtaoEdges, quantiseEdges and gtaoNormalFromDepth
// (gtao_pixel.hpp) for pixels [x, x + N) of row y, 1 <= x, x + N <= W - 1 (the row's
// neighbours are contiguous loads; the rows above and below are clamped). The same float
// operations in the same order (IEEE division and square root, no FMA), so the same bits.
template <class DF, class V = hn::Vec<DF>>
HWY_INLINE void EdgesNormalsChunk(DF df, const GtaoSimdInput& in, int x, int y, std::uint8_t* HWY_RESTRICT edges,
                                  float* HWY_RESTRICT normals) {
    const hn::RebindToSigned<DF> di;
    const hn::Rebind<std::uint8_t, DF> d8;
    const float* t = in.chain;  // level 0
    const float* rc = t + std::size_t(y) * std::size_t(in.width);
    const float* ra = t + std::size_t(y > 0 ? y - 1 : 0) * std::size_t(in.width);
    const float* rb = t + std::size_t(y + 1 < in.height ? y + 1 : in.height - 1) * std::size_t(in.width);
    const V zero = hn::Zero(df), one = hn::Set(df, 1.0f);
    const V tc = hn::LoadU(df, rc + x);
    const V nb[4] = {hn::LoadU(df, rc + x - 1), hn::LoadU(df, rc + x + 1), hn::LoadU(df, ra + x),
                     hn::LoadU(df, rb + x)};
    hn::Mask<DF> sky[4];
    V dt[4];
    for (int i = 0; i < 4; ++i) sky[i] = hn::IsInf(nb[i]), dt[i] = hn::IfThenZeroElse(sky[i], hn::Sub(nb[i], tc));
    const V half = hn::Set(df, 0.5f);
    const V sLR = hn::Mul(hn::Sub(dt[1], dt[0]), half), sTB = hn::Mul(hn::Sub(dt[3], dt[2]), half);
    const V adj[4] = {hn::Add(dt[0], sLR), hn::Sub(dt[1], sLR), hn::Add(dt[2], sTB), hn::Sub(dt[3], sTB)};
    const V scale = hn::Mul(tc, hn::Set(df, 0.011f));
    const auto skyC = hn::IsInf(tc);
    V e[4];
    auto packed = hn::Zero(di);
    for (int i = 0; i < 4; ++i) {
        const V m = hn::IfThenElse(sky[i ^ 1], hn::Abs(dt[i]), hn::Min(hn::Abs(dt[i]), hn::Abs(adj[i])));
        const V ei = hn::Min(hn::Max(hn::Sub(hn::Set(df, 1.25f), hn::Div(m, scale)), zero), one);
        e[i] = hn::IfThenZeroElse(hn::Or(sky[i], skyC), ei);
        // quantiseEdges: roundEven(2.9 e) << 2 i
        const auto q = hn::ConvertTo(di, hn::Round(hn::Mul(hn::Set(df, 2.9f), e[i])));
        packed = hn::Or(packed, hn::ShiftLeftSame(q, 2 * i));
    }
    hn::StoreU(hn::DemoteTo(d8, packed), d8, edges);

    // The normal: positions z (ax + bx x), z (ay + by y), z with z = -t.
    const V fxC = hn::Add(hn::Set(df, in.ax),
                          hn::Mul(hn::Set(df, in.bx), hn::ConvertTo(df, ssfx::HWY_NAMESPACE::IotaFrom(di, x))));
    const V fyC = hn::Set(df, in.ay + in.by * float(y));
    const V zC = hn::Neg(tc);
    const V cx = hn::Mul(zC, fxC), cy = hn::Mul(zC, fyC);
    auto unitOrZero = [&](V& nx, V& ny, V& nz) {
        const V len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
        const auto ok = hn::And(hn::Gt(len, zero), hn::Not(hn::IsInf(len)));  // len >= 0 or NaN
        nx = hn::IfThenElseZero(ok, hn::Div(nx, len));
        ny = hn::IfThenElseZero(ok, hn::Div(ny, len));
        nz = hn::IfThenElseZero(ok, hn::Div(nz, len));
    };
    // Neighbours L, R, T, B: their own positions (x -+ 1 or y -+ 1) with their t.
    const V fxL = hn::Add(hn::Set(df, in.ax),
                          hn::Mul(hn::Set(df, in.bx), hn::ConvertTo(df, ssfx::HWY_NAMESPACE::IotaFrom(di, x - 1))));
    const V fxR = hn::Add(hn::Set(df, in.ax),
                          hn::Mul(hn::Set(df, in.bx), hn::ConvertTo(df, ssfx::HWY_NAMESPACE::IotaFrom(di, x + 1))));
    const V fyT = hn::Set(df, in.ay + in.by * float(y - 1)), fyB = hn::Set(df, in.ay + in.by * float(y + 1));
    const V fxs[4] = {fxL, fxR, fxC, fxC}, fys[4] = {fyC, fyC, fyT, fyB};
    V ux[4], uy[4], uz[4];
    for (int i = 0; i < 4; ++i) {
        const V z = hn::Neg(nb[i]);
        ux[i] = hn::Sub(hn::Mul(z, fxs[i]), cx), uy[i] = hn::Sub(hn::Mul(z, fys[i]), cy), uz[i] = hn::Sub(z, zC);
        unitOrZero(ux[i], uy[i], uz[i]);
        ux[i] = hn::IfThenZeroElse(sky[i], ux[i]), uy[i] = hn::IfThenZeroElse(sky[i], uy[i]);
        uz[i] = hn::IfThenZeroElse(sky[i], uz[i]);
    }
    enum { L, R, T, B };
    auto weight = [&](int a, int b) {
        const V w = hn::Min(hn::Max(hn::Add(hn::Mul(e[a], e[b]), hn::Set(df, 0.01f)), zero), one);
        return hn::IfThenZeroElse(hn::Or(sky[a], sky[b]), w);
    };
    const V aLT = weight(L, T), aTR = weight(T, R), aRB = weight(R, B), aBL = weight(B, L);
    // cross(a, b) = (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x)
    auto crossX = [&](int a, int b) { return hn::Sub(hn::Mul(uy[a], uz[b]), hn::Mul(uz[a], uy[b])); };
    auto crossY = [&](int a, int b) { return hn::Sub(hn::Mul(uz[a], ux[b]), hn::Mul(ux[a], uz[b])); };
    auto crossZ = [&](int a, int b) { return hn::Sub(hn::Mul(ux[a], uy[b]), hn::Mul(uy[a], ux[b])); };
    auto blend = [&](const auto& c) {  // aLT cLT + aTR cTR + aRB cRB + aBL cBL, left to right
        return hn::Add(hn::Add(hn::Add(hn::Mul(aLT, c(T, L)), hn::Mul(aTR, c(R, T))), hn::Mul(aRB, c(B, R))),
                       hn::Mul(aBL, c(L, B)));
    };
    V nx = blend(crossX), ny = blend(crossY), nz = blend(crossZ);
    unitOrZero(nx, ny, nz);
    nx = hn::IfThenZeroElse(skyC, nx), ny = hn::IfThenZeroElse(skyC, ny), nz = hn::IfThenZeroElse(skyC, nz);
    hn::StoreInterleaved3(nx, ny, nz, df, normals);
}

// Edges and normals of pixels [x0, x1) of row y (1 <= x0, x1 <= W - 1) into the work
// region's row (edges, normals: the entries of x0 on), whole vectors; returns the first x
// it left to the scalar loop.
inline int GtaoEdgesNormalsRow(const GtaoSimdInput& in, int y, int x0, int x1, std::uint8_t* HWY_RESTRICT edges,
                               float* HWY_RESTRICT normals) {
    const hn::ScalableTag<float> df;
    const int n = int(hn::Lanes(df));
    int x = x0;
    for (; x + n <= x1; x += n) EdgesNormalsChunk(df, in, x, y, edges + (x - x0), normals + 3 * std::size_t(x - x0));
    return x;
}

// Section 8 per lane: GtaoDenoise::pixel (gtao_pixel.hpp) without bent normals, for pixels
// [x, x + N) of row y, workX0 + 1 <= x, x + N <= workX0 + workWidth - 1 (the row's neighbours
// are contiguous; the rows above and below are clamped to the work region). The same float
// operations in the same order; a sky neighbour's terms are added as zeros, which leaves
// the non-negative sums as they are.
template <class DF, class V = hn::Vec<DF>>
HWY_INLINE V DenoiseChunk(DF df, const GtaoDenoiseInput& in, int x, int y) {
    const hn::RebindToSigned<DF> di;
    const hn::Rebind<std::uint8_t, DF> d8;
    const int ya = std::max(y - 1, in.workY0), yb = std::min(y + 1, in.workY0 + in.workHeight - 1);
    const int rows[3] = {ya, y, yb};
    const int i = x - in.workX0;
    // Neighbours C, L, R, T, B, TL, TR, BL, BR: row (0 above, 1 centre, 2 below) and column offset.
    const int nr[9] = {1, 1, 1, 0, 2, 0, 0, 2, 2}, nc[9] = {0, -1, 1, 0, 0, -1, 1, -1, 1};
    hn::Vec<decltype(di)> e[9];
    hn::Mask<DF> sky[9];
    V a[9];
    for (int k = 0; k < 9; ++k) {
        const int r = rows[nr[k]];
        const std::size_t work = std::size_t(r - in.workY0) * std::size_t(in.workWidth) + std::size_t(i + nc[k]);
        e[k] = hn::PromoteTo(di, hn::LoadU(d8, in.edges + work));
        sky[k] = hn::IsInf(hn::LoadU(df, in.t0 + std::size_t(r) * std::size_t(in.width) + std::size_t(x + nc[k])));
        a[k] = hn::LoadU(df, in.a + work);
    }
    enum { C, L, R, T, B, TL, TR, BL, BR };
    enum { SL, SR, ST, SB };
    const V three = hn::Set(df, 3.0f), zero = hn::Zero(df), one = hn::Set(df, 1.0f);
    auto edgeOf = [&](int k, int side) {  // float((packed >> 2 side) & 3) / 3
        return hn::Div(hn::ConvertTo(df, hn::And(hn::ShiftRightSame(e[k], 2 * side), hn::Set(di, 3))), three);
    };
    auto clamp01 = [&](V v) { return hn::Min(hn::Max(v, zero), one); };
    V eL = hn::Mul(edgeOf(C, SL), edgeOf(L, SR)), eR = hn::Mul(edgeOf(C, SR), edgeOf(R, SL));
    V eT = hn::Mul(edgeOf(C, ST), edgeOf(T, SB)), eB = hn::Mul(edgeOf(C, SB), edgeOf(B, ST));
    const V leak = hn::Mul(
        hn::Div(clamp01(hn::Sub(hn::Set(df, 1.5f), hn::Add(hn::Add(hn::Add(eL, eR), eT), eB))), hn::Set(df, 1.5f)),
        hn::Set(df, 0.5f));
    eL = clamp01(hn::Add(eL, leak)), eR = clamp01(hn::Add(eR, leak));
    eT = clamp01(hn::Add(eT, leak)), eB = clamp01(hn::Add(eB, leak));
    const V k425 = hn::Set(df, 0.425f);
    V w[9];
    w[C] = hn::Set(df, in.beta), w[L] = eL, w[R] = eR, w[T] = eT, w[B] = eB;
    w[TL] = hn::Mul(k425, hn::Add(hn::Mul(eL, edgeOf(L, ST)), hn::Mul(eT, edgeOf(T, SL))));
    w[TR] = hn::Mul(k425, hn::Add(hn::Mul(eT, edgeOf(T, SR)), hn::Mul(eR, edgeOf(R, ST))));
    w[BL] = hn::Mul(k425, hn::Add(hn::Mul(eB, edgeOf(B, SL)), hn::Mul(eL, edgeOf(L, SB))));
    w[BR] = hn::Mul(k425, hn::Add(hn::Mul(eR, edgeOf(R, SB)), hn::Mul(eB, edgeOf(B, SR))));
    V sum = zero, wsum = zero;
    for (int k = 0; k < 9; ++k) {
        sum = hn::Add(sum, hn::IfThenZeroElse(sky[k], hn::Mul(w[k], a[k])));
        wsum = hn::Add(wsum, hn::IfThenZeroElse(sky[k], w[k]));
    }
    return hn::IfThenElse(sky[C], one, hn::Div(sum, wsum));
}

inline int GtaoDenoiseRow(const GtaoDenoiseInput& in, int y, int x0, int x1, float* HWY_RESTRICT out) {
    const hn::ScalableTag<float> df;
    const int n = int(hn::Lanes(df));
    int x = x0;
    for (; x + n <= x1; x += n) hn::StoreU(DenoiseChunk(df, in, x, y), df, out + (x - x0));
    return x;
}

// Test hook (gtao_simd.hpp): how many p in [0, n) get a GtaoLanes::TexelOf(p, wm, n) other
// than floor((2 p + 1) wm / 2 n).
inline std::int64_t GtaoTexelMismatches(int n, int wm) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    GtaoSimdInput in{};
    const GtaoLanes<decltype(df)> lanes{in, df, di};
    const int lanesN = int(hn::Lanes(di));
    std::vector<std::int32_t> got(static_cast<std::size_t>(lanesN));
    std::int64_t mismatches = 0;
    for (int p0 = 0; p0 < n; p0 += lanesN) {
        const auto p = hn::Min(ssfx::HWY_NAMESPACE::IotaFrom(di, p0), hn::Set(di, n - 1));
        hn::StoreU(lanes.TexelOf(p, hn::Set(di, wm), n), di, got.data());
        for (int i = 0; i < lanesN && p0 + i < n; ++i)
            mismatches +=
                got[std::size_t(i)] != std::int32_t((2 * std::int64_t(p0 + i) + 1) * wm / (2 * std::int64_t(n)));
    }
    return mismatches;
}

inline int GtaoRowSimd(const GtaoSimdInput& in, int y, int x0, int x1, float* HWY_RESTRICT out) {
    const hn::ScalableTag<float> df;
    const int n = int(hn::Lanes(df));
    const GtaoLanes<decltype(df)> lanes{in, df, {}};
    int x = x0;
    for (; x + n <= x1; x += n) hn::StoreU(lanes.Pixels(x, y), df, out + (x - x0));
    return x;
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::ao::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
