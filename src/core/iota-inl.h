// Lane indices from a run-time start, for the Highway kernels' loops.
//
// Highway 1.0 builds hn::Iota(d, first) by storing the lanes to memory and loading them
// back; with `first` known only at run time that is a store-forwarding stall on every call
// of a hot loop (seen at the top of fxaa3c's listing loop in perf on Zen 4). Iota(d, 0) is a
// constant, so first + Iota(d, 0) is one add: the same lanes.
#if defined(SSFX_CORE_IOTA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SSFX_CORE_IOTA_INL_H_
#undef SSFX_CORE_IOTA_INL_H_
#else
#define SSFX_CORE_IOTA_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace ssfx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

//! Lane i holds first + i (as hn::Iota(d, first)).
template <class D>
HWY_INLINE hn::Vec<D> IotaFrom(D d, hn::TFromD<D> first) {
    return hn::Add(hn::Iota(d, 0), hn::Set(d, first));
}

}  // namespace ssfx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
