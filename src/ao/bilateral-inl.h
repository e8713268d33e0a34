// Highway body of one row of SAO's bilateral reconstruction (paper section 2.4; the loop
// it follows is in sao.cpp bilateralPass): each lane is one output pixel and sums its taps
// in t order, with the scalar loop's float operations in the same order and without FMA,
// so the result is bit for bit the per-pixel formula's on every target.
// Included by sao-inl.h (one Highway translation unit for the AO kernels).
#if defined(SSFX_AO_BILATERAL_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AO_BILATERAL_SIMD_INL_H_
#undef SSFX_AO_BILATERAL_SIMD_INL_H_
#else
#define SSFX_AO_BILATERAL_SIMD_INL_H_
#endif

#include <hwy/highway.h>

#include <cmath>

#include "src/ao/ao_simd.hpp"

HWY_BEFORE_NAMESPACE();
namespace ssfx::ao::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out[i] for i in [lo, hi): sum_t w_t a_t / (sum_t w_t + epsilon) with w_t = g_t max(0, 1 - k |z_t - z_c|),
// or 1 where z_c is infinite (sky).
inline void BilateralRowSimd(const BilateralRowInput& in, int lo, int hi, float* HWY_RESTRICT out) {
    const hn::ScalableTag<float> df;
    const int n = int(hn::Lanes(df));
    const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), k = hn::Set(df, in.edgeSharpness);
    const auto inf = hn::Set(df, HUGE_VALF);
    int i = lo;
    for (; i + n <= hi; i += n) {
        const auto zc = hn::LoadU(df, in.zCentre + i);
        auto s = zero, ws = zero;
        for (int t = 0; t < in.taps; ++t) {
            const auto zt = hn::LoadU(df, in.zTap[t] + i);
            // std::max(0, x) is (0 < x ? x : 0), also for NaN (k = 0 next to the sky).
            const auto x = hn::Sub(one, hn::Mul(k, hn::Abs(hn::Sub(zt, zc))));
            const auto w = hn::Mul(hn::Set(df, in.gauss[t]), hn::IfThenElseZero(hn::Gt(x, zero), x));
            s = hn::Add(s, hn::Mul(w, hn::LoadU(df, in.aTap[t] + i)));
            ws = hn::Add(ws, w);
        }
        const auto sky = hn::Eq(hn::Abs(zc), inf);
        hn::StoreU(hn::IfThenElse(sky, one, hn::Div(s, hn::Add(ws, hn::Set(df, in.epsilon)))), df, out + i);
    }
    for (; i < hi; ++i) {  // the row's last few pixels, one at a time (same operations)
        const float zc = in.zCentre[i];
        float s = 0.0f, ws = 0.0f;
        for (int t = 0; t < in.taps; ++t) {
            const float w = in.gauss[t] * std::max(0.0f, 1.0f - in.edgeSharpness * std::fabs(in.zTap[t][i] - zc));
            s += w * in.aTap[t][i];
            ws += w;
        }
        out[i] = std::isinf(zc) ? 1.0f : s / (ws + in.epsilon);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::ao::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
