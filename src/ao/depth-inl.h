// Highway body of one row of depth -> z (paper eq. 2; the loop it follows is depthToZ in
// depth.cpp): z = c0 / (d c1 + c2) in double, rounded to float, with the scalar loop's
// operations in the same order and without FMA, so the same bits on every target; d = 1
// (nothing drawn) is sky, z = -inf, whatever the far plane.
// Included by sao-inl.h (one Highway translation unit for the AO kernels).
#if defined(SSFX_AO_DEPTH_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_AO_DEPTH_SIMD_INL_H_
#undef SSFX_AO_DEPTH_SIMD_INL_H_
#else
#define SSFX_AO_DEPTH_SIMD_INL_H_
#endif

#include <hwy/highway.h>

#include <cmath>

HWY_BEFORE_NAMESPACE();
namespace ssfx::ao::detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// z for d[0 .. n); false (z partly written) when some d is outside [0, 1] or NaN: the
// caller then redoes the row with the per-pixel loop, which names the first bad pixel.
inline bool DepthToZRowSimd(const float* HWY_RESTRICT d, float* HWY_RESTRICT z, int n, double c0, double c1,
                            double c2) {
    const hn::ScalableTag<double> dd;
    const hn::Rebind<float, decltype(dd)> df;  // as many floats as doubles
    const int lanes = int(hn::Lanes(dd));
    const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), sky = hn::Set(df, -HUGE_VALF);
    const auto k0 = hn::Set(dd, c0), k1 = hn::Set(dd, c1), k2 = hn::Set(dd, c2);
    // One pass: convert and check together; on a bad value the caller redoes the row.
    auto inRange = hn::FirstN(df, std::size_t(lanes));  // all true
    int x = 0;
    for (; x + lanes <= n; x += lanes) {
        const auto f = hn::LoadU(df, d + x);
        inRange = hn::And(inRange, hn::And(hn::Ge(f, zero), hn::Le(f, one)));  // false for NaN
        const auto v = hn::PromoteTo(dd, f);
        // d = 1 (nothing drawn) is sky for any far plane, as in the per-pixel loop.
        const auto zf = hn::DemoteTo(df, hn::Div(k0, hn::Add(hn::Mul(v, k1), k2)));
        hn::StoreU(hn::IfThenElse(hn::Eq(f, one), sky, zf), df, z + x);
    }
    for (; x < n; ++x) {
        if (!(d[x] >= 0.0f && d[x] <= 1.0f)) return false;
        z[x] = d[x] == 1.0f ? -HUGE_VALF : float(c0 / (double(d[x]) * c1 + c2));
    }
    return hn::AllTrue(df, inRange);
}

}  // namespace HWY_NAMESPACE
}  // namespace ssfx::ao::detail
HWY_AFTER_NAMESPACE();

#endif  // include guard
