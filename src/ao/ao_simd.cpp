// Runtime dispatch of the vector AO kernels: the sample pass (sao-inl.h), a row of the
// bilateral blur (bilateral-inl.h) and a row of depth -> z (depth-inl.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/ao/sao-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/ao/sao-inl.h"

#if HWY_ONCE
namespace ssfx::ao::detail {
HWY_EXPORT(SampleRowSimd);
HWY_EXPORT(BilateralRowSimd);
HWY_EXPORT(DepthToZRowSimd);
bool depthToZRowSimd(const float* d, float* z, int n, double c0, double c1, double c2) {
    return HWY_DYNAMIC_DISPATCH(DepthToZRowSimd)(d, z, n, c0, c1, c2);
}
void bilateralRowSimd(const BilateralRowInput& in, int lo, int hi, float* out) {
    HWY_DYNAMIC_DISPATCH(BilateralRowSimd)(in, lo, hi, out);
}
int sampleRowSimd(const SimdSampleInput& in, int y, int x0, int x1, float* out) {
    return HWY_DYNAMIC_DISPATCH(SampleRowSimd)(in, y, x0, x1, out);
}
}  // namespace ssfx::ao::detail
#endif
