// Exact float division of small integers by a constant, for the Highway kernels.
//
// The kernels divide integer sums by constants (a channel byte by 255, a GPU-model
// bilinear sum by 4080, half-way sums by 510 and 1020) and must give the IEEE quotient
// RN(k / d) bit for bit, as the scalar code does. A vector divide is slow on x86, so on
// targets with a fused multiply-add the quotient is refined from the reciprocal instead
// (Markstein's correction step):
//   q0 = RN(k * r), r = RN(1 / d);   e = k - q0 d, exact with an FMA (q0 is within an
//   ulp of k / d);   q = RN(q0 + e r).
// This is not the correctly rounded quotient for every k and d in general, so it is used
// only where it has been checked for every integer of the range: tests/core/test_color.cpp
// (ExactDivisionIsIeeeDivisionForEveryInteger) runs all k in [0, kMax] for each divisor the
// library uses. Targets without FMA use the divide itself.
#if defined(SSFX_CORE_EXACT_DIV_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_CORE_EXACT_DIV_INL_H_
#undef SSFX_CORE_EXACT_DIV_INL_H_
#else
#define SSFX_CORE_EXACT_DIV_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace ssfx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

//! A divisor d with its float reciprocal, set up once outside a kernel's loop.
template <class DF>
struct ExactDivisor {
    hn::Vec<DF> d, r;
    ExactDivisor(DF df, float divisor) : d(hn::Set(df, divisor)), r(hn::Set(df, 1.0f / divisor)) {}
};

//! RN(k / d) for lanes holding integers k in the checked range (see above).
template <class DF>
HWY_INLINE hn::Vec<DF> DivExact(hn::Vec<DF> k, const ExactDivisor<DF>& div) {
#if HWY_NATIVE_FMA
    const hn::Vec<DF> q0 = hn::Mul(k, div.r);
    const hn::Vec<DF> e = hn::NegMulAdd(q0, div.d, k);  // k - q0 d, exact
    return hn::MulAdd(e, div.r, q0);
#else
    return hn::Div(k, div.d);
#endif
}

}  // namespace ssfx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
