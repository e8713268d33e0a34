// Runtime dispatch of the vector AO sample pass (see sao_simd-inl.h).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/ao/sao_simd-inl.h"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/ao/sao_simd-inl.h"

#if HWY_ONCE
namespace ssfx::ao::detail {
HWY_EXPORT(SampleRowSimd);
int sampleRowSimd(const SimdSampleInput& in, int y, int x0, int x1, float* out) {
    return HWY_DYNAMIC_DISPATCH(SampleRowSimd)(in, y, x0, x1, out);
}
}  // namespace ssfx::ao::detail
#endif
